#include "static_survey.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace refloc {
namespace {

// Largest standard deviation of a 2x2 covariance: the root of its largest eigenvalue [m].
double major_sigma(const Eigen::Matrix2d& c) {
  const double mean = 0.5 * (c(0, 0) + c(1, 1));
  return std::sqrt(std::max(0.0, mean + std::hypot(0.5 * (c(0, 0) - c(1, 1)), c(0, 1))));
}

}  // namespace

double integrated_autocorrelation_time(const std::vector<double>& series) {
  const size_t n = series.size();
  if (n < 4) return 1.0;
  double mean = 0.0;
  for (const double v : series) mean += v;
  mean /= static_cast<double>(n);
  const auto autocovariance = [&](size_t lag) {
    double sum = 0.0;
    for (size_t i = 0; i + lag < n; ++i) sum += (series[i] - mean) * (series[i + lag] - mean);
    return sum / static_cast<double>(n);
  };
  const double variance = autocovariance(0);
  if (!(variance > 0.0)) return 1.0;
  // Sokal's window: sum the autocorrelations up to the first lag M >= 5 tau(M); beyond it the
  // sum adds mostly noise (a fixed "until negative" rule overestimates tau of a drifting series).
  double tau = 1.0;
  for (size_t lag = 1; lag <= n / 2; ++lag) {
    tau += 2.0 * autocovariance(lag) / variance;
    if (static_cast<double>(lag) >= 5.0 * tau) break;
  }
  return std::max(1.0, tau);
}

StaticSurvey::StaticSurvey(StaticSurveyConfig config) : config_(config) {}

