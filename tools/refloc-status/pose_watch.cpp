#include "pose_watch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace refloc {
namespace {

constexpr double kDegPerRad = 180.0 / M_PI;

/// 1-sigma along the worst direction of the x-y covariance; -1 when not a covariance.
double largest_position_sigma(const std::array<double, 9>& c) {
  const double a = c[0], b = c[1], d = c[4];
  const double half_trace = 0.5 * (a + d);
  const double largest = half_trace + std::sqrt(0.25 * (a - d) * (a - d) + b * b);
  return std::isfinite(largest) && largest >= 0.0 && a >= 0.0 && d >= 0.0 ? std::sqrt(largest) : -1.0;
}

std::string sigma_text(const PoseReport& r) {
  const std::string position =
      r.sigma_position_m >= 0.0 ? fmt::format("{:.1f} mm", r.sigma_position_m * 1000.0) : "? mm";
  const std::string heading =
      r.sigma_theta_rad >= 0.0 ? fmt::format("{:.2f} deg", r.sigma_theta_rad * kDegPerRad) : "? deg";
  return position + " " + heading;
}

}  // namespace

std::string pose_status_name(int8_t status) {
  // Values of pose2d_t::STATUS_* (lcmtypes/pose2d_t.lcm); a test checks they agree.
  switch (status) {
    case 0:
      return "OK";
    case 1:
      return "DEGRADED";
    case 2:
      return "LOST";
    case 3:
      return "AMBIGUOUS";
    case 4:
      return "INITIALIZING";
    default:
      return "STATUS_" + std::to_string(static_cast<int>(status));
  }
}

PoseWatch::PoseWatch(double start_s, double max_age_s, double fix_window_s)
    : start_s_(start_s), max_age_s_(max_age_s), fix_window_s_(fix_window_s) {}

void PoseWatch::on_pose(const PoseSample& pose, double receive_s) {
  heard_ = true;
  last_ = pose;
  last_receive_s_ = receive_s;
}

void PoseWatch::on_laser_pose(int8_t status, double receive_s) {
  fixes_.push_back({receive_s, status == 0});
  while (!fixes_.empty() && fixes_.front().receive_s < receive_s - fix_window_s_) fixes_.pop_front();
}

PoseReport PoseWatch::report(double now_s) const {
  PoseReport r;
  r.heard = heard_;
  if (heard_) {
    r.last = last_;
    r.age_s = std::max(0.0, now_s - last_receive_s_);
    r.stale = r.age_s > max_age_s_;
    r.sigma_position_m = largest_position_sigma(last_.covariance);
    const double var_theta = last_.covariance[8];
    r.sigma_theta_rad = std::isfinite(var_theta) && var_theta >= 0.0 ? std::sqrt(var_theta) : -1.0;
  }
  // Over the last fix_window_s, or since listening began when that is shorter.
  const double window_start_s = std::max(now_s - fix_window_s_, start_s_);
  const double span_s = now_s - window_start_s;
  if (span_s <= 0.0) return r;
  int all = 0, ok = 0;
  for (const auto& f : fixes_) {
    if (f.receive_s < window_start_s || f.receive_s > now_s) continue;
    ++all;
    ok += f.ok ? 1 : 0;
  }
  r.laser_poses_per_s = all / span_s;
  r.fixes_ok_per_s = ok / span_s;
  return r;
}

std::string format_pose_line(const PoseReport& r) {
  const std::string fixes =
      fmt::format("fixes {:.1f}/s OK of {:.1f}/s", r.fixes_ok_per_s, r.laser_poses_per_s);
  if (!r.heard) return "POSE none heard, " + fixes + "\n";
  const std::string status =
      r.stale ? fmt::format("STALE ({} {:.1f} s ago)", pose_status_name(r.last.status), r.age_s)
              : pose_status_name(r.last.status);
  return fmt::format("POSE {} x {:.3f} y {:.3f} m, theta {:.2f} deg, sigma {}, {}\n", status, r.last.x_m,
                     r.last.y_m, r.last.theta_rad * kDegPerRad, sigma_text(r), fixes);
}

nlohmann::json pose_to_json(const PoseReport& r) {
  const auto number_or_null = [](bool known, double v) {
    return known ? nlohmann::json(v) : nlohmann::json();
  };
  nlohmann::json j;
  j["heard"] = r.heard;
  j["status"] = r.heard ? nlohmann::json(pose_status_name(r.last.status)) : nlohmann::json();
  j["x_m"] = number_or_null(r.heard, r.last.x_m);
  j["y_m"] = number_or_null(r.heard, r.last.y_m);
  j["theta_rad"] = number_or_null(r.heard, r.last.theta_rad);
  j["sigma_position_m"] = number_or_null(r.heard && r.sigma_position_m >= 0.0, r.sigma_position_m);
  j["sigma_theta_rad"] = number_or_null(r.heard && r.sigma_theta_rad >= 0.0, r.sigma_theta_rad);
  j["age_s"] = number_or_null(r.heard, r.age_s);
  j["stale"] = r.stale;
  j["fixes_ok_per_s"] = r.fixes_ok_per_s;
  j["laser_poses_per_s"] = r.laser_poses_per_s;
  return j;
}

}  // namespace refloc
