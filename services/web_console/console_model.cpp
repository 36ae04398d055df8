#include "web_console/console_model.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <utility>

namespace refloc {
namespace {

using nlohmann::json;

ConsoleFrame frame(const json& j, std::string latest_key = "", bool send_now = true) {
  // Text from the bus (a heartbeat's detail, a navigator's reason) may be any bytes: invalid
  // UTF-8 is replaced, never thrown on (a throw here would end the service).
  return {std::move(latest_key), send_now,
          std::make_shared<const std::string>(j.dump(-1, ' ', false, json::error_handler_t::replace))};
}

/// Metres to millimetres as an integer: the page needs no more, and frames stay small.
long long mm(double m) { return std::llround(m * 1000.0); }

json pose_json(const std::array<double, 3>& p) { return json::array({p[0], p[1], p[2]}); }

json laser_pose_json(const std::optional<std::array<double, 3>>& map_T_laser) {
  return map_T_laser ? pose_json(*map_T_laser) : json(nullptr);
}

}  // namespace

const char* pose_source_name(PoseSource source) {
  switch (source) {
    case PoseSource::kPose:
      return "POSE";
    case PoseSource::kLaserPose:
      return "LASER_POSE";
    case PoseSource::kGroundTruth:
      return "GROUND_TRUTH";
  }
  return "POSE";
}

ConsoleModel::ConsoleModel(const ConsoleModelConfig& config, ReflectorMap map, bool control_enabled)
    : config_(config),
      map_(std::move(map)),
      control_enabled_(control_enabled),
      scan_rate_(config.scan_rate_hz),
      detections_rate_(config.scan_rate_hz),
      clusters_rate_(config.scan_rate_hz),
      matches_rate_(config.scan_rate_hz) {
  for (int i = 0; i < 3; ++i) {
    pose_rates_.emplace_back(config.pose_rate_hz);
    trails_.emplace_back(config.trail_points, config.trail_step_m);
  }
}

ConsoleFrame ConsoleModel::map_frame() const {
  json reflectors = json::array();
  for (const MapReflector& r : map_.reflectors)
    reflectors.push_back(
        {{"id", r.id}, {"x", r.map_p_center.x()}, {"y", r.map_p_center.y()}, {"r", r.radius}});
  json occluders = json::array();
  for (const MapOccluder& o : map_.occluders) {
    json points = json::array();
    for (const auto& p : o.map_points) points.push_back({p.x(), p.y()});
    occluders.push_back({{"name", o.name}, {"points", points}, {"closed", o.closed}});
  }
  return frame({{"type", "map"},
                {"map_id", map_.info.map_id},
                {"version", map_.info.version},
                {"reflectors", reflectors},
                {"occluders", occluders}},
               "map");
}

ConsoleFrame ConsoleModel::console_frame() const {
  return frame({{"type", "console"},
                {"control_enabled", control_enabled_},
                {"scan_rate_hz", config_.scan_rate_hz},
                {"pose_rate_hz", config_.pose_rate_hz}},
               "console");
}

std::optional<ConsoleFrame> ConsoleModel::on_scan(const ConsoleScan& scan) {
  ++scans_in_;
  if (!scan_rate_.accept(scan.utime)) {
    ++scans_skipped_;
    return std::nullopt;
  }
  json ranges = json::array();
  for (const float r : scan.ranges) ranges.push_back(std::isfinite(r) && r > 0.0f && r < 1e6f ? mm(r) : 0);
  return frame({{"type", "scan"},
                {"utime", scan.utime},
                {"start_angle", scan.start_angle},
                {"angle_increment", scan.angle_increment},
                {"ranges_mm", ranges},
                {"rssi", scan.rssi},
                {"rssi_bits", scan.rssi_bits},
                {"map_T_laser", laser_pose_json(map_T_laser_)}},
               "scan");
}

std::optional<ConsoleFrame> ConsoleModel::on_detections(const ConsoleDetections& in) {
  if (!detections_rate_.accept(in.utime)) return std::nullopt;
  json detections = json::array();
  for (const ConsoleDetection& d : in.detections)
    detections.push_back({{"x", d.x},
                          {"y", d.y},
                          {"range", d.range},
                          {"bearing", d.bearing},
                          {"first_beam", d.first_beam},
                          {"beams", d.beams},
                          {"mean_rssi", d.mean_rssi},
                          {"radius", d.radius}});
  return frame({{"type", "detections"},
                {"utime", in.utime},
                {"clusters_considered", in.clusters_considered},
                {"clusters_rejected", in.clusters_rejected},
                {"detections", detections},
                {"map_T_laser", laser_pose_json(map_T_laser_)}},
               "detections");
}

std::optional<ConsoleFrame> ConsoleModel::on_clusters(const ConsoleClusters& in) {
  if (!clusters_rate_.accept(in.utime)) return std::nullopt;
  json clusters = json::array();
  for (const ConsoleCluster& c : in.clusters)
    clusters.push_back({{"first_beam", c.first_beam},
                        {"last_beam", c.last_beam},
                        {"beams", c.beams},
                        {"outcome", c.outcome},
                        {"range", c.range},
                        {"bearing", c.bearing},
                        {"max_rssi_8bit", c.max_rssi_8bit}});
  return frame({{"type", "clusters"},
                {"utime", in.utime},
                {"energy_threshold_8bit", in.energy_threshold_8bit},
                {"energy_threshold_raw", in.energy_threshold_raw},
                {"rssi_read_as_8bit", in.rssi_read_as_8bit},
                {"clusters", clusters}},
               "clusters");
}

std::optional<ConsoleFrame> ConsoleModel::on_matches(const ConsoleMatches& in) {
  if (in.status == "OK") map_T_laser_ = in.map_T_laser;  // from every scan, also those not sent
  matches_status_ = in.status;
  if (!matches_rate_.accept(in.utime)) return std::nullopt;
  json matches = json::array();
  for (const ConsoleMatch& m : in.matches)
    matches.push_back(
        {{"map_id", m.map_id}, {"map_x", m.map_x}, {"map_y", m.map_y}, {"x", m.laser_x}, {"y", m.laser_y}});
  return frame({{"type", "matches"},
                {"utime", in.utime},
                {"status", in.status},
                {"mode", in.mode},
                {"map_T_laser", pose_json(in.map_T_laser)},
                {"detections", in.detections},
                {"matches", matches}},
               "matches");
}

std::optional<ConsoleFrame> ConsoleModel::on_pose(PoseSource source, const ConsolePose& pose) {
  const int i = static_cast<int>(source);
  // The solver's LOST / AMBIGUOUS / INITIALIZING LASER_POSE carries zeros, not a pose.
  const bool has_pose = source != PoseSource::kLaserPose || pose.status == "OK" || pose.status == "DEGRADED";
  if (has_pose) trails_[i].add(pose.x, pose.y);
  if (source == PoseSource::kLaserPose) {
    ++fixes_;
    ok_fixes_ += pose.status == "OK" ? 1 : 0;
  }
  if (source == PoseSource::kPose) {
    pose_status_ = pose.status;
    ++poses_in_;
  }
  if (!pose_rates_[i].accept(pose.utime)) return std::nullopt;
  const std::string name = pose_source_name(source);
  return frame({{"type", "pose"},
                {"channel", name},
                {"utime", pose.utime},
                {"x", pose.x},
                {"y", pose.y},
                {"theta", pose.theta},
                {"covariance", pose.covariance},
                {"status", pose.status},
                {"reflectors_used", pose.reflectors_used}},
               "pose/" + name);
}

ConsoleFrame ConsoleModel::on_goal(const ConsoleGoal& goal) {
  json waypoints = json::array();
  for (const auto& w : goal.waypoints) waypoints.push_back(pose_json(w));
  return frame({{"type", "goal"}, {"goal_id", goal.goal_id}, {"waypoints", waypoints}}, "goal");
}

ConsoleFrame ConsoleModel::on_nav_status(const ConsoleNavStatus& s) {
  return frame({{"type", "nav_status"},
                {"goal_id", s.goal_id},
                {"state", s.state},
                {"waypoint_index", s.waypoint_index},
                {"waypoints_reached", s.waypoints_reached},
                {"waypoints", s.waypoints},
                {"distance_to_waypoint", s.distance_to_waypoint},
                {"heading_error", s.heading_error},
                {"reason", s.reason}},
               "nav_status");
}

ConsoleFrame ConsoleModel::on_heartbeat(const ConsoleHeartbeat& h) {
  const bool kept = kept_services_.count(h.service) > 0 ||
                    (kept_services_.size() < kMaxKeptServices && kept_services_.insert(h.service).second);
  json counters = json::object();
  for (const auto& [name, value] : h.counters) counters[name] = value;
  return frame({{"type", "heartbeat"},
                {"utime", h.utime},
                {"service", h.service},
                {"pid", h.pid},
                {"state", h.state},
                {"detail", h.detail},
                {"uptime_s", h.uptime_s},
                {"messages_in", h.messages_in},
                {"messages_out", h.messages_out},
                {"decode_errors", h.decode_errors},
                {"processing_p50_us", h.processing_p50_us},
                {"processing_p99_us", h.processing_p99_us},
                {"counters", counters}},
               kept ? "heartbeat/" + h.service : "");
}

ConsoleFrame ConsoleModel::on_map_health(const ConsoleMapHealth& in) {
  json reflectors = json::array();
  for (const ConsoleReflectorHealth& r : in.reflectors)
    reflectors.push_back({{"id", r.id},
                          {"state", r.state},
                          {"seen", r.seen},
                          {"expected_missing", r.expected_missing},
                          {"offset_x", r.offset_x},
                          {"offset_y", r.offset_y}});
  json candidates = json::array();
  for (const ConsoleCandidate& c : in.candidates)
    candidates.push_back(
        {{"x", c.x}, {"y", c.y}, {"sightings", c.sightings}, {"moved_reflector_id", c.moved_reflector_id}});
  return frame({{"type", "map_health"},
                {"map_id", in.map_id},
                {"map_version", in.map_version},
                {"scans_used", in.scans_used},
                {"reflectors", reflectors},
                {"candidates", candidates}},
               "map_health");
}

ConsoleFrame ConsoleModel::localization_frame(int64_t now_mono_us) {
  const double elapsed_s = last_localization_mono_us_ < 0
                               ? 0.0
                               : static_cast<double>(now_mono_us - last_localization_mono_us_) * 1e-6;
  const auto per_s = [&](int64_t n) { return elapsed_s > 0.0 ? static_cast<double>(n) / elapsed_s : 0.0; };
  const ConsoleFrame f = frame({{"type", "localization"},
                                {"fixes_per_s", per_s(fixes_)},
                                {"ok_fixes_per_s", per_s(ok_fixes_)},
                                {"pose_status", pose_status_},
                                {"matches_status", matches_status_}},
                               "localization");
  last_localization_mono_us_ = now_mono_us;
  fixes_ = ok_fixes_ = 0;
  return f;
}

ConsoleState ConsoleModel::state(int64_t now_mono_us) {
  ConsoleState out;
  const auto watch = [&](Silence& silence, int64_t count, const char* what) {
    if (count != silence.count_seen || silence.changed_us < 0) {
      silence.count_seen = count;
      silence.changed_us = now_mono_us;
    }
    const int64_t quiet_us = now_mono_us - silence.changed_us;
    // Counted from the console's start as well: a channel that never spoke is silent too.
    if (quiet_us <= kSilentAfterUs) return;
    out.ok = false;
    out.detail += fmt::format("{}no {} for {:.0f} s", out.detail.empty() ? "" : "; ", what, 1e-6 * quiet_us);
  };
  watch(scan_silence_, scans_in_, "scan");
  watch(pose_silence_, poses_in_, "POSE");
  return out;
}

std::vector<ConsoleFrame> ConsoleModel::trail_frames() const {
  std::vector<ConsoleFrame> frames;
  for (int i = 0; i < 3; ++i) {
    json points = json::array();
    trails_[i].for_each([&](const std::array<double, 2>& p) { points.push_back({p[0], p[1]}); });
    const std::string name = pose_source_name(static_cast<PoseSource>(i));
    frames.push_back(
        frame({{"type", "trail"}, {"channel", name}, {"points", points}}, "trail/" + name, false));
  }
  return frames;
}

}  // namespace refloc
