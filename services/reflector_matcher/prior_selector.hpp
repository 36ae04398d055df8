#pragma once
// Which prior the matcher tracks from, per scan:
//  1. none during the startup window (StartupRelocalization: relocalize on its own first);
//  2. the fused POSE when its status is OK and it is fresh (|POSE utime - scan utime| <=
//     max_age), map_T_robot composed with the mount and its covariance propagated through it.
//     Which POSE: the newest stamped at or before the scan (else the earliest after it), not
//     the last to arrive: REFLECTORS reach the matcher after the extractor's work, POSE straight
//     from fusion or a log, so the last arrival depends on timing and a replay of the same log
//     would track from different priors;
//  3. else the matcher's own last OK map_T_laser when fresh, with the configured sigmas;
//  4. else none (global relocalization).
// Before all of these, an INITIAL_POSE (a user's "the robot is here", e.g. from the web
// console): for initial_pose_hold_s of scans it is the prior, with its own covariance. Its
// matches are verified against the whole scan like any prior's, so a wrong one is never
// confirmed: it expires. Once a scan matches OK from it, the matcher tracks from its own poses
// for initial_pose_hold_s more, so that a fused POSE still on the old (wrong) pose cannot pull it
// back while pose_fusion refuses the new matches and restarts from the new fixes.

#include "reflector_matcher/match_result.hpp"
#include "reflector_matcher/startup_relocalization.hpp"

#include "common/se2.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <deque>
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
  /// initial_pose_hold_s: an INITIAL_POSE is the prior for this long from the first scan after
  /// it; after its first OK scan the own poses are preferred to POSE for as long [s].
  double initial_pose_hold = 3.0;
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

enum class PriorSource { kNone, kStartupWindow, kFusedPose, kOwnPose, kInitialPose };
/// What became of an INITIAL_POSE, said once.
enum class InitialPoseEvent { kNone, kConfirmed, kExpired };
enum class StartupEvent { kNone, kRelocalized, kGaveUp };

struct PriorChoice {
  PriorSource source = PriorSource::kNone;
  std::optional<PosePrior> prior;
};

class PriorSelector {
 public:
  PriorSelector(const PriorSelectionConfig& config, const Pose2& robot_T_laser);

  void on_pose(const FusedPose& pose);
  /// A user's pose (status ignored; its covariance taken as given, the matcher's floors apply).
  void on_initial_pose(const FusedPose& pose) {
    initial_ = pose;
    initial_first_scan_utime_.reset();
  }
  /// The prior for the scan at scan_utime [us]; call on_result with its match next.
  PriorChoice select(int64_t scan_utime);
  /// The scan's result: ends the startup window, remembers an OK pose.
  StartupEvent on_result(int64_t scan_utime, const MatchResult& result);
  /// Set by select() (expired) or on_result() (confirmed); kNone after it was read.
  InitialPoseEvent take_initial_pose_event() {
    const InitialPoseEvent e = initial_event_;
    initial_event_ = InitialPoseEvent::kNone;
    return e;
  }

 private:
  /// The own last OK pose with the configured sigmas (last_own_ok_ must be set).
  PriorChoice own_pose_prior() const;
  /// Of the recent POSE, the newest stamped at or before scan_utime, else the earliest; null if none.
  const FusedPose* pose_for_scan(int64_t scan_utime) const;
  /// POSE come at up to 100 Hz; prior_max_age_s is 0.5 s by default: room for 0.64 s of them.
  static constexpr size_t kRecentPoses = 64;

  PriorSelectionConfig config_;
  Pose2 robot_T_laser_;
  int64_t max_age_us_;
  StartupRelocalization startup_;
  bool startup_was_done_ = false;
  std::deque<FusedPose> recent_poses_;                    ///< in arrival order, at most kRecentPoses
  std::optional<std::pair<int64_t, Pose2>> last_own_ok_;  ///< scan utime, map_T_laser
  std::optional<FusedPose> initial_;
  std::optional<int64_t> initial_first_scan_utime_;
  int64_t own_preferred_until_utime_ = 0;  ///< after a confirmed INITIAL_POSE
  PriorSource last_source_ = PriorSource::kNone;
  InitialPoseEvent initial_event_ = InitialPoseEvent::kNone;
};

}  // namespace refloc
