#include "pose_fusion/fusion_config_file.hpp"

#include "common/json_config.hpp"

namespace refloc {

FusionServiceConfig parse_fusion_service_config(const JsonConfig& config) {
  FusionServiceConfig c;
  FusionConfig& f = c.fusion;
  f.history = config.number("/fusion/history_s", f.history, 0.05, 10.0);
  f.max_fix_lead = config.number("/fusion/max_fix_lead_s", f.max_fix_lead, 0.0, 1.0);
  f.max_deferred_fixes = static_cast<size_t>(
      config.integer("/fusion/max_deferred_fixes", static_cast<long long>(f.max_deferred_fixes), 1, 100000));
  f.gate_chi2 = config.number("/fusion/gate_chi2", f.gate_chi2, 0.1, 1e6);
  f.degraded_after = config.number("/fusion/degraded_after_s", f.degraded_after, 0.01, 60.0);
  f.lost_after = config.number("/fusion/lost_after_s", f.lost_after, f.degraded_after, 600.0);
  f.max_consecutive_rejections = static_cast<int>(
      config.integer("/fusion/max_consecutive_rejections", f.max_consecutive_rejections, 1, 100000));
  OdometryContinuityConfig& o = c.continuity;
  o.max_gap = config.number("/continuity/max_gap_s", o.max_gap, 0.01, 60.0);
  o.max_speed = config.number("/continuity/max_speed_m_s", o.max_speed, 0.01, 10.0);
  o.max_yaw_rate = config.number("/continuity/max_yaw_rate_rad_s", o.max_yaw_rate, 0.01, 20.0);
  o.distance_slack = config.number("/continuity/distance_slack_m", o.distance_slack, 0.0, 1.0);
  c.odometry_timeout = config.number("/odometry_timeout_s", c.odometry_timeout, 0.01, 10.0);
  c.odometry_channel = config.string("/odometry_channel", c.odometry_channel);
  c.fix_channel = config.string("/fix_channel", c.fix_channel);
  c.output_channel = config.string("/output_channel", c.output_channel);
  for (const char* key : {"/odometry_channel", "/fix_channel", "/output_channel"}) {
    if (config.string(key, "x").empty()) config.fail(key, "expected a channel name, got \"\"");
  }
  return c;
}

FusionServiceConfig load_fusion_service_config(const std::string& path) {
  if (path.empty()) return {};
  const JsonConfig file = JsonConfig::load_file(path);
  FusionServiceConfig config = parse_fusion_service_config(file);
  file.reject_unknown_keys();
  return config;
}

}  // namespace refloc
