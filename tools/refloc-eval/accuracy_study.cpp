#include "accuracy_study.hpp"

#include "beam_crlb.hpp"
#include "world_renderer/world_visibility.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace refloc {
namespace {

// Beams with most of their spot on a reflector enter the bound as range
// measurements of the circle; what the rest of an edge beam's spot returns (the
// wall behind: a mixed pixel) is left out, as no estimator knows it.
constexpr double kCrlbMinCoverage = 0.5;

/// Detection statistics of one scan against what the renderer really hit.
void score_detections(const sim::World& world, const Pose2& map_T_laser,
                      const std::vector<sim::BeamTruth>& truth,
                      const std::vector<ReflectorDetection>& detections, double match_distance,
                      Measurement& m) {
  std::map<int, int> beams_on_reflector;
  for (const auto& t : truth) {
    if (t.kind == sim::HitKind::kReflector && t.coverage >= 0.5) ++beams_on_reflector[t.id];
  }
  std::set<int> visible;
  for (const auto& [id, count] : beams_on_reflector) {
    if (count >= 2) visible.insert(id);
  }
  std::set<int> detected;
  m.detections = static_cast<int>(detections.size());
  for (const auto& d : detections) {
    const Eigen::Vector2d map_p = map_T_laser * d.laser_p_center;
    int nearest = -1;
    double best = match_distance;
    for (const auto& r : world.reflectors.reflectors) {
      const double dist = (r.map_p_center - map_p).norm();
      if (dist <= best) best = dist, nearest = r.id;
    }
    if (nearest < 0) {
      ++m.false_detections;
    } else {
      detected.insert(nearest);
    }
  }
  m.visible_reflectors = static_cast<int>(visible.size());
  for (int id : visible) m.detected_visible += detected.count(id) ? 1 : 0;
}

ModeSummary summarize(const std::vector<Measurement>& all, PipelineMode mode, size_t pose_count) {
  ModeSummary s;
  s.poses = static_cast<int>(pose_count);
  std::vector<double> max_dx(pose_count, 0.0), max_dy(pose_count, 0.0);
  std::vector<bool> pose_has_ok(pose_count, false);
  double sum_e2 = 0.0, sum_h2 = 0.0, sum_crlb = 0.0, sum_point_crlb = 0.0;
  int n_ok = 0, n_crlb = 0, n_point_crlb = 0, visible = 0, detected_visible = 0, detections = 0,
      false_detections = 0;
  for (const auto& m : all) {
    if (m.mode != mode) continue;
    ++s.measurements;
    visible += m.visible_reflectors;
    detected_visible += m.detected_visible;
    detections += m.detections;
    false_detections += m.false_detections;
    s.match_ok += m.match_status == MatchStatus::kOk;
    s.match_ok_wrong += m.match_wrong;
    if (!m.published_ok) continue;
    ++s.published_ok;
    if (m.wrong) {
      ++s.wrong_matches;
      continue;
    }
    const double dx = m.estimate.x - m.truth.x, dy = m.estimate.y - m.truth.y;
    const auto p = static_cast<size_t>(m.pose_index);
    max_dx[p] = std::max(max_dx[p], std::abs(dx));
    max_dy[p] = std::max(max_dy[p], std::abs(dy));
    pose_has_ok[p] = true;
    sum_e2 += dx * dx + dy * dy;
    sum_h2 += std::pow(angle_diff(m.estimate.theta, m.truth.theta), 2);
    s.max_err_mm = std::max(s.max_err_mm, 1000.0 * std::hypot(dx, dy));
    ++n_ok;
    if (m.has_point_beam_crlb) {
      sum_point_crlb += m.point_beam_crlb_var_xy;
      ++n_point_crlb;
    }
    if (m.has_crlb) {
      sum_crlb += m.crlb_var_xy;
      ++n_crlb;
    }
  }
  ConsistencyAccumulator consistency;
  for (const auto& m : all) {
    if (m.mode != mode || !m.published_ok || m.wrong || !m.fix_ok) continue;
    const Eigen::Vector3d error(m.estimate.x - m.truth.x, m.estimate.y - m.truth.y,
                                angle_diff(m.estimate.theta, m.truth.theta));
    consistency.add(error, m.covariance);
  }
  s.consistency = consistency.summary();
  int poses_ok = 0;
  for (size_t p = 0; p < pose_count; ++p) {
    if (!pose_has_ok[p]) continue;
    s.mean_max_err_x_mm += 1000.0 * max_dx[p];
    s.mean_max_err_y_mm += 1000.0 * max_dy[p];
    ++poses_ok;
  }
  if (poses_ok > 0) {
    s.mean_max_err_x_mm /= poses_ok;
    s.mean_max_err_y_mm /= poses_ok;
  }
  if (n_ok > 0) {
    s.rmse_mm = 1000.0 * std::sqrt(sum_e2 / n_ok);
    s.heading_rmse_deg = std::sqrt(sum_h2 / n_ok) * 180.0 / M_PI;
  }
  if (n_crlb > 0) s.crlb_rmse_mm = 1000.0 * std::sqrt(sum_crlb / n_crlb);
  if (s.crlb_rmse_mm > 0.0) s.crlb_ratio = s.rmse_mm / s.crlb_rmse_mm;
  if (n_point_crlb > 0) s.point_beam_crlb_rmse_mm = 1000.0 * std::sqrt(sum_point_crlb / n_point_crlb);
  if (s.point_beam_crlb_rmse_mm > 0.0) s.point_beam_crlb_ratio = s.rmse_mm / s.point_beam_crlb_rmse_mm;
  if (visible > 0) s.recall = static_cast<double>(detected_visible) / visible;
  if (detections > 0) s.false_detection_rate = static_cast<double>(false_detections) / detections;
  return s;
}

}  // namespace

