#include "drive_truth_check.hpp"

#include <fmt/format.h>
#include <Eigen/LU>

#include <cmath>
#include <map>

namespace refloc {

DetectionTruthCheck check_detections_against_truth(const DriveSurveyResult& survey,
                                                   const std::vector<TimedPose>& truth,
                                                   const MapComparison& comparison,
                                                   const Pose2& robot_T_laser) {
  std::map<int, Eigen::Vector2d> true_p;  // surveyed id -> true centre
  for (const ReflectorComparison& c : comparison.matched) true_p[c.map_id] = c.truth_p;
  DetectionTruthCheck out;
  Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();  // range error = offset + slope * range, weighted
  Eigen::Vector2d rhs = Eigen::Vector2d::Zero();
  double across_sum = 0.0;
  struct Error {
    int id;
    Eigen::Vector2d map_e, map_u;  ///< the error and the line of sight in the map frame
    double weight;
  };
  std::vector<Error> errors;
  for (const SurveyObservation& o : survey.observations) {
    const auto p = true_p.find(o.reflector_id);
    const int64_t utime = survey.utime[static_cast<size_t>(o.scan)];
    const std::optional<Pose2> robot = interpolate_pose(truth, utime, 0.05);
    if (p == true_p.end() || !robot) continue;
    const Pose2 map_T_laser = *robot * robot_T_laser;
    const Eigen::Vector2d laser_p_true = map_T_laser.inverse() * p->second;
    const Eigen::Vector2d e = o.detection.laser_p_center - laser_p_true;
    const Eigen::Vector2d u = laser_p_true.normalized();
    const double range_error = u.dot(e), range = laser_p_true.norm();
    const double w = 1.0 / std::max(u.dot(o.detection.covariance * u), 1e-8);
    const Eigen::Vector2d x(1.0, range);
    normal += w * x * x.transpose();
    rhs += w * range_error * x;
    across_sum += u.x() * e.y() - u.y() * e.x();
    errors.push_back({o.reflector_id, map_T_laser.rotation() * e, map_T_laser.rotation() * u,
                      1.0 / std::max(o.detection.covariance.trace(), 1e-8)});
    ++out.detections;
  }
  if (out.detections < 2) return out;
  const Eigen::Vector2d fit = normal.fullPivLu().solve(rhs);
  out.range_error_offset = fit(0);
  out.range_error_slope = fit(1);
  out.across_error_mean = across_sum / out.detections;
  // The range offset the batch estimated is taken off, as the batch does.
  std::map<int, std::pair<Eigen::Vector2d, double>> per_reflector;  // weighted error sum, weight
  for (const Error& e : errors) {
    auto& r = per_reflector.try_emplace(e.id, Eigen::Vector2d::Zero(), 0.0).first->second;
    r.first += e.weight * (e.map_e - survey.range_bias * e.map_u);
    r.second += e.weight;
  }
  double sum2 = 0.0;
  for (const auto& [id, r] : per_reflector) {
    out.reflectors.push_back({id, r.first / r.second});
    sum2 += out.reflectors.back().mean_error.squaredNorm();
  }
  out.mean_error_rms = std::sqrt(sum2 / static_cast<double>(out.reflectors.size()));
  return out;
}

std::string truth_check_text(const DetectionTruthCheck& c) {
  std::string text = fmt::format(
      "detections at the true poses ({}): range error {:+.2f} mm {:+.3f} mm/m x range ({:+.0f} ppm: a map "
      "scaled by "
      "{:+.0f} ppm); across the line of sight {:+.2f} mm\n",
      c.detections, c.range_error_offset * 1e3, c.range_error_slope * 1e3, c.range_error_slope * 1e6,
      c.range_error_slope * 1e6, c.across_error_mean * 1e3);
  text += fmt::format(
      "per reflector, the weighted mean of its detections' errors at the true poses less the surveyed range "
      "offset "
      "(what a perfect trajectory would map): RMS {:.2f} mm\n",
      c.mean_error_rms * 1e3);
  for (const DetectionTruthCheck::Reflector& r : c.reflectors)
    text += fmt::format("  id {:3d}: ({:+.2f}, {:+.2f}) mm\n", r.map_id, r.mean_error.x() * 1e3,
                        r.mean_error.y() * 1e3);
  return text;
}

}  // namespace refloc
