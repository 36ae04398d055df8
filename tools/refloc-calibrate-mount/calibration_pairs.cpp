#include "calibration_pairs.hpp"

#include "common/angles.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

std::vector<FixWindow> select_fix_windows(const std::vector<TimedPose>& fixes, const WindowOptions& options) {
  std::vector<FixWindow> windows;
  size_t first = 0;
  for (size_t i = 1; i < fixes.size(); ++i) {
    if (static_cast<double>(fixes[i].utime - fixes[i - 1].utime) * 1e-6 > options.max_fix_gap_s) {
      first = i;  // a gap: the motion across it is not observed finely enough
      continue;
    }
    const Pose2 first_T_i = fixes[first].pose.inverse() * fixes[i].pose;
    const double duration_s = static_cast<double>(fixes[i].utime - fixes[first].utime) * 1e-6;
    if (first_T_i.translation().norm() >= options.min_translation_m ||
        std::abs(first_T_i.theta) >= options.min_rotation_rad || duration_s >= options.max_duration_s) {
      windows.push_back({first, i});
      first = i;
    }
  }
  return windows;
}

std::optional<Pose2> interpolate_pose(const std::vector<TimedPose>& series, int64_t utime, double max_gap_s) {
  const auto after = std::lower_bound(series.begin(), series.end(), utime,
                                      [](const TimedPose& p, int64_t t) { return p.utime < t; });
  if (after == series.end()) return std::nullopt;
  if (after->utime == utime) return after->pose;
  if (after == series.begin()) return std::nullopt;
  const TimedPose& before = *(after - 1);
  const double span_s = static_cast<double>(after->utime - before.utime) * 1e-6;
  if (span_s > max_gap_s) return std::nullopt;
  const double f = static_cast<double>(utime - before.utime) * 1e-6 / span_s;
  Pose2 p;
  p.x = before.pose.x + f * (after->pose.x - before.pose.x);
  p.y = before.pose.y + f * (after->pose.y - before.pose.y);
  p.theta = wrap_angle(before.pose.theta + f * wrap_angle(after->pose.theta - before.pose.theta));
  return p;
}

TimedPose compose_mount(const TimedPose& map_T_robot, const Pose2& robot_T_laser) {
  TimedPose out;
  out.utime = map_T_robot.utime;
  out.pose = map_T_robot.pose * robot_T_laser;
  const Eigen::Vector2d lever = map_T_robot.pose.rotation() * robot_T_laser.translation();
  Eigen::Matrix3d j = Eigen::Matrix3d::Identity();
  j(0, 2) = -lever.y();
  j(1, 2) = lever.x();
  out.covariance = j * map_T_robot.covariance * j.transpose();
  return out;
}

TimedPose relative_pose(const TimedPose& first, const TimedPose& last) {
  TimedPose out;
  out.utime = last.utime;
  out.pose = first.pose.inverse() * last.pose;
  const Eigen::Matrix2d first_R_map = first.pose.rotation().transpose();
  const Eigen::Vector2d delta = last.pose.translation() - first.pose.translation();
  const double c = std::cos(first.pose.theta);
  const double s = std::sin(first.pose.theta);
  Eigen::Matrix2d d_first_R_map;  // d/dtheta of R(theta)^T
  d_first_R_map << -s, c, -c, -s;
  Eigen::Matrix3d j_first = Eigen::Matrix3d::Zero();
  j_first.topLeftCorner<2, 2>() = -first_R_map;
  j_first.topRightCorner<2, 1>() = d_first_R_map * delta;
  j_first(2, 2) = -1.0;
  Eigen::Matrix3d j_last = Eigen::Matrix3d::Identity();
  j_last.topLeftCorner<2, 2>() = first_R_map;
  out.covariance =
      j_first * first.covariance * j_first.transpose() + j_last * last.covariance * j_last.transpose();
  return out;
}

std::array<double, 4> wheel_angle_delta(const EncoderSample& from, const EncoderSample& to,
                                        int ticks_per_rev) {
  std::array<double, 4> angle{};
  for (size_t w = 0; w < 4; ++w) {
    // Modular difference: the counters wrap as int32 (a real encoder does).
    const auto step =
        static_cast<int32_t>(static_cast<uint32_t>(to.ticks[w]) - static_cast<uint32_t>(from.ticks[w]));
    angle[w] = static_cast<double>(step) * 2.0 * M_PI / ticks_per_rev;
  }
  return angle;
}

}  // namespace refloc
