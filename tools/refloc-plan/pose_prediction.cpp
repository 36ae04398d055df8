#include "pose_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace refloc {

const char* to_string(Relocalization r) {
  switch (r) {
    case Relocalization::kNotTried:
      return "not_tried";
    case Relocalization::kUnique:
      return "unique";
    case Relocalization::kAmbiguous:
      return "ambiguous";
    case Relocalization::kWrong:
      return "wrong";
    case Relocalization::kLost:
      return "lost";
    case Relocalization::kNoPose:
      return "no_pose";
  }
  return "?";
}

namespace {

std::unique_ptr<const MapTriangleIndex> triangle_index(const ReflectorMap& map, const PlanConfig& config) {
  if (!config.check_ambiguity) return nullptr;
  const RelocalizationConfig& r = config.matcher.relocalization;
  return std::make_unique<const MapTriangleIndex>(map, r.side_tolerance, r.min_triangle_side,
                                                  r.max_triangle_side,
                                                  static_cast<size_t>(r.max_index_triangles));
}

}  // namespace

PlanMapIndex::PlanMapIndex(ReflectorMap map_in, const PlanConfig& config)
    : map(std::move(map_in)),
      grid(map, 0.5 * config.matcher.sensor.max_range),  // the matcher's own cell size
      occluders(map.occluders),
      triangles(triangle_index(map, config)) {}

PosePredictor::PosePredictor(ReflectorMap map, const PlanConfig& config)
    : PosePredictor(std::make_shared<const PlanMapIndex>(std::move(map), config), config) {}

PosePredictor::PosePredictor(std::shared_ptr<const PlanMapIndex> index, const PlanConfig& config)
    : shared_(std::move(index)),
      map_(shared_->map),
      config_(config),
      bright_beams_(map_, config),
      solver_(config.solver, config.robot_T_laser) {
  if (config_.check_ambiguity && shared_->triangles) {
    relocalizer_ = std::make_unique<GlobalRelocalizer>(map_, shared_->grid, *shared_->triangles,
                                                       config_.matcher.relocalization, config_.matcher.sensor,
                                                       config_.matcher.min_matches, &shared_->occluders);
  }
}

void PosePredictor::add_beams(int map_index, double range, double bearing) {
  const double radius = map_.reflectors[static_cast<size_t>(map_index)].radius;
  if (range <= radius) return;
  const double half_width = std::asin(radius / range);
  const PlanScanGeometry& s = config_.scan;
  const int first =
      std::max(0, static_cast<int>(std::ceil((bearing - half_width - s.start_angle) / s.angle_increment)));
  const int last =
      std::min(s.num_beams - 1,
               static_cast<int>(std::floor((bearing + half_width - s.start_angle) / s.angle_increment)));
  for (int b = first; b <= last; ++b) beams_.push_back({s.start_angle + b * s.angle_increment, map_index});
}

