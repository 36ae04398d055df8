#include "drive_log.hpp"

#include "common/lcm_bounded_decode.hpp"
#include "log_reader.hpp"
#include "reflector_extractor/extractor_messages.hpp"

#include <refloc/laser_scan_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>

#include <algorithm>

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

std::vector<TimedPose> read_true_poses(const std::string& path, const std::string& channel) {
  std::vector<TimedPose> out;
  pose2d_t m;
  for_each_log_event(path, [&](const LogEventView& e) {
    if (*e.channel != channel || !decode_lcm_bounded(e.data, e.size, m).ok) return;
    out.push_back({m.utime, {m.x, m.y, m.theta}, Eigen::Matrix3d::Zero()});
  });
  std::stable_sort(out.begin(), out.end(),
                   [](const TimedPose& a, const TimedPose& b) { return a.utime < b.utime; });
  return out;
}

}  // namespace refloc
