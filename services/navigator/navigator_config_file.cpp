#include "navigator/navigator_config_file.hpp"

#include "common/angles.hpp"
#include "common/json_config.hpp"

namespace refloc {
NavigatorServiceConfig parse_navigator_service_config(const JsonConfig& config) {
  NavigatorServiceConfig c;
  NavigatorConfig& n = c.navigator;
  ProfileLimits& t = n.translation;
  const std::string tp = "/navigator/translation";
  t.max_speed =
      config.number({tp + "/max_speed_m_s", "m/s",
                     "cruise speed toward a waypoint (a goal's max_speed may only lower it); CMD_VEL "
                     "is clamped to it; start slow on a new robot"},
                    t.max_speed, 0.001, 5.0);
  t.max_accel = config.number({tp + "/max_accel_m_s2", "m/s^2",
                               "the commanded velocity changes by at most this per second; higher: quicker, "
                               "more wheel slip and odometry error"},
                              t.max_accel, 0.001, 20.0);
  t.brake_fraction =
      config.number({tp + "/brake_fraction", "",
                     "braking is planned with this share of max_accel, a margin for pose lag and "
                     "the drive's ramp; lower: brakes earlier, arrives later"},
                    t.brake_fraction, 0.1, 1.0);
  t.creep_distance =
      config.number({tp + "/creep_distance_m", "m",
                     "the final approach starts this far from the waypoint: speed min(creep_speed, "
                     "gain x distance) converges instead of overshooting"},
                    t.creep_distance, 0.0, 1.0);
  t.creep_speed = config.number({tp + "/creep_speed_m_s", "m/s",
                                 "speed cap of the final approach, and the speed braking aims for at "
                                 "creep_distance; higher: faster arrival, more overshoot"},
                                t.creep_speed, 0.0001, 1.0);
  t.gain = config.number({tp + "/final_approach_gain_per_s", "1/s",
                          "inside creep_distance the speed is this times the remaining distance (capped at "
                          "creep_speed); higher: snappier, may oscillate on a lagging pose"},
                         t.gain, 0.01, 20.0);
  ProfileLimits& r = n.rotation;
  const std::string rp = "/navigator/rotation";
  r.max_speed = config.number({rp + "/max_speed_rad_s", "rad/s",
                               "yaw rate limit toward the waypoint's heading; CMD_VEL's wz is clamped to it"},
                              r.max_speed, 0.001, 10.0);
  r.max_accel = config.number({rp + "/max_accel_rad_s2", "rad/s^2",
                               "the commanded yaw rate changes by at most this per second; higher: quicker "
                               "turns, more wheel slip"},
                              r.max_accel, 0.001, 50.0);
  r.brake_fraction =
      config.number({rp + "/brake_fraction", "",
                     "braking of the turn is planned with this share of max_accel; lower: brakes earlier"},
                    r.brake_fraction, 0.1, 1.0);
  r.creep_distance = deg_to_rad(config.number(
      {rp + "/creep_distance_deg", "deg",
       "the turn's final approach starts at this heading error: rate min(creep_speed, gain x error)"},
      rad_to_deg(r.creep_distance), 0.0, 90.0));
  r.creep_speed =
      config.number({rp + "/creep_speed_rad_s", "rad/s",
                     "yaw rate cap of the turn's final approach, and the rate braking aims for at "
                     "creep_distance_deg; higher: faster, more overshoot"},
                    r.creep_speed, 0.0001, 1.0);
  r.gain = config.number({rp + "/final_approach_gain_per_s", "1/s",
                          "inside creep_distance_deg the yaw rate is this times the heading error (capped at "
                          "creep_speed); higher: snappier, may oscillate"},
                         r.gain, 0.01, 20.0);
  const std::string p = "/navigator";
  n.pose_timeout =
      config.number({p + "/pose_timeout_s", "s",
                     "a POSE older than this stops the robot (zero twist, STOPPED_NO_POSE) until a "
                     "fresh one; longer drives further on an old pose"},
                    n.pose_timeout, 0.01, 5.0);
  n.settle_time = config.number({p + "/settle_time_s", "s",
                                 "inside both tolerances this long in a row: waypoint reached; longer: surer "
                                 "stop, slower missions; 0: the first pose inside"},
                                n.settle_time, 0.0, 10.0);
  n.progress_timeout =
      config.number({p + "/progress_timeout_s", "s",
                     "ABORTED when neither distance (by 5 mm) nor heading error (by 0.01 rad) "
                     "improved this long outside the xy tolerance"},
                    n.progress_timeout, 1.0, 3600.0);
  n.default_xy_tolerance = config.number({p + "/default_xy_tolerance_m", "m",
                                          "reached within this distance unless the goal sets xy_tolerance; "
                                          "tighter than the robot can hold: progress_timeout aborts"},
                                         n.default_xy_tolerance, 0.0001, 1.0);
  n.default_heading_tolerance = deg_to_rad(config.number(
      {p + "/default_heading_tolerance_deg", "deg",
       "reached within this heading error unless the goal sets heading_tolerance; tighter than the POSE's "
       "heading noise: it may never settle"},
      rad_to_deg(n.default_heading_tolerance), 0.001, 45.0));
  n.drive_on_degraded_pose = config.boolean({p + "/drive_on_degraded_pose", "",
                                             "true: also drive on a DEGRADED POSE (no recent laser fix: "
                                             "odometry only, drifting); false: stop until "
                                             "fixes return"},
                                            n.drive_on_degraded_pose);
  c.control_rate = config.number({"/control_rate_hz", "Hz",
                                  "CMD_VEL rate while a goal is active, the control period; the bridge stops "
                                  "after 0.2 s without one; below 10 Hz accelerations lag"},
                                 c.control_rate, 1.0, 1000.0);
  c.status_rate = config.number(
      {"/status_rate_hz", "Hz", "NAV_STATUS rate, besides one on every change of state or waypoint"},
      c.status_rate, 0.1, 100.0);
  c.goal_channel = config.string(
      {"/goal_channel", "", "LCM channel of the goals read (nav_goal_t); refloc-mission sends on NAV_GOAL"},
      c.goal_channel);
  c.pose_channel =
      config.string({"/pose_channel", "",
                     "LCM channel of the pose driven on (pose2d_t with its status): pose_fusion's POSE"},
                    c.pose_channel);
  c.command_channel = config.string(
      {"/command_channel", "", "LCM channel of the body twist commands (twist_t) to the motor bridge"},
      c.command_channel);
  c.status_channel = config.string(
      {"/status_channel", "", "LCM channel of the goal's progress (nav_status_t), read by refloc-mission"},
      c.status_channel);
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
