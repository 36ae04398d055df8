#include "drive_survey.hpp"

#include "common/json_config.hpp"
#include "reflector_matcher/rigid_fit_2d.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <set>

namespace refloc {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

BundleProblem make_problem(const std::vector<DriveScan>& scans, const TrackerResult& front,
                           const Pose2& robot_T_laser, const OdometryNoise& noise) {
  BundleProblem p;
  p.robot_T_laser = robot_T_laser;
  p.odometry_noise = noise;
  for (size_t k = 0; k < scans.size(); ++k) {
    p.angle_increment = std::max(p.angle_increment, scans[k].angle_increment);
    p.map_T_robot.push_back(front.scans[k].map_T_robot);
    p.odom_T_robot.push_back(scans[k].odom_T_robot);
    for (size_t d = 0; d < scans[k].detections.size(); ++d) {
      const int landmark = front.association[k][d];
      if (landmark < 0) continue;
      const ReflectorDetection& det = scans[k].detections[d];
      p.observations.push_back(
          {static_cast<int>(k), landmark, static_cast<int>(d), det.laser_p_center, det.covariance});
    }
  }
  for (const LandmarkTrack& t : front.landmarks) p.map_p_landmark.push_back(t.mean(front.range_bias));
  return p;
}

std::vector<BundleAnchor> place_anchors(const std::vector<SurveyAnchor>& anchors, const BundleResult& b,
                                        double gate, std::vector<int>& anchor_of_landmark) {
  std::vector<BundleAnchor> out;
  anchor_of_landmark.assign(b.landmarks.size(), -1);
  for (size_t a = 0; a < anchors.size(); ++a) {
    int best = -1;
    double best_distance = gate;
    for (size_t j = 0; j < b.landmarks.size(); ++j) {
      const double d = (b.landmarks[j].map_p - anchors[a].near).norm();
      if (b.landmarks[j].observations > 0 && d < best_distance) {
        best = static_cast<int>(j);
        best_distance = d;
      }
    }
    if (best < 0)
      throw ConfigError(
          fmt::format("anchor id {}: no surveyed reflector within {:.2f} m of ({:.3f}, {:.3f}) in "
                      "the survey's frame (--start-pose)",
                      anchors[a].id, gate, anchors[a].near.x(), anchors[a].near.y()));
    const int other = anchor_of_landmark[static_cast<size_t>(best)];
    if (other >= 0)
      throw ConfigError(fmt::format("anchors id {} and id {} name the same surveyed reflector",
                                    anchors[static_cast<size_t>(other)].id, anchors[a].id));
    anchor_of_landmark[static_cast<size_t>(best)] = static_cast<int>(a);
    out.push_back({best, anchors[a].map_p});
  }
  return out;
}

/// DriveSurveyConfig::scale_sigma_ppm: sigma^2 (p - c)(p - c)^T added to each covariance.
void add_scale_uncertainty(double scale_sigma, std::vector<SurveyedReflector>& reflectors) {
  if (!(scale_sigma > 0.0) || reflectors.empty()) return;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const SurveyedReflector& r : reflectors) centroid += r.map_p;
  centroid /= static_cast<double>(reflectors.size());
  for (SurveyedReflector& r : reflectors) {
    const Eigen::Vector2d d = r.map_p - centroid;
    const Eigen::Matrix2d scale_part = scale_sigma * scale_sigma * d * d.transpose();
    r.covariance += scale_part;
    r.frame_covariance += scale_part;
  }
}

