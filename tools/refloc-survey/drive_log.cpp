#include "drive_log.hpp"

#include "common/lcm_bounded_decode.hpp"
#include "log_reader.hpp"
#include "reflector_extractor/extractor_messages.hpp"

#include <refloc/laser_scan_t.hpp>
#include <refloc/odometry_t.hpp>

namespace refloc {

std::vector<DriveScan> read_drive_log(const std::string& path, const ExtractorServiceConfig& extractor,
                                      const Pose2& robot_T_laser, const DriveScanOptions& options,
                                      DriveScanCounts& scan_counts, DriveLogCounts& log_counts) {
  DriveScanBuilder builder(extractor, robot_T_laser, options);
  laser_scan_t scan_message;
  odometry_t odometry_message;
  LaserScan scan;
  log_counts = {};
  log_counts.events = static_cast<int64_t>(for_each_log_event(path, [&](const LogEventView& e) {
    if (*e.channel == extractor.input_channel) {
      if (!decode_lcm_bounded(e.data, e.size, scan_message).ok) return void(++log_counts.undecodable);
      scan_from_message(scan_message, scan);
      builder.on_scan(scan);
    } else if (*e.channel == extractor.odometry_channel) {
      if (!decode_lcm_bounded(e.data, e.size, odometry_message).ok) return void(++log_counts.undecodable);
      const odometry_t& m = odometry_message;
      builder.on_odometry({m.utime, {m.vx, m.vy, m.wz}, {m.x, m.y, m.theta}, m.distance});
    }
  }));
  std::vector<DriveScan> scans = builder.finish();
  scan_counts = builder.counts();
  return scans;
}

}  // namespace refloc