void StaticSurvey::add_scan(const std::vector<ReflectorDetection>& detections) {
  ++scans_;
  // Nearest pairs first, each track and each detection used once: two reflectors never share
  // a track, a reflector's detection never goes to a neighbour's track because it came first.
  std::vector<std::tuple<double, size_t, size_t>> pairs;
  for (size_t d = 0; d < detections.size(); ++d) {
    for (size_t t = 0; t < tracks_.size(); ++t) {
      const double distance = (detections[d].laser_p_center - tracks_[t].mean()).norm();
      if (distance <= config_.association_gate_m) pairs.emplace_back(distance, d, t);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<char> detection_used(detections.size(), 0);
  std::vector<char> track_used(tracks_.size(), 0);
  for (const auto& [distance, d, t] : pairs) {
    if (detection_used[d] || track_used[t]) continue;
    detection_used[d] = track_used[t] = 1;
    Track& track = tracks_[t];
    track.sum += detections[d].laser_p_center;
    track.detection_cov_sum += detections[d].covariance;
    track.centres.push_back(detections[d].laser_p_center);
  }
  for (size_t d = 0; d < detections.size(); ++d) {
    if (detection_used[d]) continue;
    Track track;
    track.sum = detections[d].laser_p_center;
    track.detection_cov_sum = detections[d].covariance;
    track.centres.push_back(detections[d].laser_p_center);
    tracks_.push_back(std::move(track));
  }
}

StaticSurveyReflector StaticSurvey::surveyed(const Track& track, const Pose2& map_T_laser) const {
  StaticSurveyReflector r;
  const size_t n = track.centres.size();
  r.times_seen = static_cast<int>(n);
  const Eigen::Vector2d mean = track.mean();
  const Eigen::Vector2d along = mean.normalized();  // line of sight
  const Eigen::Vector2d across(-along.y(), along.x());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  std::vector<double> radial, tangential;
  for (const Eigen::Vector2d& p : track.centres) {
    scatter += (p - mean) * (p - mean).transpose();
    radial.push_back(along.dot(p));
    tangential.push_back(across.dot(p));
  }
  r.laser_cov_scatter =
      n > 1 ? Eigen::Matrix2d(scatter / static_cast<double>(n - 1)) : Eigen::Matrix2d::Zero();
  r.autocorrelation_time =
      std::max(integrated_autocorrelation_time(radial), integrated_autocorrelation_time(tangential));
  r.laser_cov_statistical = r.laser_cov_scatter * r.autocorrelation_time / static_cast<double>(n);
  const double fraction = config_.scan_bias_fraction;
  r.laser_cov_floor = track.detection_cov_sum / static_cast<double>(n) * fraction * fraction;
  const double bias_sigma = config_.range_bias_sigma_m;
  r.laser_cov_range_bias = bias_sigma * bias_sigma * along * along.transpose();
  r.laser_p_center = mean - config_.range_bias_m * along;
  const Eigen::Matrix2d laser_cov = r.laser_cov_statistical + r.laser_cov_floor + r.laser_cov_range_bias;
  const Eigen::Matrix2d rotation = map_T_laser.rotation();
  r.map_p_center = map_T_laser * r.laser_p_center;
  r.map_cov_center = rotation * laser_cov * rotation.transpose();
  return r;
}

StaticSurveyResult StaticSurvey::finish(const Pose2& map_T_laser) const {
  StaticSurveyResult result;
  result.scans = scans_;
  const double needed = config_.min_seen_fraction * static_cast<double>(scans_);
  for (const Track& track : tracks_) {
    if (static_cast<double>(track.centres.size()) < needed || track.centres.size() < 2) {
      result.dropped_times_seen.push_back(static_cast<int>(track.centres.size()));
      continue;
    }
    result.reflectors.push_back(surveyed(track, map_T_laser));
  }
  std::sort(result.reflectors.begin(), result.reflectors.end(), [](const auto& a, const auto& b) {
    return std::atan2(a.laser_p_center.y(), a.laser_p_center.x()) <
           std::atan2(b.laser_p_center.y(), b.laser_p_center.x());
  });
  for (size_t i = 0; i < result.reflectors.size(); ++i) result.reflectors[i].id = static_cast<int>(i) + 1;
  return result;
}

ReflectorMap static_survey_map(const StaticSurveyResult& result, const std::string& map_id,
                               double reflector_radius_m) {
  ReflectorMap map;
  map.info = MapInfo{2, map_id, 1, iso8601_utc_now(), "surveyed"};
  for (const StaticSurveyReflector& s : result.reflectors) {
    MapReflector r;
    r.id = s.id;
    r.map_p_center = s.map_p_center;
    r.radius = reflector_radius_m;
    // The file holds one off-diagonal term: symmetric to the last bit.
    Eigen::Matrix2d cov = s.map_cov_center;
    cov(0, 1) = cov(1, 0) = 0.5 * (cov(0, 1) + cov(1, 0));
    r.map_cov_center = cov;
    map.reflectors.push_back(r);
  }
  return map;
}

std::string static_survey_report(const StaticSurveyResult& result) {
  std::string text = fmt::format(
      "{} scans, {} reflectors kept, {} tracks left out (seen in too few scans)\n"
      "  id      x_m      y_m  range_m  seen   tau  sigma_mm: scatter/scan  statistical  floor  range_bias  "
      "total\n",
      result.scans, result.reflectors.size(), result.dropped_times_seen.size());
  for (const StaticSurveyReflector& r : result.reflectors) {
    text += fmt::format(
        "  {:>2} {:>8.4f} {:>8.4f} {:>8.3f} {:>5} {:>5.2f}  {:>21.2f}  {:>11.3f}  {:>5.3f}  "
        "{:>10.3f}  {:>5.3f}\n",
        r.id, r.map_p_center.x(), r.map_p_center.y(), r.range_m(), r.times_seen, r.autocorrelation_time,
        1e3 * major_sigma(r.laser_cov_scatter), 1e3 * major_sigma(r.laser_cov_statistical),
        1e3 * major_sigma(r.laser_cov_floor), 1e3 * major_sigma(r.laser_cov_range_bias),
        1e3 * major_sigma(r.map_cov_center));
  }
  return text;
}

}  // namespace refloc
