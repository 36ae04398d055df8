#pragma once
// The RSSI calibration behind refloc-calibrate-rssi, LCM-free: every echo beam labelled
// "on a detected reflector" or "anything else", the two RSSI distributions by range band,
// and an energy threshold recommended between them with its margins.

#include "common/reflector_detection.hpp"
#include "reflector_extractor/beam_table.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace refloc {

struct RssiSample {
  double range = 0.0;      ///< [m]
  double rssi_8bit = 0.0;  ///< [8-bit scale]
  bool on_reflector = false;
};

struct BeamLabelConfig {
  double radius = 0.06;        ///< reflector radius [m]
  double tolerance = 0.02;     ///< range noise allowance [m]
  double core_fraction = 0.6;  ///< a reflector beam passes within this fraction of the radius of the centre
};

/// Appends the echoes of table with RSSI to out, labelled against detections (laser frame):
/// on_reflector when the beam passes within core_fraction * radius of a centre and its point
/// lies within radius + tolerance of it; left out (neither class) when it passes the
/// reflector's silhouette otherwise at or behind it: partial edge hits and mixed pixels,
/// whose RSSI says how much of the spot hit the foil, not what the foil returns. Returns
/// how many were left out.
size_t label_beams(const BeamTable& table, const std::vector<ReflectorDetection>& detections,
                   const BeamLabelConfig& config, std::vector<RssiSample>& out);

/// Linearly interpolated percentile q in [0, 100] of sorted values; 0 when empty.
double percentile(const std::vector<double>& sorted, double q);

struct RssiDistribution {
  size_t count = 0;
  double p1 = 0.0, p50 = 0.0, p99 = 0.0, p999 = 0.0, min = 0.0, max = 0.0;  ///< [8-bit scale]
};
RssiDistribution describe(std::vector<double> values);

struct RssiBand {
  double range_min = 0.0, range_max = 0.0;  ///< [m), +inf for the last
  RssiDistribution reflector, other;
};

/// Between the 99.9th percentile of the other beams and the 1st of the reflector beams.
struct ThresholdRecommendation {
  bool have_both = false;  ///< reflector and other beams were seen
  bool separable = false;  ///< other_p999 < reflector_p1
  double other_p999 = 0.0;
  double reflector_p1 = 0.0;
  double threshold = 0.0;     ///< the midpoint when separable, else reflector_p1 [8-bit]
  double margin_below = 0.0;  ///< threshold - other_p999
  double margin_above = 0.0;  ///< reflector_p1 - threshold
};

struct RssiCalibration {
  RssiDistribution reflector, other;  ///< all ranges
  std::vector<RssiBand> bands;
  ThresholdRecommendation recommendation;
};

/// What a threshold [8-bit] does to the samples: the share of reflector beams below it (lost)
/// and of other beams at or above it (let into clustering).
struct ThresholdShares {
  double reflector_below = 0.0;
  double other_at_or_above = 0.0;
};
ThresholdShares shares_at(const std::vector<RssiSample>& samples, double threshold_8bit);

/// band_edges: increasing range limits [m]; bands [0, e0), [e0, e1), ..., [e_last, inf).
RssiCalibration calibrate_rssi(const std::vector<RssiSample>& samples, const std::vector<double>& band_edges);

/// An SVG: both RSSI histograms (log counts, bins of 5) with the percentiles and the
/// recommended threshold marked.
std::string rssi_histogram_svg(const std::vector<RssiSample>& samples, const RssiCalibration& calibration);

}  // namespace refloc
