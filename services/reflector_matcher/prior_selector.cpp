#include "reflector_matcher/prior_selector.hpp"

#include "common/covariance_propagation.hpp"

#include <cstdlib>

namespace refloc {

PosePrior prior_from_robot_pose(const FusedPose& pose, const Pose2& robot_T_laser) {
  Eigen::Matrix3d robot_cov = pose.covariance;
  if (!robot_cov.allFinite()) robot_cov.setZero();  // the matcher's floors take over
  return PosePrior{pose.map_T_robot * robot_T_laser,
                   propagate_through_mount(pose.map_T_robot, robot_cov, robot_T_laser)};
}

PriorSelector::PriorSelector(const PriorSelectionConfig& config, const Pose2& robot_T_laser)
    : config_(config),
      robot_T_laser_(robot_T_laser),
      max_age_us_(static_cast<int64_t>(config.max_age * 1e6)),
      startup_(config.relocalize_on_start) {}

PriorChoice PriorSelector::own_pose_prior() const {
  const double sxy2 = config_.own_sigma_xy * config_.own_sigma_xy;
  const double st2 = config_.own_sigma_theta * config_.own_sigma_theta;
  return {PriorSource::kOwnPose,
          PosePrior{last_own_ok_->second, Eigen::Vector3d(sxy2, sxy2, st2).asDiagonal()}};
}

void PriorSelector::on_pose(const FusedPose& pose) {
  recent_poses_.push_back(pose);
  if (recent_poses_.size() > kRecentPoses) recent_poses_.pop_front();
}

const FusedPose* PriorSelector::pose_for_scan(int64_t scan_utime) const {
  const FusedPose* before = nullptr;
  const FusedPose* earliest = nullptr;
  for (const FusedPose& p : recent_poses_) {
    if (p.utime <= scan_utime && (before == nullptr || p.utime >= before->utime)) before = &p;
    if (earliest == nullptr || p.utime < earliest->utime) earliest = &p;
  }
  return before != nullptr ? before : earliest;
}

PriorChoice PriorSelector::select(int64_t scan_utime) {
  startup_was_done_ = startup_.done();
  PriorChoice choice;
  const auto hold_us = static_cast<int64_t>(config_.initial_pose_hold * 1e6);
  if (initial_) {
    if (!initial_first_scan_utime_) initial_first_scan_utime_ = scan_utime;
    if (scan_utime - *initial_first_scan_utime_ <= hold_us) {
      choice.source = PriorSource::kInitialPose;
      choice.prior = prior_from_robot_pose(*initial_, robot_T_laser_);
      last_source_ = choice.source;
      return choice;
    }
    initial_.reset();
    initial_event_ = InitialPoseEvent::kExpired;
  }
  const bool own_fresh = last_own_ok_ && std::llabs(scan_utime - last_own_ok_->first) <= max_age_us_;
  if (scan_utime <= own_preferred_until_utime_ && own_fresh) {
    choice = own_pose_prior();
  } else if (!startup_.prior_allowed(scan_utime)) {
    choice.source = PriorSource::kStartupWindow;
  } else if (const FusedPose* pose = pose_for_scan(scan_utime);
             pose != nullptr && pose->ok && std::llabs(scan_utime - pose->utime) <= max_age_us_) {
    choice.source = PriorSource::kFusedPose;
    choice.prior = prior_from_robot_pose(*pose, robot_T_laser_);
  } else if (config_.use_own_pose && own_fresh) {
    choice = own_pose_prior();
  }
  last_source_ = choice.source;
  return choice;
}

StartupEvent PriorSelector::on_result(int64_t scan_utime, const MatchResult& result) {
  startup_.on_result(result.status, result.mode);
  if (result.status == MatchStatus::kOk) last_own_ok_ = std::make_pair(scan_utime, result.map_T_laser);
  if (last_source_ == PriorSource::kInitialPose && result.status == MatchStatus::kOk &&
      result.mode == MatchMode::kTracking) {
    initial_.reset();
    initial_event_ = InitialPoseEvent::kConfirmed;
    own_preferred_until_utime_ = scan_utime + static_cast<int64_t>(config_.initial_pose_hold * 1e6);
    if (!startup_.done()) {
      startup_.confirm_by_user_pose();
      startup_was_done_ = true;  // the user's pose ended the window: no "relocalized" event
    }
  }
  if (!startup_was_done_ && startup_.relocalized()) return StartupEvent::kRelocalized;
  if (!startup_was_done_ && startup_.gave_up()) return StartupEvent::kGaveUp;
  return StartupEvent::kNone;
}

}  // namespace refloc
