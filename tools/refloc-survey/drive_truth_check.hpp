#pragma once
// Simulation only (a log with GROUND_TRUTH and the world's true map): the survey's detections
// measured against the truth at the true poses, to tell the survey's own errors from the ones
// its input already has. Two numbers answer "could any batch do better with these detections?":
// the range error's slope over range (a slope s maps the hall s too large: the map's scale is
// set by the ranges, the range offset only absorbs a constant) and, per reflector, the weighted
// mean of its detections' errors at the true poses (what a perfect trajectory would map).

#include "drive_map_comparison.hpp"
#include "drive_survey.hpp"

#include "calibration_pairs.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace refloc {

struct DetectionTruthCheck {
  int detections = 0;             ///< surveyed detections of reflectors paired with the truth
  double range_error_offset = 0;  ///< weighted fit: range error = offset + slope * range [m]
  double range_error_slope = 0;   ///< [m per m]
  double across_error_mean = 0;   ///< across the line of sight, + = counter-clockwise [m]
  struct Reflector {
    int map_id = 0;
    Eigen::Vector2d mean_error = Eigen::Vector2d::Zero();  ///< map frame [m]
  };
  std::vector<Reflector> reflectors;
  double mean_error_rms =
      0;  ///< RMS over reflectors of |mean_error| (the surveyed range offset taken off) [m]
};

/// truth: the true map_T_robot series (sorted); comparison pairs surveyed ids with true ones.
DetectionTruthCheck check_detections_against_truth(const DriveSurveyResult& survey,
                                                   const std::vector<TimedPose>& truth,
                                                   const MapComparison& comparison,
                                                   const Pose2& robot_T_laser);

std::string truth_check_text(const DetectionTruthCheck& check);

}  // namespace refloc
