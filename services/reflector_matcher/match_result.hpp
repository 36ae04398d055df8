#pragma once
// What the matcher says about one scan: which detections are which map
// reflectors, how sure it is, and the map_T_laser hypothesis behind it.

#include "common/reflector_detection.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

/// Same meaning as reflector_matches_t::STATUS_*.
enum class MatchStatus { kOk = 0, kAmbiguous = 1, kLost = 2 };
/// Same meaning as reflector_matches_t::MODE_*.
enum class MatchMode { kTracking = 0, kGlobal = 1 };

/// A prior for map_T_laser, e.g. the fused robot pose composed with the laser mount.
struct PosePrior {
  Pose2 map_T_laser;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< of (x, y, theta) [m^2, m rad, rad^2]
};

struct MatchResult {
  MatchStatus status = MatchStatus::kLost;
  MatchMode mode = MatchMode::kGlobal;
  std::vector<ReflectorMatch> matches;
  double hypothesis_score = 0.0;  ///< support of the chosen hypothesis (matched minus penalties)
  double runner_up_score = 0.0;   ///< best hypothesis that is a substantially different pose
  Pose2 runner_up_map_T_laser;    ///< that hypothesis (global relocalization only; refloc-plan)
  Pose2 map_T_laser;              ///< hypothesis the matches were verified against
  int ndetections = 0;
};

}  // namespace refloc
