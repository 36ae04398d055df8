#include "rssi_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace refloc {

size_t label_beams(const BeamTable& table, const std::vector<ReflectorDetection>& detections,
                   const BeamLabelConfig& config, std::vector<RssiSample>& out) {
  if (!table.has_rssi) return 0;
  const double reach = config.radius + config.tolerance;
  size_t left_out = 0;
  for (const TableBeam& b : table.beams) {
    if (b.kind != BeamKind::kEcho) continue;
    bool core = false, silhouette = false;
    for (const ReflectorDetection& d : detections) {
      const Eigen::Vector2d& c = d.laser_p_center;
      const double lateral = std::abs(b.direction.x() * c.y() - b.direction.y() * c.x());
      const double along = b.direction.dot(c);
      if (lateral > reach || b.range < along - reach) continue;
      silhouette = true;
      core = core || (lateral <= config.core_fraction * config.radius && (b.point - c).norm() <= reach);
    }
    if (silhouette && !core) {
      ++left_out;
      continue;
    }
    out.push_back({b.range, b.rssi_8bit, core});
  }
  return left_out;
}

double percentile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0.0;
  const double position = std::clamp(q, 0.0, 100.0) / 100.0 * static_cast<double>(sorted.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(position));
  const size_t above = std::min(below + 1, sorted.size() - 1);
  const double t = position - static_cast<double>(below);
  return sorted[below] + t * (sorted[above] - sorted[below]);
}

RssiDistribution describe(std::vector<double> values) {
  RssiDistribution d;
  d.count = values.size();
  if (values.empty()) return d;
  std::sort(values.begin(), values.end());
  d.p1 = percentile(values, 1.0);
  d.p50 = percentile(values, 50.0);
  d.p99 = percentile(values, 99.0);
  d.p999 = percentile(values, 99.9);
  d.min = values.front();
  d.max = values.back();
  return d;
}

namespace {

void split(const std::vector<RssiSample>& samples, double range_min, double range_max,
           RssiDistribution& reflector, RssiDistribution& other) {
  std::vector<double> on, off;
  for (const RssiSample& s : samples) {
    if (s.range < range_min || s.range >= range_max) continue;
    (s.on_reflector ? on : off).push_back(s.rssi_8bit);
  }
  reflector = describe(std::move(on));
  other = describe(std::move(off));
}

}  // namespace

ThresholdShares shares_at(const std::vector<RssiSample>& samples, double threshold_8bit) {
  size_t reflector = 0, below = 0, other = 0, above = 0;
  for (const RssiSample& s : samples) {
    if (s.on_reflector) {
      ++reflector;
      below += s.rssi_8bit < threshold_8bit ? 1 : 0;
    } else {
      ++other;
      above += s.rssi_8bit >= threshold_8bit ? 1 : 0;
    }
  }
  ThresholdShares shares;
  if (reflector > 0) shares.reflector_below = static_cast<double>(below) / static_cast<double>(reflector);
  if (other > 0) shares.other_at_or_above = static_cast<double>(above) / static_cast<double>(other);
  return shares;
}

RssiCalibration calibrate_rssi(const std::vector<RssiSample>& samples,
                               const std::vector<double>& band_edges) {
  RssiCalibration c;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  split(samples, 0.0, kInf, c.reflector, c.other);
  double lower = 0.0;
  for (size_t i = 0; i <= band_edges.size(); ++i) {
    RssiBand band;
    band.range_min = lower;
    band.range_max = i < band_edges.size() ? band_edges[i] : kInf;
    split(samples, band.range_min, band.range_max, band.reflector, band.other);
    c.bands.push_back(band);
    lower = band.range_max;
  }
  ThresholdRecommendation& r = c.recommendation;
  r.have_both = c.reflector.count > 0 && c.other.count > 0;
  if (!r.have_both) return c;
  r.other_p999 = c.other.p999;
  r.reflector_p1 = c.reflector.p1;
  r.separable = r.other_p999 < r.reflector_p1;
  r.threshold = r.separable ? 0.5 * (r.other_p999 + r.reflector_p1) : r.reflector_p1;
  r.margin_below = r.threshold - r.other_p999;
  r.margin_above = r.reflector_p1 - r.threshold;
  return c;
}

}  // namespace refloc
