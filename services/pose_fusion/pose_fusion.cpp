#include "pose_fusion/pose_fusion.hpp"

#include "common/se2.hpp"

#include <algorithm>

namespace refloc {

const char* to_string(FusionStatus status) {
  switch (status) {
    case FusionStatus::kInitializing:
      return "INITIALIZING";
    case FusionStatus::kOk:
      return "OK";
    case FusionStatus::kDegraded:
      return "DEGRADED";
    case FusionStatus::kLost:
      return "LOST";
  }
  return "?";
}

PoseFusion::PoseFusion(const FusionConfig& config) : config_(config) {}

const PoseEstimate& PoseFusion::estimate() const { return posterior(static_cast<long>(steps_.size()) - 1); }

int64_t PoseFusion::utime() const { return steps_.empty() ? base_utime_ : steps_.back().utime; }

const PoseEstimate& PoseFusion::posterior(long i) const {
  return i < 0 ? base_ : steps_[static_cast<size_t>(i)].posterior;
}

bool PoseFusion::lost(int64_t now_utime) const {
  return lost_by_rejections_ ||
         static_cast<double>(now_utime - last_accepted_fix_utime_) > config_.lost_after * 1e6;
}

FusionStatus PoseFusion::status(int64_t now_utime) const {
  if (!initialised_) return FusionStatus::kInitializing;
  if (lost(now_utime)) return FusionStatus::kLost;
  if (static_cast<double>(now_utime - last_accepted_fix_utime_) > config_.degraded_after * 1e6 ||
      last_accepted_fix_utime_ <= seam_utime_) {
    return FusionStatus::kDegraded;
  }
  return FusionStatus::kOk;
}

bool PoseFusion::add_odometry(int64_t utime, const Pose2& delta, const Eigen::Matrix3d& q) {
  if (utime <= this->utime()) return false;
  has_odometry_ = true;
  Step step;
  step.utime = utime;
  step.delta = delta;
  step.q = q;
  step.posterior = ekf_predict(estimate(), delta, q);
  steps_.push_back(std::move(step));
  trim_history();
  apply_deferred_fixes();
  return true;
}

bool PoseFusion::add_odometry_seam(int64_t utime, const Pose2& delta, const Eigen::Matrix3d& q) {
  const int64_t start = this->utime();
  if (utime <= start) return false;
  if (initialised_) seam_utime_ = start;
  return add_odometry(utime, delta, q);
}

void PoseFusion::apply_deferred_fixes() {
  deferred_results_.clear();
  if (deferred_.empty()) return;
  std::vector<PoseFix> due;
  const int64_t now = utime();
  auto it = std::stable_partition(deferred_.begin(), deferred_.end(),
                                  [&](const PoseFix& f) { return f.utime > now; });
  due.assign(it, deferred_.end());
  deferred_.erase(it, deferred_.end());
  for (const PoseFix& fix : due) deferred_results_.push_back(add_fix(fix));
}

void PoseFusion::trim_history() {
  const auto horizon = utime() - static_cast<int64_t>(config_.history * 1e6);
  while (steps_.size() > 1 && steps_.front().utime < horizon) {
    base_ = steps_.front().posterior;
    base_utime_ = steps_.front().utime;
    steps_.pop_front();
  }
}

void PoseFusion::recompute(size_t i) {
  Step& step = steps_[i];
  step.posterior = ekf_predict(posterior(static_cast<long>(i) - 1), step.delta, step.q);
  for (const AppliedFix& fix : step.fixes) {
    step.posterior = ekf_correct(step.posterior, fix.map_T_robot, fix.covariance);
  }
}

void PoseFusion::repropagate_from(size_t first) {
  for (size_t i = first; i < steps_.size(); ++i) recompute(i);
}

long PoseFusion::step_ending_at(int64_t t) {
  size_t i = 0;
  while (i < steps_.size() && steps_[i].utime < t) ++i;
  if (i == steps_.size()) return static_cast<long>(i) - 1;
  if (steps_[i].utime == t) return static_cast<long>(i);
  const int64_t start = i == 0 ? base_utime_ : steps_[i - 1].utime;
  if (t <= start) return static_cast<long>(i) - 1;
  // Split step i at t, assuming a constant body twist over it (the exact-arc model).
  const double alpha = static_cast<double>(t - start) / static_cast<double>(steps_[i].utime - start);
  Step first;
  first.utime = t;
  first.delta = se2_exp(se2_log(steps_[i].delta), alpha);
  first.q = alpha * steps_[i].q;
  steps_[i].delta = first.delta.inverse() * steps_[i].delta;
  steps_[i].q *= 1.0 - alpha;
  steps_.insert(steps_.begin() + static_cast<long>(i), std::move(first));
  recompute(i);
  recompute(i + 1);
  return static_cast<long>(i);
}

void PoseFusion::initialise(const PoseFix& fix) {
  // Everything before the fix is forgotten: the fix becomes the base and the
  // odometry after it is re-applied. A fix newer than the latest odometry is
  // taken as a fix at that time (one encoder period at most).
  if (!steps_.empty() && fix.utime < utime()) {
    const long i = step_ending_at(std::max(fix.utime, base_utime_));
    base_utime_ = i < 0 ? base_utime_ : steps_[static_cast<size_t>(i)].utime;
    steps_.erase(steps_.begin(), steps_.begin() + (i + 1));
    for (Step& step : steps_) step.fixes.clear();  // accepted by the filter that got lost
  } else {
    base_utime_ = steps_.empty() && base_utime_ == 0 ? fix.utime : utime();
    steps_.clear();
  }
  base_ = {fix.map_T_robot, fix.covariance};
  repropagate_from(0);
  initialised_ = true;
  seam_utime_ = -1;
  lost_by_rejections_ = false;
  consecutive_rejections_ = 0;
  last_accepted_fix_utime_ = fix.utime;
}

FixResult PoseFusion::add_fix(const PoseFix& fix) {
  // The time checks come first: they hold for (re-)initialisation too.
  if (has_odometry_) {
    if (!(static_cast<double>(fix.utime - utime()) <= config_.history * 1e6))
      return FixResult::kAheadOfOdometry;
    if (fix.utime < base_utime_) return FixResult::kTooOld;
  }
  // Lost is judged at the odometry's time, never at the fix's: a fix cannot declare
  // the filter lost by its own stamp.
  if (!initialised_ || lost(utime())) {
    if (fix.quality != FixQuality::kGood) return FixResult::kWaitingForGood;
    initialise(fix);
    return FixResult::kInitialised;
  }
  if (fix.utime < base_utime_) return FixResult::kTooOld;
  if (static_cast<double>(fix.utime - utime()) > config_.max_fix_lead * 1e6) {
    if (deferred_.size() >= config_.max_deferred_fixes) deferred_.erase(deferred_.begin());
    deferred_.push_back(fix);
    return FixResult::kDeferred;
  }
  // A fix newer than the latest odometry by at most max_fix_lead is applied to the latest estimate.
  const long i = step_ending_at(std::min(fix.utime, utime()));
  last_mahalanobis_squared_ = mahalanobis_squared(posterior(i), fix.map_T_robot, fix.covariance);
  if (!(last_mahalanobis_squared_ <= config_.gate_chi2)) {  // NaN fails the gate
    if (++consecutive_rejections_ >= config_.max_consecutive_rejections) lost_by_rejections_ = true;
    return FixResult::kRejectedGate;
  }
  consecutive_rejections_ = 0;
  last_accepted_fix_utime_ = std::max(last_accepted_fix_utime_, fix.utime);
  if (i < 0) {
    base_ = ekf_correct(base_, fix.map_T_robot, fix.covariance);
    repropagate_from(0);
  } else {
    steps_[static_cast<size_t>(i)].fixes.push_back({fix.map_T_robot, fix.covariance});
    recompute(static_cast<size_t>(i));
    repropagate_from(static_cast<size_t>(i) + 1);
  }
  return FixResult::kAccepted;
}

}  // namespace refloc