std::vector<Pose2> paper_table_poses() {
  const double mm[10][2] = {{750, 1000},  {750, 2000},  {750, 3000},  {1500, 1000}, {1500, 2000},
                            {1500, 3000}, {2500, 1000}, {2500, 2000}, {2500, 3000}, {3000, 1000}};
  std::vector<Pose2> poses;
  for (const auto& p : mm) poses.push_back({p[0] / 1000.0, p[1] / 1000.0, 0.0});
  return poses;
}

std::vector<Pose2> random_drivable_poses(const sim::World& world, int n, double clearance,
                                         std::mt19937_64& rng) {
  std::vector<Pose2> poses;
  if (world.drivable_areas.empty()) return poses;
  std::uniform_int_distribution<size_t> area(0, world.drivable_areas.size() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0), heading(-M_PI, M_PI);
  for (int attempts = 0; static_cast<int>(poses.size()) < n && attempts < 1000 * n; ++attempts) {
    const auto& a = world.drivable_areas[area(rng)];
    const Eigen::Vector2d p(a.x_min + unit(rng) * (a.x_max - a.x_min),
                            a.y_min + unit(rng) * (a.y_max - a.y_min));
    if (sim::clearance(world, p) < clearance) continue;
    poses.push_back({p.x(), p.y(), heading(rng)});
  }
  return poses;
}

StudyResult run_study(const sim::World& world, const ReflectorMap& map, const Pose2& robot_T_laser,
                      const PipelineConfigs& paper_configs, const PipelineConfigs& default_configs,
                      const std::vector<Pose2>& poses, const StudyConfig& config,
                      const ProgressCallback& progress) {
  sim::ScanRenderConfig render_config;
  render_config.sensor = config.sensor;
  sim::ScanRenderer renderer(render_config);
  // The bound models the beam the renderer casts.
  BeamSpotModel spot;
  spot.exit_diameter = render_config.sensor.beam_exit_diameter;
  spot.divergence = render_config.sensor.beam_divergence;
  spot.retro_incidence_exponent = render_config.sensor.retro_incidence_exponent;
  LocalizationPipeline paper(PipelineMode::kPaper, paper_configs, map, robot_T_laser);
  LocalizationPipeline best(PipelineMode::kDefault, default_configs, map, robot_T_laser);
  std::mt19937_64 rng(config.seed);
  LaserScan scan;
  std::vector<ReflectorBeam> crlb_beams;
  StudyResult result;
  const size_t total = poses.size() * static_cast<size_t>(config.repeats);
  size_t done = 0;
  for (size_t p = 0; p < poses.size(); ++p) {
    const Pose2 map_T_laser = poses[p] * robot_T_laser;
    for (int r = 0; r < config.repeats; ++r) {
      const auto utime =
          1700000000000000 + static_cast<int64_t>(static_cast<double>(done) * config.scan_spacing * 1e6);
      renderer.render(world, map_T_laser, utime, rng, scan);
      // The bound is the sensor's in the world as it is, whatever map the localization loads
      // (a surveyed map numbers its reflectors its own way): the world's reflectors, by their ids.
      const ReflectorMap& truth = world.reflectors;
      crlb_beams.clear();
      for (size_t b = 0; b < renderer.truth().size(); ++b) {
        const auto& t = renderer.truth()[b];
        const int index =
            t.kind == sim::HitKind::kReflector && t.coverage >= kCrlbMinCoverage ? truth.index_of(t.id) : -1;
        if (index >= 0) crlb_beams.push_back({scan.beam_angle(b), index});
      }
      const auto crlb =
          beam_range_crlb(truth, poses[p], robot_T_laser, crlb_beams, config.sensor.range_sigma, spot);
      const auto point_crlb = beam_range_crlb(truth, poses[p], robot_T_laser, crlb_beams,
                                              config.sensor.range_sigma, BeamSpotModel::point_beam());
      for (LocalizationPipeline* pipeline : {&paper, &best}) {
        const PipelineOutput& out = pipeline->on_scan(scan);
        Measurement m;
        m.mode = pipeline->mode();
        m.pose_index = static_cast<int>(p);
        m.repeat = r;
        m.truth = poses[p];
        m.published_ok = out.published_ok();
        m.match_status = out.match->result.status;
        // The solver runs only on an OK match (the services' rule): else no solution.
        m.solve_status = out.fix->has_pose ? out.solution->status : SolveStatus::kLost;
        m.estimate = out.fix->map_T_robot;
        m.fix_ok = out.fix->status == LaserFixStatus::kOk;
        m.covariance = out.fix->covariance;
        m.reflectors_used = out.fix->reflectors_used;
        if (crlb) {
          m.has_crlb = true;
          m.crlb_var_xy = (*crlb)(0, 0) + (*crlb)(1, 1);
        }
        if (point_crlb) {
          m.has_point_beam_crlb = true;
          m.point_beam_crlb_var_xy = (*point_crlb)(0, 0) + (*point_crlb)(1, 1);
        }
        m.wrong =
            m.published_ok && !approx_equal(m.estimate, m.truth, config.wrong_distance, config.wrong_angle);
        for (const ReflectorMatch& match : out.match->result.matches) {
          const auto d = static_cast<size_t>(match.detection_index);
          m.match_wrong = m.match_wrong ||
                          (m.match_status == MatchStatus::kOk && d < out.detections().size() &&
                           (map_T_laser * out.detections()[d].laser_p_center - match.map_p_center).norm() >
                               config.wrong_distance);
        }
        score_detections(world, map_T_laser, renderer.truth(), out.detections(),
                         config.detection_match_distance, m);
        result.measurements.push_back(m);
      }
      ++done;
      if (progress) progress(done, total);
    }
  }
  result.paper = summarize(result.measurements, PipelineMode::kPaper, poses.size());
  result.default_mode = summarize(result.measurements, PipelineMode::kDefault, poses.size());
  return result;
}

