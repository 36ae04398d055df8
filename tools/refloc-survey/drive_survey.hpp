#pragma once
// The driving survey as one library call: the front end's association (drive_landmark_tracker),
// the batch adjustment (drive_bundle_adjustment), the checks of every landmark against its own
// residuals, spacing and visibility behind the traced walls (drive_landmark_checks: a
// distractor that slipped through is dropped, a reflector mapped twice merged, then solved
// again), the frame (start pose, or anchors), the final covariances and the occluders.
// refloc-survey drive and the tests run this on DriveScans from a log or from the renderer.

#include "drive_bundle_adjustment.hpp"
#include "drive_landmark_checks.hpp"
#include "drive_landmark_tracker.hpp"
#include "drive_occluders.hpp"
#include "drive_scan.hpp"

#include "common/odometry_noise.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace refloc {

/// A reflector whose map coordinates the user knows: the surveyed reflector nearest to near
/// (in the survey's own frame, the one --start-pose defines) is held at map_p and gets id.
struct SurveyAnchor {
  int id = 0;
  Eigen::Vector2d map_p = Eigen::Vector2d::Zero();  ///< [m]
  Eigen::Vector2d near = Eigen::Vector2d::Zero();   ///< [m]
};

struct DriveSurveyConfig {
  LandmarkTrackerConfig tracker;
  BundleOptions bundle;
  LandmarkCheckConfig checks;
  OccluderConfig occluders;
  /// An anchor's nearest surveyed reflector must lie within this of its near point [m].
  double anchor_gate = 0.5;
  /// Without anchors the map's scale comes from the ranges alone, and the range offset and the
  /// scale are told apart only by the spread of ranges: a systematic scale error of this std dev
  /// is added to each reflector's covariance along its line from the map's centroid (measured on
  /// simulated demo and sideways drives: -30..+313 ppm, RMS 166 ppm over 12) [1e-6]. 0: none.
  double scale_sigma_ppm = 200.0;
};

struct SurveyedReflector {
  int id = 0;
  Eigen::Vector2d map_p = Eigen::Vector2d::Zero();  ///< [m]
  /// [m^2]; zero for an anchor. Frame-free (BundleLandmark::frame_free_covariance) when the
  /// batch could compute it, else with the frame's uncertainty (anchors, very large maps).
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  /// With the uncertainty of the frame (the held first pose) in it [m^2].
  Eigen::Matrix2d frame_covariance = Eigen::Matrix2d::Zero();
  bool anchor = false;
  int times_seen = 0;       ///< detections used
  int scans_expected = 0;   ///< scans that should have seen it (drive_visibility)
  int scans_seen = 0;       ///< of those, scans that did
  double residual_rms = 0;  ///< [m]
  double normalised_rms = 0;
  double view_span = 0;          ///< [rad]
  double front_end_scatter = 0;  ///< [m]
  /// Its centre in front of the nearest traced surface (drive_landmark_checks) [m]; NaN: none near.
  double surface_clearance = 0;
};

/// Something bright the survey did not map, and why.
struct RejectedTrack {
  Eigen::Vector2d map_p = Eigen::Vector2d::Zero();  ///< in the final frame [m]
  int times_seen = 0;
  double view_span = 0;  ///< [rad]
  double scatter = 0;    ///< [m]
  double seen_fraction = 0;
  std::string reason;
};

/// One detection the final batch used, with its residual there (the report's observations.csv).
struct SurveyObservation {
  int scan = -1;
  int reflector_id = 0;
  ReflectorDetection detection;
  Eigen::Vector2d residual = Eigen::Vector2d::Zero();  ///< laser_p - predicted, laser frame [m]
};

struct DriveSurveyResult {
  std::vector<SurveyedReflector> reflectors;
  std::vector<SurveyObservation> observations;
  std::vector<MapOccluder> occluders;  ///< traced at the final poses
  std::vector<RejectedTrack> rejected;
  std::vector<Pose2> map_T_robot;               ///< every scan after the batch
  std::vector<Pose2> front_end_map_T_robot;     ///< every scan from the front end (same frame before anchors)
  std::vector<int64_t> utime;                   ///< of every scan [us]
  double range_bias = 0, range_bias_sigma = 0;  ///< [m]
  double chi2_per_dof = 0;
  int scans = 0, scans_dead_reckoned = 0, observations_used = 0, batch_runs = 0;
  double front_end_s = 0, batch_s = 0, covariance_s = 0;  ///< wall times [s]
  std::string batch_message;
  std::vector<std::string> warnings;  ///< one line each, for the user
};

/// Throws ConfigError when an anchor has no surveyed reflector within anchor_gate, or fewer
/// than 2 anchors are given (0 is fine: the start pose fixes the frame).
DriveSurveyResult run_drive_survey(const std::vector<DriveScan>& scans, const Pose2& robot_T_laser,
                                   const OdometryNoise& odometry_noise, const Pose2& start,
                                   const std::vector<SurveyAnchor>& anchors, const DriveSurveyConfig& config);

}  // namespace refloc
