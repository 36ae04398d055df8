#include "pose_prediction.hpp"

#include <algorithm>
#include <cmath>

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

PosePredictor::PosePredictor(ReflectorMap map, const PlanConfig& config)
    : map_(std::move(map)),
      config_(config),
      grid_(map_, 0.5 * config.matcher.sensor.max_range),  // the matcher's own cell size
      occluders_(map_.occluders),
      bright_beams_(map_, config),
      solver_(config.solver, config.robot_T_laser) {
  if (config_.check_ambiguity) {
    const RelocalizationConfig& r = config_.matcher.relocalization;
    index_ =
        std::make_unique<MapTriangleIndex>(map_, r.side_tolerance, r.min_triangle_side, r.max_triangle_side,
                                           static_cast<size_t>(r.max_index_triangles));
    relocalizer_ = std::make_unique<GlobalRelocalizer>(map_, grid_, *index_, r, config_.matcher.sensor,
                                                       config_.matcher.min_matches, &occluders_);
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
  predict_reflectors(map_, grid_, map_T_laser, config_.matcher.sensor, 0.0, scratch_, predicted_);
  visible_.clear();
  beams_.clear();
  detections_.clear();
  for (size_t k = 0; k < predicted_.size(); ++k) {
    const PredictedReflector& p = predicted_[k];
    if (!p.in_view || is_shadowed(map_, predicted_, k)) continue;
    const MapReflector& reflector = map_.reflectors[static_cast<size_t>(p.map_index)];
    // A partly hidden reflector may show enough bright beams: the traced beams decide.
    if (line_of_sight(occluders_, map_T_laser.translation(), reflector) == LineOfSight::kBlocked) continue;
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
  const RelocalizationConfig& r = config_.matcher.relocalization;
  const auto near_truth = [&](const Pose2& map_T_laser_estimate) {
    return approx_equal(map_T_laser_estimate, map_T_laser, r.distinct_pose_distance, r.distinct_pose_angle);
  };
  const Pose2 laser_T_robot = config_.robot_T_laser.inverse();
  if (match_.status == MatchStatus::kLost) {
    out.relocalization = Relocalization::kLost;
  } else if (match_.status == MatchStatus::kOk) {
    out.relocalization = near_truth(match_.map_T_laser) ? Relocalization::kUnique : Relocalization::kWrong;
    if (out.relocalization == Relocalization::kWrong) {
      out.map_T_robot_rival = match_.map_T_laser * laser_T_robot;
    } else {
      solver_.solve(detections_, match_.matches, solution_);
      if (solution_.status == SolveStatus::kLost) out.relocalization = Relocalization::kNoPose;
    }
  } else {
    out.relocalization = Relocalization::kAmbiguous;
    // The rival is whichever of the best and the runner-up is not here.
    const Pose2& rival = near_truth(match_.map_T_laser) ? match_.runner_up_map_T_laser : match_.map_T_laser;
    out.map_T_robot_rival = rival * laser_T_robot;
  }
  return out;
}

}  // namespace refloc
