#include "reflector_extractor/extractor_node.hpp"

namespace refloc {

ExtractorHealth extractor_health(int64_t messages_in, const std::string& input_channel) {
  if (messages_in == 0) return {true, "waiting for " + input_channel};
  return {false, ""};
}

ExtractorNode::ExtractorNode(const ExtractorServiceConfig& config, const Pose2& robot_T_laser)
    : extractor_(config.extractor),
      compensator_(config.motion_compensation, config.odometry_max_age, robot_T_laser) {
  output_.detections.reserve(64);
}

const ExtractorOutput& ExtractorNode::on_scan(const LaserScan& scan) {
  output_.utime = scan.utime;
  output_.scan_counter = scan.scan_counter;
  output_.detections = extractor_.extract(scan);  // copy into reused storage
  output_.stats = extractor_.stats();
  output_.compensation = compensator_.apply(output_.detections, scan.utime);
  return output_;
}

}  // namespace refloc