PosePrediction PosePredictor::predict(const Pose2& map_T_robot) {
  const Pose2 map_T_laser = map_T_robot * config_.robot_T_laser;
  predict_reflectors(map_, shared_->grid, map_T_laser, config_.matcher.sensor, 0.0, scratch_, predicted_);
  visible_.clear();
  beams_.clear();
  detections_.clear();
  for (size_t k = 0; k < predicted_.size(); ++k) {
    const PredictedReflector& p = predicted_[k];
    if (!p.in_view || is_shadowed(map_, predicted_, k)) continue;
    const MapReflector& reflector = map_.reflectors[static_cast<size_t>(p.map_index)];
    // A partly hidden reflector may show enough bright beams: the traced beams decide.
    if (line_of_sight(shared_->occluders, map_T_laser.translation(), reflector) == LineOfSight::kBlocked)
      continue;
    // Fewer bright beams than the extractor needs: no detection, and no beams in the bound.
    if (p.range <= reflector.radius ||
        bright_beams_.count(map_T_laser, p.map_index) < config_.extractor.min_beams) {
      continue;
    }
    add_beams(p.map_index, p.range, p.bearing);
    visible_.push_back(p.map_index);
    ReflectorDetection d;
    d.laser_p_center = p.laser_p;
    d.range = p.range;
    d.bearing = p.bearing;
    const double sigma = config_.range_sigma;
    d.covariance = Eigen::Matrix2d::Identity() * sigma * sigma;
    detections_.push_back(d);
  }
  PosePrediction out;
  out.visible = static_cast<int>(visible_.size());
  const auto bound =
      beam_range_crlb(map_, map_T_robot, config_.robot_T_laser, beams_, config_.range_sigma, config_.spot);
  if (bound && (*bound)(0, 0) + (*bound)(1, 1) >= 0.0 && (*bound)(2, 2) >= 0.0) {
    out.has_bound = true;
    out.sigma_xy = std::sqrt((*bound)(0, 0) + (*bound)(1, 1));
    out.sigma_theta = std::sqrt((*bound)(2, 2));
  }
  if (!relocalizer_ || out.visible < config_.matcher.min_matches) return out;
  relocalizer_->relocalize(detections_, match_);
  out.relocalization = classify(match_, map_T_laser, out.map_T_robot_rival);
  if (out.relocalization == Relocalization::kAmbiguous || out.relocalization == Relocalization::kWrong) {
    confirm_rival(map_T_laser, out);
  }
  if (out.relocalization == Relocalization::kUnique) {
    solver_.solve(detections_, match_.matches, solution_);
    if (solution_.status == SolveStatus::kLost) out.relocalization = Relocalization::kNoPose;
  }
  return out;
}

Relocalization PosePredictor::classify(const MatchResult& match, const Pose2& map_T_laser,
                                       Pose2& map_T_robot_rival) const {
  const RelocalizationConfig& r = config_.matcher.relocalization;
  const auto near_truth = [&](const Pose2& map_T_laser_estimate) {
    return approx_equal(map_T_laser_estimate, map_T_laser, r.distinct_pose_distance, r.distinct_pose_angle);
  };
  const Pose2 laser_T_robot = config_.robot_T_laser.inverse();
  if (match.status == MatchStatus::kLost) return Relocalization::kLost;
  if (match.status == MatchStatus::kOk) {
    if (near_truth(match.map_T_laser)) return Relocalization::kUnique;
    map_T_robot_rival = match.map_T_laser * laser_T_robot;
    return Relocalization::kWrong;
  }
  // The rival is whichever of the best and the runner-up is not here.
  const Pose2& rival = near_truth(match.map_T_laser) ? match.runner_up_map_T_laser : match.map_T_laser;
  map_T_robot_rival = rival * laser_T_robot;
  return Relocalization::kAmbiguous;
}

void PosePredictor::confirm_rival(const Pose2& map_T_laser, PosePrediction& out) {
  const int samples = config_.rival_noise_samples;
  if (samples <= 0) return;
  // Seeded by the pose, so a plan is repeatable and a pose's verdict does not depend on the order.
  std::seed_seq seed{static_cast<long>(std::lround(map_T_laser.x * 1e4)),
                     static_cast<long>(std::lround(map_T_laser.y * 1e4)),
                     static_cast<long>(std::lround(map_T_laser.theta * 1e6))};
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, config_.range_sigma);
  int unique = 0, ambiguous = 0, wrong = 0;
  Pose2 rival;
  for (int s = 0; s < samples; ++s) {
    noisy_ = detections_;
    for (ReflectorDetection& d : noisy_) {
      d.laser_p_center += Eigen::Vector2d(normal(rng), normal(rng));
      d.range = d.laser_p_center.norm();
      d.bearing = std::atan2(d.laser_p_center.y(), d.laser_p_center.x());
    }
    relocalizer_->relocalize(noisy_, noisy_match_);
    switch (classify(noisy_match_, map_T_laser, rival)) {
      case Relocalization::kUnique:
        ++unique;
        break;
      case Relocalization::kAmbiguous:
        ++ambiguous;
        break;
      case Relocalization::kWrong:
        ++wrong;
        break;
      default:
        break;
    }
  }
  // As the measurement counts a pose: ambiguous when any scan fixes at the wrong place or
  // AMBIGUOUS is at least as frequent as a fix here.
  if (wrong == 0 && unique > ambiguous) out.relocalization = Relocalization::kUnique;
}

}  // namespace refloc
