#include "calibration_log.hpp"

#include "log_reader.hpp"

#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/wheel_encoders_t.hpp>

#include <algorithm>

namespace refloc {
namespace {

template <class Message>
bool decode(const LogEventView& e, Message& m) {
  return m.decode(e.data, 0, static_cast<int>(e.size)) >= 0;
}

Eigen::Matrix3d covariance_of(const double (&c)[9]) {
  Eigen::Matrix3d m;
  for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = c[i];
  return m;
}

template <class T>
void sort_by_utime(std::vector<T>& v) {
  std::stable_sort(v.begin(), v.end(), [](const T& a, const T& b) { return a.utime < b.utime; });
}

}  // namespace

CalibrationDrive read_calibration_log(const std::string& path, const CalibrationChannels& channels,
                                      CalibrationLogCounts& counts) {
  CalibrationDrive drive;
  counts = {};
  for_each_log_event(path, [&](const LogEventView& e) {
    if (*e.channel == channels.odometry) {
      odometry_t m{};
      if (!decode(e, m)) return void(++counts.undecodable);
      drive.odometry.push_back({m.utime, Pose2{m.x, m.y, m.theta}, covariance_of(m.covariance)});
      ++counts.odometry;
    } else if (*e.channel == channels.laser_pose) {
      pose2d_t m{};
      if (!decode(e, m)) return void(++counts.undecodable);
      if (m.status != pose2d_t::STATUS_OK) return void(++counts.laser_fixes_not_ok);
      drive.laser_fixes.push_back({m.utime, Pose2{m.x, m.y, m.theta}, covariance_of(m.covariance)});
      ++counts.laser_fixes_ok;
    } else if (*e.channel == channels.encoders) {
      wheel_encoders_t m{};
      if (!decode(e, m)) return void(++counts.undecodable);
      drive.encoders.push_back({m.utime, {m.ticks[0], m.ticks[1], m.ticks[2], m.ticks[3]}});
      ++counts.encoders;
    }
  });
  sort_by_utime(drive.odometry);
  sort_by_utime(drive.laser_fixes);
  sort_by_utime(drive.encoders);
  return drive;
}

}  // namespace refloc
