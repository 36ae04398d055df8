#pragma once
// The survey's front end: landmark association from a cold start, with no map and no ids.
// Each scan's pose is dead-reckoned from odometry and corrected against the landmarks mapped
// so far and the candidates already seen consistently (the matcher's TrackingAssociator on
// them, then the pose solver's fit with its range bias filter), so odometry's drift (~0.8 m
// over the demo loop) never reaches the loop closure. Detections no landmark
// explains become candidates (LandmarkTrack), and a candidate becomes a landmark only by the
// PromotionRule. Its output is the batch adjustment's starting point and data association.

#include "drive_landmark_track.hpp"
#include "drive_scan.hpp"

#include "common/odometry_noise.hpp"
#include "common/se2.hpp"
#include "pose_solver/solver_config.hpp"
#include "reflector_matcher/matcher_config.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

struct LandmarkTrackerConfig {
  PromotionRule promotion;
  /// An unmatched detection within this of a candidate's mean is another sighting of it [m].
  double candidate_gate = 0.15;
  /// An unmatched detection this close to a landmark starts no candidate: it is that landmark
  /// seen with a poor pose, or something stuck to it [m].
  double landmark_exclusion = 0.3;
  /// A candidate counts as expected in a scan when in the field of view within this range [m]
  /// (the matcher's missed_penalty_max_range: farther ones may span too few beams).
  double expected_range = 8.0;
  /// Matched landmarks needed to correct the pose by the laser; fewer: dead reckoning [-].
  int min_matches = 3;
  /// A candidate seen this often, its centre within promotion.max_scatter, also corrects the
  /// pose (it is not mapped for that): the front end stays locked between promotions [-].
  int anchor_min_sightings = 3;
  SensorVisibilityConfig sensor;  ///< the matcher's defaults
  TrackingConfig tracking;
  RelocalizationConfig relocalization;
  SolverConfig solver;  ///< pose_solver's defaults, its range bias filter included
};

/// Per scan what the front end concluded.
struct TrackedScan {
  Pose2 map_T_robot;  ///< dead-reckoned, then corrected when laser_corrected
  bool laser_corrected = false;
  int matched = 0;  ///< detections associated with landmarks
};

struct TrackerResult {
  std::vector<TrackedScan> scans;         ///< one per DriveScan
  std::vector<LandmarkTrack> landmarks;   ///< promoted, in the order of promotion
  std::vector<LandmarkTrack> candidates;  ///< never promoted (distractors, rare sightings)
  /// Per scan, per detection: index into landmarks, or -1.
  std::vector<std::vector<int>> association;
  int scans_dead_reckoned = 0;  ///< without a laser correction
  /// The range offset the front end ended with (its tracks' positions are meant with it) [m].
  double range_bias = 0.0;
};

/// Run the front end over the whole drive; start: map_T_robot of the first scan.
TrackerResult track_landmarks(const std::vector<DriveScan>& scans, const Pose2& robot_T_laser,
                              const OdometryNoise& odometry_noise, const Pose2& start,
                              const LandmarkTrackerConfig& config);

}  // namespace refloc
