#include "navigator/navigator_config_file.hpp"

#include "common/angles.hpp"
#include "common/json_config.hpp"

namespace refloc {
NavigatorServiceConfig parse_navigator_service_config(const JsonConfig& config) {
  NavigatorServiceConfig c;
  NavigatorConfig& n = c.navigator;
  ProfileLimits& t = n.translation;
  const std::string tp = "/navigator/translation";
  t.max_speed = config.number(tp + "/max_speed_m_s", t.max_speed, 0.001, 5.0);
  t.max_accel = config.number(tp + "/max_accel_m_s2", t.max_accel, 0.001, 20.0);
  t.brake_fraction = config.number(tp + "/brake_fraction", t.brake_fraction, 0.1, 1.0);
  t.creep_distance = config.number(tp + "/creep_distance_m", t.creep_distance, 0.0, 1.0);
  t.creep_speed = config.number(tp + "/creep_speed_m_s", t.creep_speed, 0.0001, 1.0);
  t.gain = config.number(tp + "/final_approach_gain_per_s", t.gain, 0.01, 20.0);
  ProfileLimits& r = n.rotation;
  const std::string rp = "/navigator/rotation";
  r.max_speed = config.number(rp + "/max_speed_rad_s", r.max_speed, 0.001, 10.0);
  r.max_accel = config.number(rp + "/max_accel_rad_s2", r.max_accel, 0.001, 50.0);
  r.brake_fraction = config.number(rp + "/brake_fraction", r.brake_fraction, 0.1, 1.0);
  r.creep_distance =
      deg_to_rad(config.number(rp + "/creep_distance_deg", rad_to_deg(r.creep_distance), 0.0, 90.0));
  r.creep_speed = config.number(rp + "/creep_speed_rad_s", r.creep_speed, 0.0001, 1.0);
  r.gain = config.number(rp + "/final_approach_gain_per_s", r.gain, 0.01, 20.0);
  const std::string p = "/navigator";
  n.pose_timeout = config.number(p + "/pose_timeout_s", n.pose_timeout, 0.01, 5.0);
  n.settle_time = config.number(p + "/settle_time_s", n.settle_time, 0.0, 10.0);
  n.progress_timeout = config.number(p + "/progress_timeout_s", n.progress_timeout, 1.0, 3600.0);
  n.default_xy_tolerance = config.number(p + "/default_xy_tolerance_m", n.default_xy_tolerance, 0.0001, 1.0);
  n.default_heading_tolerance = deg_to_rad(config.number(
      p + "/default_heading_tolerance_deg", rad_to_deg(n.default_heading_tolerance), 0.001, 45.0));
  n.drive_on_degraded_pose = config.boolean(p + "/drive_on_degraded_pose", n.drive_on_degraded_pose);
  c.control_rate = config.number("/control_rate_hz", c.control_rate, 1.0, 1000.0);
  c.status_rate = config.number("/status_rate_hz", c.status_rate, 0.1, 100.0);
  c.goal_channel = config.string("/goal_channel", c.goal_channel);
  c.pose_channel = config.string("/pose_channel", c.pose_channel);
  c.command_channel = config.string("/command_channel", c.command_channel);
  c.status_channel = config.string("/status_channel", c.status_channel);
  for (const char* key : {"/goal_channel", "/pose_channel", "/command_channel", "/status_channel"}) {
    if (config.string(key, "x").empty()) config.fail(key, "expected a channel name, got \"\"");
  }
  return c;
}

NavigatorServiceConfig load_navigator_service_config(const std::string& path) {
  if (path.empty()) return {};
  const JsonConfig file = JsonConfig::load_file(path);
  NavigatorServiceConfig config = parse_navigator_service_config(file);
  file.reject_unknown_keys();
  return config;
}

}  // namespace refloc
