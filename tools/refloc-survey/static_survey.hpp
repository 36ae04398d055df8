#pragma once
// refloc-survey static: the reflectors around a robot standing still, from N scans' detections
// (the extractor's, in the laser frame). Detections are associated across scans by position
// (nearest track mean within a gate), reflectors seen in at least a fraction of the scans are
// kept, their centres averaged and moved into the map frame through map_T_robot * robot_T_laser.
//
// Each centre's covariance is the sum of
//  - the statistical part: the scatter of the per-scan centres / N_eff, where N_eff = N / tau
//    and tau is the integrated autocorrelation time of the per-scan series (slow drift makes
//    successive scans agree and 1/N too optimistic; tau measures it, >= 1);
//  - a floor for what averaging from one pose cannot remove: the same beams hit the same spots
//    of the cylinder in every scan, so the fit's bias from beam placement, edge beams and
//    millimetre quantization repeats; it is taken as a fraction of one scan's own centre
//    covariance (the extractor's), measured on rendered scans (tools/refloc-survey/README.md);
//  - the systematic range error the user states (mean subtracted along the line of sight,
//    its sigma along the line of sight): from one pose it is indistinguishable from the
//    reflectors standing farther out, and it is common to all reflectors.

#include "common/reflector_detection.hpp"
#include "common/reflector_map.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace refloc {

struct StaticSurveyConfig {
  /// A detection within this of a reflector's mean centre so far is that reflector [m]; two
  /// reflectors stand at least 2 r + 1 cm = 13 cm apart, one reflector's scatter is millimetres.
  double association_gate_m = 0.05;
  /// Reflectors seen in fewer than this fraction of the scans are left out (a glint, a far
  /// reflector at the detection limit, something moving through) [-].
  double min_seen_fraction = 0.8;
  /// Per-pose fit bias floor: this fraction of one scan's centre sigma stays after averaging [-].
  double scan_bias_fraction = 0.2;
  /// The sensor's systematic range error, measured - true [m] (LMS100: +-30 mm typical);
  /// subtracted along each reflector's line of sight.
  double range_bias_m = 0.0;
  /// Its uncertainty [m]; 0: known exactly. Default 30 mm: the LMS100's typical systematic
  /// error, also pose_solver's prior sigma for it; state a measured one (README).
  double range_bias_sigma_m = 0.03;
};

/// One reflector as surveyed.
struct StaticSurveyReflector {
  int id = 0;                             ///< 1.. in order of bearing, right to left
  int times_seen = 0;                     ///< scans with a detection associated
  Eigen::Vector2d laser_p_center;         ///< mean centre, range bias removed [m]
  Eigen::Vector2d map_p_center;           ///< the same in the map frame [m]
  Eigen::Matrix2d map_cov_center;         ///< total covariance in the map frame [m^2]
  Eigen::Matrix2d laser_cov_scatter;      ///< scatter of the per-scan centres (one scan) [m^2]
  Eigen::Matrix2d laser_cov_statistical;  ///< scatter * tau / N [m^2]
  Eigen::Matrix2d laser_cov_floor;        ///< scan_bias_fraction^2 * one scan's covariance [m^2]
  Eigen::Matrix2d laser_cov_range_bias;   ///< range_bias_sigma^2 along the line of sight [m^2]
  double autocorrelation_time = 1.0;      ///< tau [scans], >= 1
  double range_m() const { return laser_p_center.norm(); }
};

struct StaticSurveyResult {
  int scans = 0;  ///< scans added
  std::vector<StaticSurveyReflector> reflectors;
  /// Tracks left out: seen in fewer than min_seen_fraction of the scans (times seen each).
  std::vector<int> dropped_times_seen;
};

/// Accumulates scans' detections; finish() surveys.
class StaticSurvey {
 public:
  explicit StaticSurvey(StaticSurveyConfig config = {});

  /// One scan's detections in the laser frame (an empty scan counts: it saw nothing).
  void add_scan(const std::vector<ReflectorDetection>& detections);
  int scans() const { return scans_; }

  /// The reflectors kept, in the map frame given by map_T_laser (= map_T_robot * robot_T_laser).
  StaticSurveyResult finish(const Pose2& map_T_laser) const;

 private:
  struct Track {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    Eigen::Matrix2d detection_cov_sum = Eigen::Matrix2d::Zero();
    std::vector<Eigen::Vector2d> centres;  ///< per scan, in scan order
    Eigen::Vector2d mean() const { return sum / static_cast<double>(centres.size()); }
  };
  StaticSurveyReflector surveyed(const Track& track, const Pose2& map_T_laser) const;

  StaticSurveyConfig config_;
  int scans_ = 0;
  std::vector<Track> tracks_;
};

/// Integrated autocorrelation time of a series (1 + 2 sum of its autocorrelations up to Sokal's
/// window, the first lag M >= 5 tau(M)), at least 1: the factor by which it carries fewer
/// independent samples than its length.
double integrated_autocorrelation_time(const std::vector<double>& series);

/// The survey as a format-2 map: source "surveyed", version 1, created now, each reflector's
/// total covariance, radius reflector_radius_m.
ReflectorMap static_survey_map(const StaticSurveyResult& result, const std::string& map_id,
                               double reflector_radius_m);

/// The per-reflector table refloc-survey static prints: id, map x y, range, seen, sigmas.
std::string static_survey_report(const StaticSurveyResult& result);

}  // namespace refloc