/// Returns the id of every landmark (0: not mapped).
std::vector<int> fill_reflectors(const BundleResult& b, const TrackerResult& front,
                                 const std::vector<VisibilityCount>& visibility,
                                 const std::vector<double>& clearance,
                                 const std::vector<SurveyAnchor>& anchors,
                                 const std::vector<int>& anchor_of_landmark, DriveSurveyResult& out) {
  std::vector<int> ids(b.landmarks.size(), 0);
  std::set<int> used_ids;
  for (const SurveyAnchor& a : anchors) used_ids.insert(a.id);
  int next_id = 1;
  for (size_t j = 0; j < b.landmarks.size(); ++j) {
    const BundleLandmark& l = b.landmarks[j];
    if (l.observations == 0) continue;
    SurveyedReflector r;
    const int anchor = anchor_of_landmark.empty() ? -1 : anchor_of_landmark[j];
    if (anchor >= 0) {
      r.id = anchors[static_cast<size_t>(anchor)].id;
      r.anchor = true;
    } else {
      while (used_ids.count(next_id)) ++next_id;
      r.id = next_id++;
    }
    r.map_p = l.map_p;
    r.frame_covariance = l.covariance;
    r.covariance = l.frame_free_covariance.trace() > 0.0 ? l.frame_free_covariance : l.covariance;
    r.times_seen = l.observations;
    r.scans_expected = visibility[j].expected;
    r.scans_seen = visibility[j].seen;
    r.residual_rms = l.residual_rms;
    r.normalised_rms = l.normalised_rms;
    r.view_span = front.landmarks[j].view_span();
    r.front_end_scatter = front.landmarks[j].scatter(front.range_bias);
    r.surface_clearance = clearance[j];
    out.reflectors.push_back(r);
    ids[j] = r.id;
  }
  return ids;
}

void fill_observations(const std::vector<DriveScan>& scans, const BundleProblem& p, const BundleResult& b,
                       const std::vector<int>& ids, DriveSurveyResult& out) {
  out.observations.reserve(p.observations.size());
  for (size_t i = 0; i < p.observations.size(); ++i) {
    const BundleObservation& z = p.observations[i];
    const ReflectorDetection& d =
        scans[static_cast<size_t>(z.pose)].detections[static_cast<size_t>(z.detection)];
    out.observations.push_back({z.pose, ids[static_cast<size_t>(z.landmark)], d, b.residuals[i]});
  }
}

/// The front end's frame into the final one (they differ when anchors moved it).
Pose2 final_T_front(const TrackerResult& front, const BundleResult& b) {
  RigidFit2d fit;
  for (size_t j = 0; j < b.landmarks.size(); ++j)
    if (b.landmarks[j].observations > 0)
      fit.add(front.landmarks[j].mean(front.range_bias), b.landmarks[j].map_p);
  Pose2 out;
  if (!fit.solve(out)) return Pose2{};
  return out;
}

void fill_rejected(const TrackerResult& front, const BundleResult& b, const PromotionRule& rule,
                   const std::vector<std::string>& batch_reasons, DriveSurveyResult& out) {
  const Pose2 T = final_T_front(front, b);
  const auto add = [&](const LandmarkTrack& t, const std::string& reason) {
    out.rejected.push_back({T * t.mean(front.range_bias), t.sightings(), t.view_span(),
                            t.scatter(front.range_bias), t.seen_fraction(), reason});
  };
  for (size_t j = 0; j < front.landmarks.size(); ++j)
    if (!batch_reasons[j].empty()) add(front.landmarks[j], batch_reasons[j]);
  for (const LandmarkTrack& t : front.candidates) add(t, t.promotion_failure(rule, front.range_bias));
  std::sort(out.rejected.begin(), out.rejected.end(),
            [](const RejectedTrack& a, const RejectedTrack& c) { return a.times_seen > c.times_seen; });
}

std::vector<Eigen::Vector2d> observed_landmarks(const BundleResult& b) {
  std::vector<Eigen::Vector2d> out;
  for (const BundleLandmark& l : b.landmarks)
    if (l.observations > 0) out.push_back(l.map_p);
  return out;
}

BundleResult solve(const BundleProblem& problem, const BundleOptions& options, DriveSurveyResult& out) {
  BundleResult b = adjust_bundle(problem, options);
  ++out.batch_runs;
  if (!b.ok) throw std::runtime_error("the batch adjustment failed: " + b.message);
  return b;
}

/// Batches until the residual and spacing checks change nothing (a few rounds at most), then
/// the surface and visibility checks against the walls traced at those poses, once.
BundleResult solve_and_check(const std::vector<DriveScan>& scans, const DriveSurveyConfig& config,
                             BundleProblem& problem, std::vector<std::string>& reasons,
                             DriveSurveyResult& out) {
  BundleOptions options = config.bundle;
  options.compute_covariance = false;
  BundleResult b = solve(problem, options, out);
  while (out.batch_runs < 5 && check_residuals_and_spacing(b, config.checks, problem, reasons))
    b = solve(problem, options, out);
  const std::vector<MapOccluder> walls = trace_occluders(
      scans, b.map_T_robot, problem.robot_T_laser, b.range_bias, observed_landmarks(b), config.occluders);
  if (check_surface_and_visibility(b, walls, config.checks, problem, reasons))
    b = solve(problem, options, out);
  return b;
}

