#include "reflector_matcher/scan_evidence.hpp"

#include "reflector_matcher/rigid_fit_2d.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {
namespace {

SensorVisibilityConfig expectation_limits(SensorVisibilityConfig sensor, const MapHealthConfig& config) {
  sensor.max_range = std::max(sensor.min_range, std::min(sensor.max_range, config.expect_max_range));
  return sensor;
}

}  // namespace

bool line_of_sight_clear(const LaserScan& scan, double range, double bearing, double radius,
                         double tolerance) {
  if (scan.ranges.empty() || !(scan.angle_increment > 0.0) || range <= radius) return false;
  // The cylinder's angular half width, plus one beam: the beams are measured while the laser
  // turns, the prediction is for the scan's first beam.
  const double half = std::asin(radius / range) + scan.angle_increment;
  const double first = std::ceil((bearing - half - scan.start_angle) / scan.angle_increment);
  const double last = std::floor((bearing + half - scan.start_angle) / scan.angle_increment);
  const double beams = static_cast<double>(scan.ranges.size());
  if (first < 0.0 || last >= beams || first > last) return false;
  const double near_face = range - radius - tolerance;
  for (auto i = static_cast<size_t>(first); i <= static_cast<size_t>(last); ++i) {
    const double r = scan.ranges[i];
    if (r == 0.0) continue;  // no echo: nothing in front within the sensor's range
    if (r < scan.range_min || r < near_face) return false;
  }
  return true;
}

ScanEvidenceBuilder::ScanEvidenceBuilder(const ReflectorMap& map, const SensorVisibilityConfig& sensor,
                                         const MapHealthConfig& config)
    : map_(map),
      grid_(map, 0.5 * expectation_limits(sensor, config).max_range),
      occluders_(map.occluders),
      sensor_(expectation_limits(sensor, config)),
      config_(config),
      reflector_matched_(map.reflectors.size(), 0) {
  for (size_t i = 0; i < map.reflectors.size(); ++i) index_of_id_[map.reflectors[i].id] = static_cast<int>(i);
}

// Fits map_T_laser to the scan's matches but the one at skip (-1: all); false when degenerate.
// rms: the fit's RMS residual over the matches used [m].
bool ScanEvidenceBuilder::fit(const std::vector<ReflectorDetection>& detections, const MatchResult& result,
                              int skip, Pose2& map_T_laser, double& rms) const {
  RigidFit2d rigid;
  for (size_t o = 0; o < result.matches.size(); ++o) {
    if (static_cast<int>(o) == skip) continue;
    rigid.add(detections[static_cast<size_t>(result.matches[o].detection_index)].laser_p_center,
              result.matches[o].map_p_center);
  }
  if (rigid.count() < 3 || !rigid.solve(map_T_laser)) return false;
  double sum2 = 0.0;
  for (size_t o = 0; o < result.matches.size(); ++o) {
    if (static_cast<int>(o) == skip) continue;
    const Eigen::Vector2d& laser_p =
        detections[static_cast<size_t>(result.matches[o].detection_index)].laser_p_center;
    sum2 += (map_T_laser * laser_p - result.matches[o].map_p_center).squaredNorm();
  }
  rms = std::sqrt(sum2 / rigid.count());
  return true;
}

void ScanEvidenceBuilder::add_sightings(const std::vector<ReflectorDetection>& detections,
                                        const MatchResult& result, ScanEvidence& out) {
  detection_matched_.assign(detections.size(), 0);
  // The pose the unmapped detections are placed with: the fit to all matches when they agree,
  // else the best fit leaving one out (a moved reflector), else none.
  Pose2 trusted;
  double trusted_rms = 0.0;
  bool have_trusted =
      fit(detections, result, -1, trusted, trusted_rms) && trusted_rms <= config_.consistent_fit_rms;
  for (size_t m = 0; m < result.matches.size(); ++m) {
    const ReflectorMatch& match = result.matches[m];
    const auto found = index_of_id_.find(match.map_id);
    if (found == index_of_id_.end()) continue;
    detection_matched_[static_cast<size_t>(match.detection_index)] = 1;
    reflector_matched_[static_cast<size_t>(found->second)] = 1;
    const ReflectorDetection& detection = detections[static_cast<size_t>(match.detection_index)];
    ReflectorSighting s;
    s.map_index = found->second;
    s.map_p = result.map_T_laser * detection.laser_p_center;
    // Measured from a pose fitted without this reflector (a moved one would pull the pose by
    // 1/n of its offset), and only when the others agree (no moved one among them).
    Pose2 without;
    double rms = 0.0;
    if (result.matches.size() >= 4 && fit(detections, result, static_cast<int>(m), without, rms) &&
        rms <= config_.consistent_fit_rms) {
      s.map_p = without * detection.laser_p_center;
      s.has_offset = detection.range <= sensor_.max_range;
      if (!have_trusted || rms < trusted_rms) trusted = without, trusted_rms = rms, have_trusted = true;
    }
    out.seen.push_back(s);
  }
  if (!have_trusted) return;
  for (size_t d = 0; d < detections.size(); ++d) {
    if (detection_matched_[d] || detections[d].range > sensor_.max_range) continue;
    const Eigen::Vector2d map_p = trusted * detections[d].laser_p_center;
    // A centre behind a wall or rack face seen from the laser is no cylinder: the circle fitted
    // to a flat bright strip on that face lies behind it.
    if (!occluders_.empty() && occluders_.blocks(trusted.translation(), map_p)) continue;
    out.unmapped.push_back(map_p);
  }
}

void ScanEvidenceBuilder::add_expected_unseen(const MatchResult& result, const LaserScan& scan,
                                              ScanEvidence& out) {
  predict_reflectors(map_, grid_, result.map_T_laser, sensor_, 0.0, scratch_, predicted_);
  for (size_t k = 0; k < predicted_.size(); ++k) {
    const PredictedReflector& p = predicted_[k];
    if (!p.in_view || reflector_matched_[static_cast<size_t>(p.map_index)] ||
        is_shadowed(map_, predicted_, k))
      continue;
    const double radius = map_.reflectors[static_cast<size_t>(p.map_index)].radius;
    if (line_of_sight_clear(scan, p.range, p.bearing, radius, config_.line_of_sight_tolerance))
      out.expected_unseen.push_back(p.map_index);
  }
}

void ScanEvidenceBuilder::build(int64_t utime, const std::vector<ReflectorDetection>& detections,
                                const MatchResult& result, const LaserScan* scan, ScanEvidence& out) {
  out.utime = utime;
  out.map_p_laser = result.map_T_laser.translation();
  out.seen.clear();
  out.unmapped.clear();
  out.expected_unseen.clear();
  add_sightings(detections, result, out);
  if (scan != nullptr) add_expected_unseen(result, *scan, out);
  for (const ReflectorSighting& s : out.seen) reflector_matched_[static_cast<size_t>(s.map_index)] = 0;
}

}  // namespace refloc
