#pragma once
// ReflectorExtractor: one LaserScan in, the retro-reflector cylinders it sees out
// (centres in the laser frame with covariance). Composes energy screening, adaptive
// breakpoint clustering, a circle fit and a roundness test, in one of two modes:
//  - kPaper:   the paper's §3.2-3.4 (centre fitted with the designed radius, which the paper leaves
//              open; d-bar under the calibrated line);
//  - kDefault: known-radius Gauss-Newton fit with covariance and a stricter roundness test.

#include "common/laser_scan.hpp"
#include "common/reflector_detection.hpp"
#include "reflector_extractor/adaptive_breakpoint.hpp"
#include "reflector_extractor/beam_table.hpp"
#include "reflector_extractor/circle_fit.hpp"
#include "reflector_extractor/paper_centre.hpp"
#include "reflector_extractor/roundness.hpp"

#include <cstdint>
#include <vector>

namespace refloc {

struct ExtractorConfig {
  enum class Mode { kDefault, kPaper };
  Mode mode = Mode::kDefault;

  double energy_threshold_8bit = 180.0;  ///< paper §3.2 [RSSI on the 8-bit scale]
  AdaptiveBreakpointConfig clustering;   ///< lambda 10 deg, sigma_r 0.012 m (also the fit's range noise)
  double reflector_radius = 0.06;        ///< known cylinder radius [m]
  /// Smaller clusters are not reflectors. 1 keeps far reflectors (one bright beam beyond
  /// ~7 m on the LMS100) at the price of no shape test for them.
  int min_beams = 2;

  // Paper mode (§3.3-3.4).
  int paper_drop_points = 1;  ///< first and last n points left out of d-bar (and of the polar C_r)
  /// How the centre (C_r, C_theta) is read from a cluster; the paper leaves it open. The
  /// designed radius held fixed: 10.4 / 6.1 mm mean max error on the Table 1 protocol against
  /// 42.3 / 19.7 mm with the free algebraic circle (extractor README, "Modes").
  PaperCentreReading paper_centre = PaperCentreReading::kKnownRadius;
  RoundnessLine paper_roundness;

  // Default mode.
  KnownRadiusFitConfig fit;
  KnownRadiusRoundnessConfig roundness;
  /// Bearing noise of a beam [rad]: adds (range * angle_sigma)^2 across the line of sight.
  double angle_sigma = 0.002;
  /// An edge beam whose RSSI is below this fraction of the cluster's brightest is a partial
  /// hit (beam straddling the reflector's edge, mixed range): dropped from the fit.
  double edge_rssi_ratio = 0.6;
  /// A neighbour beam closer than the cluster's edge by this much hides part of the
  /// reflector, which would bias the centre sideways [m].
  double occlusion_margin = 0.1;
  bool reject_occluded = true;
  /// A dazzled neighbour (sensor code 1) may be the rest of the reflector.
  bool reject_next_to_dazzled = true;

  /// The paper's method with the paper's parameters.
  static ExtractorConfig paper();
};

/// config with the corrections that make a long average of detections unbiased (a map from
/// thousands of sightings: refloc-survey drive), at a small cost in single-scan variance: the
/// wall behind a reflector in the spot model and the fit's second-order bias removed. Demo hall,
/// rendered scans: mean radial error -0.2..-1.7 mm at 1.5-6 m without them, -0.3..+0.04 mm with.
ExtractorConfig mapping_corrections(ExtractorConfig config);

/// What became of one cluster of bright beams (REFLECTOR_CLUSTERS says it per cluster).
enum class ClusterOutcome : uint8_t {
  kAccepted,
  kTooFewBeams,
  kTooWide,
  kTooNarrow,
  kNotRound,  ///< residual, d-bar or flat-surface test
  kRadius,
  kOccluded,  ///< occluded or next to a dazzled beam
  kFitFailed,
};
const char* cluster_outcome_name(ClusterOutcome outcome);  ///< "accepted", "too_few_beams", ...

/// One cluster of bright beams as the extractor judged it.
struct ClusterRecord {
  int first_beam = 0;
  int last_beam = 0;
  int num_beams = 0;  ///< bright beams in it
  ClusterOutcome outcome = ClusterOutcome::kAccepted;
  double range = 0.0;          ///< mean range of its bright beams [m]
  double bearing = 0.0;        ///< of its middle beam, laser frame [rad]
  double max_rssi_8bit = 0.0;  ///< its brightest beam [8-bit scale]
};

/// Counts of one scan's clusters by fate.
struct ExtractionStats {
  int clusters_considered = 0;  ///< high-energy clusters
  int rejected_too_few_beams = 0;
  int rejected_too_wide = 0;
  int rejected_too_narrow = 0;  ///< bright patch far narrower than the diameter up close
  int rejected_not_round = 0;   ///< residual or d-bar test
  int rejected_radius = 0;      ///< free-fit radius far from the known radius
  int rejected_occluded = 0;    ///< occluded or next to a dazzled beam
  int rejected_fit_failed = 0;
  int rejected() const {
    return rejected_too_few_beams + rejected_too_wide + rejected_too_narrow + rejected_not_round +
           rejected_radius + rejected_occluded + rejected_fit_failed;
  }
  void count(ClusterOutcome outcome);
};

class ReflectorExtractor {
 public:
  explicit ReflectorExtractor(ExtractorConfig config = {});

  /// Detections in scan (a 16-bit RSSI channel read on rssi_scale), in beam order; the
  /// reference stays valid until the next call. No allocation once the internal buffers have
  /// grown to the largest scan seen.
  const std::vector<ReflectorDetection>& extract(const LaserScan& scan,
                                                 RssiScale rssi_scale = RssiScale::kNative);
  /// The same from a scan already read into a beam table.
  const std::vector<ReflectorDetection>& extract(const BeamTable& table);

  const ExtractionStats& stats() const { return stats_; }
  /// Every bright cluster of the last scan, in beam order, with its outcome; the accepted ones
  /// are the detections, in the same order.
  const std::vector<ClusterRecord>& clusters() const { return records_; }
  const ExtractorConfig& config() const { return config_; }

 private:
  void gather_beams(const BeamTable& table, const BeamCluster& cluster);
  bool occluded(const BeamTable& table, const BeamCluster& cluster) const;
  ClusterOutcome process_cluster_paper(const BeamTable& table, const BeamCluster& cluster);
  ClusterOutcome process_cluster_default(const BeamTable& table, const BeamCluster& cluster);
  ClusterRecord describe(const BeamTable& table, const BeamCluster& cluster) const;
  void emit(const BeamTable& table, const BeamCluster& cluster, const CircleFit& fit, double roundness,
            double fitted_radius);

  ExtractorConfig config_;
  AdaptiveBreakpointClusterer clusterer_;
  ExtractionStats stats_;
  BeamTable table_;
  std::vector<uint8_t> high_energy_;
  std::vector<BeamCluster> clusters_;
  std::vector<FitBeam> beams_;
  std::vector<double> beam_rssi_;
  std::vector<ReflectorDetection> detections_;
  std::vector<ClusterRecord> records_;
};

}  // namespace refloc