void add_warnings(DriveSurveyResult& out) {
  if (out.reflectors.size() < 3)
    out.warnings.push_back(
        fmt::format("only {} reflectors surveyed: a map needs 3 or more", out.reflectors.size()));
  if (out.scans > 0 && out.scans_dead_reckoned > out.scans / 2)
    out.warnings.push_back(
        fmt::format("{} of {} scans had no laser correction in the front end (dead reckoning)",
                    out.scans_dead_reckoned, out.scans));
  if (out.covariance_s > 0.0 && out.batch_message.find("covariance not computable") != std::string::npos)
    out.warnings.push_back("no covariance: " + out.batch_message);
}

}  // namespace

DriveSurveyResult run_drive_survey(const std::vector<DriveScan>& scans, const Pose2& robot_T_laser,
                                   const OdometryNoise& odometry_noise, const Pose2& start,
                                   const std::vector<SurveyAnchor>& anchors,
                                   const DriveSurveyConfig& config) {
  if (anchors.size() == 1)
    throw ConfigError("one anchor cannot fix the map frame (a rotation about it stays free): give 2 or more");
  DriveSurveyResult out;
  auto clock = std::chrono::steady_clock::now();
  const TrackerResult front = track_landmarks(scans, robot_T_laser, odometry_noise, start, config.tracker);
  out.front_end_s = seconds_since(clock);
  out.scans = static_cast<int>(scans.size());
  out.scans_dead_reckoned = front.scans_dead_reckoned;
  for (size_t k = 0; k < scans.size(); ++k) {
    out.front_end_map_T_robot.push_back(front.scans[k].map_T_robot);
    out.utime.push_back(scans[k].utime);
  }

  clock = std::chrono::steady_clock::now();
  BundleProblem problem = make_problem(scans, front, robot_T_laser, odometry_noise);
  std::vector<std::string> reasons(front.landmarks.size());
  BundleResult b = solve_and_check(scans, config, problem, reasons, out);

  std::vector<int> anchor_of_landmark;
  // Anchors: the solution moved rigidly onto them first, so the anchored solve starts close.
  Pose2 anchored_T_survey;
  if (!anchors.empty()) {
    problem.anchors = place_anchors(anchors, b, config.anchor_gate, anchor_of_landmark);
    RigidFit2d fit;
    for (const BundleAnchor& a : problem.anchors)
      fit.add(b.landmarks[static_cast<size_t>(a.landmark)].map_p, a.map_p);
    fit.solve(anchored_T_survey);
  }
  problem.map_T_robot = b.map_T_robot;
  for (Pose2& x : problem.map_T_robot) x = anchored_T_survey * x;
  for (size_t j = 0; j < b.landmarks.size(); ++j)
    problem.map_p_landmark[j] = anchored_T_survey * b.landmarks[j].map_p;
  b = solve(problem, config.bundle, out);
  out.batch_s = seconds_since(clock) - b.covariance_s;
  out.covariance_s = b.covariance_s;
  out.batch_message = b.message;
  out.map_T_robot = b.map_T_robot;
  out.range_bias = b.range_bias;
  out.range_bias_sigma = b.range_bias_sigma;
  out.chi2_per_dof = b.chi2_per_dof;
  out.observations_used = static_cast<int>(problem.observations.size());
  out.occluders = trace_occluders(scans, out.map_T_robot, robot_T_laser, b.range_bias, observed_landmarks(b),
                                  config.occluders);
  const std::vector<VisibilityCount> visibility =
      landmark_visibility(b, problem, out.occluders, config.checks);
  const std::vector<double> clearance = surface_clearances(b, problem, out.occluders, config.checks);
  const std::vector<int> ids =
      fill_reflectors(b, front, visibility, clearance, anchors, anchor_of_landmark, out);
  fill_observations(scans, problem, b, ids, out);
  fill_rejected(front, b, config.tracker.promotion, reasons, out);
  if (anchors.empty()) add_scale_uncertainty(config.scale_sigma_ppm * 1e-6, out.reflectors);

  add_warnings(out);
  return out;
}

}  // namespace refloc
