#include "reflector_matcher/matcher_config_file.hpp"

#include "common/json_config.hpp"

#include <filesystem>

namespace refloc {

MatcherServiceConfig parse_matcher_service_config(const JsonConfig& config, const std::string& base_dir) {
  MatcherServiceConfig s;
  MatcherConfig& m = s.matcher;
  constexpr double kDeg = M_PI / 180.0;
  const std::string map_name = config.string("/map_file", "map_demo.json");
  std::filesystem::path map_path(map_name);
  if (map_path.is_relative() && !base_dir.empty()) map_path = std::filesystem::path(base_dir) / map_path;
  s.map_file = map_path.lexically_normal().string();
  m.mode = config.choice("/mode", "default", {"default", "paper"}) == "paper" ? MatcherMode::kPaper
                                                                              : MatcherMode::kDefault;
  s.input_channel = config.string("/input_channel", s.input_channel);
  s.prior_channel = config.string("/prior_channel", s.prior_channel);
  s.output_channel = config.string("/output_channel", s.output_channel);
  PriorSelectionConfig& p = s.prior;
  p.max_age = config.number("/prior_max_age_s", p.max_age, 0.0, 10.0);
  p.use_own_pose = config.boolean("/use_own_pose_as_prior", p.use_own_pose);
  p.own_sigma_xy = config.number("/own_prior_sigma_m", p.own_sigma_xy, 0.001, 10.0);
  p.own_sigma_theta = config.number("/own_prior_sigma_deg", p.own_sigma_theta / kDeg, 0.01, 90.0) * kDeg;
  p.relocalize_on_start = config.number("/relocalize_on_start_s", p.relocalize_on_start, 0.0, 60.0);

  m.sensor.min_range = config.number("/sensor/min_range_m", m.sensor.min_range, 0.0, 100.0);
  m.sensor.max_range = config.number("/sensor/max_range_m", m.sensor.max_range, 0.5, 100.0);
  m.sensor.field_of_view =
      config.number("/sensor/field_of_view_deg", m.sensor.field_of_view / kDeg, 1.0, 360.0) * kDeg;
  if (m.sensor.min_range >= m.sensor.max_range)
    config.fail("/sensor/min_range_m", "must be below /sensor/max_range_m");

  m.paper.side_tolerance = config.number("/paper/side_tolerance_m", m.paper.side_tolerance, 0.001, 2.0);
  m.paper.angle_tolerance =
      config.number("/paper/angle_tolerance_deg", m.paper.angle_tolerance / kDeg, 0.01, 45.0) * kDeg;

  m.tracking.prior_min_sigma_xy =
      config.number("/tracking/prior_min_sigma_m", m.tracking.prior_min_sigma_xy, 0.0, 10.0);
  m.tracking.prior_min_sigma_theta =
      config.number("/tracking/prior_min_sigma_deg", m.tracking.prior_min_sigma_theta / kDeg, 0.0, 90.0) *
      kDeg;
  m.tracking.gate_chi2 = config.number("/tracking/gate_chi2", m.tracking.gate_chi2, 0.1, 1000.0);
  m.tracking.detection_min_sigma =
      config.positive_number("/tracking/detection_min_sigma_m", m.tracking.detection_min_sigma, 1.0,
                             "0 lets an exact detection divide the gate by zero");
  m.tracking.max_unexplained =
      static_cast<int>(config.integer("/tracking/max_unexplained", m.tracking.max_unexplained, 0, 1000));
  m.tracking.min_score = config.number("/tracking/min_score", m.tracking.min_score, -1000.0, 1000.0);

  m.relocalization.side_tolerance =
      config.number("/relocalization/side_tolerance_m", m.relocalization.side_tolerance, 0.001, 2.0);
  m.relocalization.min_triangle_side =
      config.number("/relocalization/min_triangle_side_m", m.relocalization.min_triangle_side, 0.0, 50.0);
  m.relocalization.max_triangle_side =
      config.number("/relocalization/max_triangle_side_m", 2.0 * m.sensor.max_range, 0.1, 1000.0);
  if (m.relocalization.max_triangle_side <= m.relocalization.min_triangle_side) {
    config.fail("/relocalization/max_triangle_side_m",
                "must be above /relocalization/min_triangle_side_m (else no triangle is indexed)");
  }
  m.relocalization.max_index_triangles = static_cast<int>(config.integer(
      "/relocalization/max_index_triangles", m.relocalization.max_index_triangles, 1000, 100000000));
  m.relocalization.max_triple_detections = static_cast<int>(config.integer(
      "/relocalization/max_triple_detections", m.relocalization.max_triple_detections, 3, 100));
  m.relocalization.max_hypotheses = static_cast<int>(
      config.integer("/relocalization/max_hypotheses", m.relocalization.max_hypotheses, 1, 10000000));
  m.relocalization.hypothesis_fit_max_error = config.number(
      "/relocalization/hypothesis_fit_max_error_m", m.relocalization.hypothesis_fit_max_error, 0.001, 5.0);
  m.relocalization.verify_coarse_gate =
      config.number("/relocalization/verify_coarse_gate_m", m.relocalization.verify_coarse_gate, 0.001, 5.0);
  m.relocalization.verify_fine_gate =
      config.number("/relocalization/verify_fine_gate_m", m.relocalization.verify_fine_gate, 0.001, 5.0);
  m.relocalization.missed_penalty =
      config.number("/relocalization/missed_penalty", m.relocalization.missed_penalty, 0.0, 10.0);
  m.relocalization.missed_penalty_max_range = config.number(
      "/relocalization/missed_penalty_max_range_m", m.relocalization.missed_penalty_max_range, 0.0, 100.0);
  m.relocalization.unexplained_penalty =
      config.number("/relocalization/unexplained_penalty", m.relocalization.unexplained_penalty, 0.0, 10.0);
  m.relocalization.min_explained_fraction = config.number("/relocalization/min_explained_fraction",
                                                          m.relocalization.min_explained_fraction, 0.0, 1.0);
  m.relocalization.min_score =
      config.number("/relocalization/min_score", m.relocalization.min_score, -1000.0, 1000.0);
  m.relocalization.ambiguity_ratio =
      config.number("/relocalization/ambiguity_ratio", m.relocalization.ambiguity_ratio, 0.0, 1.0);
  m.relocalization.ambiguity_missed_margin = config.number(
      "/relocalization/ambiguity_missed_margin", m.relocalization.ambiguity_missed_margin, 0.0, 100.0);
  m.relocalization.distinct_pose_distance = config.number(
      "/relocalization/distinct_pose_distance_m", m.relocalization.distinct_pose_distance, 0.0, 100.0);
  m.relocalization.distinct_pose_angle =
      config.number("/relocalization/distinct_pose_angle_deg", m.relocalization.distinct_pose_angle / kDeg,
                    0.0, 180.0) *
      kDeg;
  m.min_matches = static_cast<int>(config.integer("/min_matches", m.min_matches, 3, 100));
  return s;
}

MatcherServiceConfig load_matcher_service_config(const std::string& path) {
  const JsonConfig file =
      path.empty() ? JsonConfig(nlohmann::json::object(), "(defaults)") : JsonConfig::load_file(path);
  const std::string base =
      path.empty() ? "deploy/config" : std::filesystem::path(path).parent_path().string();
  MatcherServiceConfig config = parse_matcher_service_config(file, base);
  file.reject_unknown_keys();
  return config;
}

}  // namespace refloc