nlohmann::json to_json(const ModeSummary& s) {
  nlohmann::json j = {{"poses", s.poses},
                      {"measurements", s.measurements},
                      {"published_ok", s.published_ok},
                      {"wrong_matches", s.wrong_matches},
                      {"match_ok", s.match_ok},
                      {"match_ok_wrong", s.match_ok_wrong},
                      {"mean_max_err_x_mm", s.mean_max_err_x_mm},
                      {"mean_max_err_y_mm", s.mean_max_err_y_mm},
                      {"rmse_mm", s.rmse_mm},
                      {"max_err_mm", s.max_err_mm},
                      {"heading_rmse_deg", s.heading_rmse_deg},
                      {"crlb_rmse_mm", s.crlb_rmse_mm},
                      {"crlb_ratio", s.crlb_ratio},
                      {"point_beam_crlb_rmse_mm", s.point_beam_crlb_rmse_mm},
                      {"point_beam_crlb_ratio", s.point_beam_crlb_ratio},
                      {"recall", s.recall},
                      {"false_detection_rate", s.false_detection_rate}};
  j.update(consistency_json(s.consistency));
  return j;
}

std::string measurements_csv(const std::vector<Measurement>& measurements) {
  std::string csv =
      "mode,pose_index,repeat,true_x_m,true_y_m,true_theta_rad,published_ok,match_status,solve_status,wrong,"
      "est_x_m,est_y_m,est_theta_rad,"
      "err_x_mm,err_y_mm,reflectors_used,crlb_rmse_mm,visible_reflectors,detected_visible,detections,"
      "false_detections,fix_ok,nees_xy,nees_theta,match_wrong\n";
  for (const auto& m : measurements) {
    // NEES columns stay empty without a pose or a usable covariance.
    const auto nees_xy = position_nees({m.estimate.x - m.truth.x, m.estimate.y - m.truth.y},
                                       m.covariance.topLeftCorner<2, 2>());
    const auto nees_theta = heading_nees(angle_diff(m.estimate.theta, m.truth.theta), m.covariance(2, 2));
    const std::string nees = fmt::format(
        "{},{},{},{}", m.fix_ok ? 1 : 0, m.published_ok && nees_xy ? fmt::format("{:.4f}", *nees_xy) : "",
        m.published_ok && nees_theta ? fmt::format("{:.4f}", *nees_theta) : "", m.match_wrong ? 1 : 0);
    csv += fmt::format(
        "{},{},{},{:.4f},{:.4f},{:.5f},{},{},{},{},{:.5f},{:.5f},{:.6f},{:.2f},{:.2f},{},{:.3f},{},{},{},{},{"
        "}"
        "\n",
        to_string(m.mode), m.pose_index, m.repeat, m.truth.x, m.truth.y, m.truth.theta,
        m.published_ok ? 1 : 0, static_cast<int>(m.match_status), static_cast<int>(m.solve_status),
        m.wrong ? 1 : 0, m.estimate.x, m.estimate.y, m.estimate.theta, 1000.0 * (m.estimate.x - m.truth.x),
        1000.0 * (m.estimate.y - m.truth.y), m.reflectors_used,
        m.has_crlb ? 1000.0 * std::sqrt(m.crlb_var_xy) : 0.0, m.visible_reflectors, m.detected_visible,
        m.detections, m.false_detections, nees);
  }
  return csv;
}

}  // namespace refloc
