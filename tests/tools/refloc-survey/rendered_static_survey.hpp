#pragma once
// A static survey of rendered scans: N scans of a world from one robot pose through the
// extractor the service runs (ExtractorNode with the deployed config), surveyed, and each
// surveyed reflector compared with the world's true one.

#include "common/robot_config.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "reflector_extractor/extractor_node.hpp"
#include "static_survey.hpp"
#include "world_renderer/scan_renderer.hpp"
#include "world_renderer/world_loader.hpp"
#include "world_renderer/world_visibility.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace refloc::testing {

inline const std::string kConfigDir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";

struct SurveyedVersusTruth {
  int id = 0;                  ///< surveyed id
  int true_id = -1;            ///< the world's nearest reflector
  Eigen::Vector2d error;       ///< surveyed - true [m]
  double mahalanobis = 0.0;    ///< sqrt(e^T C^-1 e) with the surveyed covariance
  double major_sigma_m = 0.0;  ///< the covariance's largest sigma [m]
  /// Farther than 5 cm from every reflector, within 10 cm of tape or metal: a distractor mapped.
  bool at_distractor = false;
};

struct RenderedSurvey {
  StaticSurveyResult result;
  std::vector<SurveyedVersusTruth> comparison;
  int visible = 0;  ///< world reflectors within 15 m in the field of view with a free line of sight

  /// Surveyed entries that are real reflectors (not distractors), and how many are within 3 sigma.
  int reflectors() const {
    return static_cast<int>(
        std::count_if(comparison.begin(), comparison.end(), [](const auto& c) { return !c.at_distractor; }));
  }
  int inside_three_sigma() const {
    return static_cast<int>(std::count_if(comparison.begin(), comparison.end(), [](const auto& c) {
      return !c.at_distractor && c.mahalanobis <= 3.0;
    }));
  }
};

inline double distance_to_segment(const Eigen::Vector2d& p, const sim::WorldSegment& s) {
  const Eigen::Vector2d ab = s.map_p_b - s.map_p_a;
  const double t = std::clamp((p - s.map_p_a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (s.map_p_a + t * ab - p).norm();
}

inline double largest_sigma(const Eigen::Matrix2d& c) {
  return std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(c).eigenvalues().maxCoeff());
}

inline RenderedSurvey rendered_static_survey(const Pose2& map_T_robot, const sim::Lms100ErrorModel& sensor,
                                             const StaticSurveyConfig& config, int scans, uint64_t seed) {
  const sim::World world = sim::load_world(kConfigDir + "world_demo.json");
  const RobotConfig robot = load_robot_config(kConfigDir + "robot.json");
  const ExtractorServiceConfig extractor =
      load_extractor_service_config(kConfigDir + "reflector_extractor.json");
  const Pose2 map_T_laser = map_T_robot * robot.robot_T_laser;
  sim::ScanRenderConfig render;
  render.sensor = sensor;
  sim::ScanRenderer renderer(render);
  ExtractorNode node(extractor, robot.robot_T_laser);
  StaticSurvey survey(config);
  std::mt19937_64 rng(seed);
  LaserScan scan;
  for (int i = 0; i < scans; ++i) {
    renderer.render(world, map_T_laser, 1700000000000000 + i * 20000, rng, scan);
    scan.scan_counter = static_cast<uint32_t>(i);
    const ExtractorOutput& out = node.on_scan(scan);
    if (out.accepted) survey.add_scan(out.detections);
  }
  RenderedSurvey run;
  run.result = survey.finish(map_T_laser);
  run.visible =
      static_cast<int>(sim::visible_reflector_ids(world, map_T_laser, 15.0, 135.0 * kDegToRad).size());
  for (const StaticSurveyReflector& r : run.result.reflectors) {
    SurveyedVersusTruth c;
    c.id = r.id;
    double best = 1e9;
    for (const MapReflector& t : world.reflectors.reflectors) {
      const double d = (r.map_p_center - t.map_p_center).norm();
      if (d < best) best = d, c.true_id = t.id, c.error = r.map_p_center - t.map_p_center;
    }
    c.mahalanobis = std::sqrt(c.error.dot(r.map_cov_center.ldlt().solve(c.error)));
    for (const sim::WorldSegment& segment : world.segments) {
      if (c.error.norm() > 0.05 && segment.surface != sim::SurfaceKind::kDiffuse &&
          distance_to_segment(r.map_p_center, segment) < 0.1)
        c.at_distractor = true;
    }
    c.major_sigma_m = largest_sigma(r.map_cov_center);
    run.comparison.push_back(c);
  }
  return run;
}

}  // namespace refloc::testing
