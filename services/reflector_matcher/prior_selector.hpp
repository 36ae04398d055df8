#pragma once
// Which prior the matcher tracks from, per scan:
//  1. none during the startup window (StartupRelocalization: relocalize on its own first);
//  2. the fused POSE when its status is OK and it is fresh (|POSE utime - scan utime| <=
//     max_age), map_T_robot composed with the mount and its covariance propagated through it;
//  3. else the matcher's own last OK map_T_laser when fresh, with the configured sigmas;
//  4. else none (global relocalization).

#include "reflector_matcher/match_result.hpp"
#include "reflector_matcher/startup_relocalization.hpp"

#include "common/se2.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <optional>

namespace refloc {

/// The top-level prior keys of reflector_matcher.json.
struct PriorSelectionConfig {
  double max_age = 0.5;  ///< prior_max_age_s: a POSE or own pose older than this vs the scan is unused [s]
  bool use_own_pose = true;   ///< use_own_pose_as_prior: track from the last OK match when no POSE is fresh
  double own_sigma_xy = 0.3;  ///< own_prior_sigma_m: std dev assumed for the own previous pose [m]
  double own_sigma_theta = 5.0 * M_PI / 180.0;  ///< own_prior_sigma_deg [rad]
  /// relocalize_on_start_s: after start, ignore priors until a global relocalization is OK,
  /// for at most this long (StartupRelocalization); 0 = track from POSE at once [s].
  double relocalize_on_start = 2.0;
};

/// The fused robot pose (POSE) as the matcher receives it.
struct FusedPose {
  int64_t utime = 0;  ///< [us]
  Pose2 map_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< may be non-finite [m^2, m rad, rad^2]
  bool ok = false;                                       ///< status OK
};

/// map_T_laser prior from a fused map_T_robot: the covariance goes through the mount's
/// Jacobian (the lever arm turns heading error into position error); a non-finite one
/// becomes zero, so the matcher's floors take over.
PosePrior prior_from_robot_pose(const FusedPose& pose, const Pose2& robot_T_laser);

enum class PriorSource { kNone, kStartupWindow, kFusedPose, kOwnPose };
enum class StartupEvent { kNone, kRelocalized, kGaveUp };

struct PriorChoice {
  PriorSource source = PriorSource::kNone;
  std::optional<PosePrior> prior;
};

class PriorSelector {
 public:
  PriorSelector(const PriorSelectionConfig& config, const Pose2& robot_T_laser);

  void on_pose(const FusedPose& pose) { last_pose_ = pose; }
  /// The prior for the scan at scan_utime [us]; call on_result with its match next.
  PriorChoice select(int64_t scan_utime);
  /// The scan's result: ends the startup window, remembers an OK pose.
  StartupEvent on_result(int64_t scan_utime, const MatchResult& result);

 private:
  PriorSelectionConfig config_;
  Pose2 robot_T_laser_;
  int64_t max_age_us_;
  StartupRelocalization startup_;
  bool startup_was_done_ = false;
  std::optional<FusedPose> last_pose_;
  std::optional<std::pair<int64_t, Pose2>> last_own_ok_;  ///< scan utime, map_T_laser
};

}  // namespace refloc
