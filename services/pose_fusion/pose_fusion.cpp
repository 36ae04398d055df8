// PoseFusion: the odometry history, (re-)initialisation and both measurement kinds;
// longer than 300 lines because pose fixes and detection scans share one rollback
// and one status rule.
#include "pose_fusion/pose_fusion.hpp"

#include "common/covariance_propagation.hpp"
#include "common/se2.hpp"

#include <algorithm>
#include <cmath>

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

namespace {

/// The prior of the states besides the pose, before any measurement.
void set_model_prior(FusionState& state, const FusionModel& model) {
  state.range_bias_m = 0.0;
  state.odometry_error.setZero();
  state.covariance.setZero();
  const double b_sigma = model.estimate_range_bias ? model.range_bias_prior_sigma_m : 0.0;
  state.covariance(StateIndex::kRangeBias, StateIndex::kRangeBias) = b_sigma * b_sigma;
  const double e_sigma = model.estimate_odometry_error ? model.odometry_error_prior_sigma : 0.0;
  for (int i = 0; i < 9; ++i)
    state.covariance(StateIndex::kOdometryError + i, StateIndex::kOdometryError + i) = e_sigma * e_sigma;
  state.scan_time_offset_s = 0.0;
  const double tau_sigma = model.estimate_scan_time_offset ? model.scan_time_offset_prior_sigma_s : 0.0;
  state.covariance(StateIndex::kScanTimeOffset, StateIndex::kScanTimeOffset) = tau_sigma * tau_sigma;
}

}  // namespace

PoseFusion::PoseFusion(const FusionConfig& config)
    : config_(config), agreement_(config.start_agreeing_usable_fixes, config.start_window, config.gate_chi2) {
  const FusionModel& m = config.model;
  walk_.range_bias_m_per_sqrt_s = m.estimate_range_bias ? m.range_bias_drift_m_per_sqrt_s : 0.0;
  walk_.odometry_error_per_sqrt_m = m.estimate_odometry_error ? m.odometry_error_walk_per_sqrt_m : 0.0;
  walk_.scan_time_offset_s_per_sqrt_s =
      m.estimate_scan_time_offset ? m.scan_time_offset_drift_s_per_sqrt_s : 0.0;
  set_model_prior(base_, m);
}

const FusionState& PoseFusion::state() const { return posterior(static_cast<long>(steps_.size()) - 1); }

int64_t PoseFusion::utime() const { return steps_.empty() ? base_utime_ : steps_.back().utime; }

const FusionState& PoseFusion::posterior(long i) const {
  return i < 0 ? base_ : steps_[static_cast<size_t>(i)].posterior;
}

std::pair<double, int> PoseFusion::take_detection_nis() {
  const std::pair<double, int> out{nis_sum_, nis_count_};
  nis_sum_ = 0.0;
  nis_count_ = 0;
  return out;
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
  const int64_t start = this->utime();
  has_odometry_ = true;
  Step step;
  step.utime = utime;
  step.delta = delta;
  step.q = q;
  step.posterior = state();
  ekf_predict(step.posterior, delta, q, static_cast<double>(utime - start) * 1e-6, walk_);
  steps_.push_back(std::move(step));
  agreement_.add_odometry(delta, q);
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
  const int64_t now = utime();
  auto it = std::stable_partition(deferred_.begin(), deferred_.end(),
                                  [&](const Measurement& m) { return m.utime > now; });
  std::vector<Measurement> due(std::make_move_iterator(it), std::make_move_iterator(deferred_.end()));
  deferred_.erase(it, deferred_.end());
  for (Measurement& m : due) {
    if (m.is_scan) {
      deferred_results_.push_back(add_detections({m.utime, std::move(m.detections)}).result);
    } else {
      deferred_results_.push_back(add_fix(m.fix));
    }
  }
}

void PoseFusion::trim_history() {
  const auto horizon = utime() - static_cast<int64_t>(config_.history * 1e6);
  while (steps_.size() > 1 && steps_.front().utime < horizon) {
    base_ = steps_.front().posterior;
    base_utime_ = steps_.front().utime;
    steps_.pop_front();
  }
}

void PoseFusion::apply(FusionState& state, const Measurement& m) const {
  if (!m.is_scan) {
    ekf_correct_pose(state, m.fix.map_T_robot, m.fix.covariance);
    return;
  }
  const double map_variance = config_.model.map_sigma_m * config_.model.map_sigma_m;
  ekf_correct_scan(state, m.detections, config_.model.robot_T_laser, map_variance, m.timing);
}

ScanTiming PoseFusion::scan_timing(long i) const {
  ScanTiming timing;
  // A step split at the scan has two parts of one constant twist: the longer one divides best.
  const auto duration_s = [&](long k) {
    const int64_t start = k == 0 ? base_utime_ : steps_[static_cast<size_t>(k - 1)].utime;
    return static_cast<double>(steps_[static_cast<size_t>(k)].utime - start) * 1e-6;
  };
  long k = -1;
  for (long c : {i, i + 1})
    if (c >= 0 && c < static_cast<long>(steps_.size()) && (k < 0 || duration_s(c) > duration_s(k))) k = c;
  if (k < 0 || !(duration_s(k) > 0.0)) return timing;
  const BodyTwist log = se2_log(steps_[static_cast<size_t>(k)].delta);
  const double vx = log.vx / duration_s(k), vy = log.vy / duration_s(k), wz = log.wz / duration_s(k);
  const Pose2& mount = config_.model.robot_T_laser;
  const Eigen::Vector2d robot_velocity_at_laser(vx - wz * mount.y, vy + wz * mount.x);
  const double c = std::cos(mount.theta), s = std::sin(mount.theta);
  timing.laser_velocity = {c * robot_velocity_at_laser.x() + s * robot_velocity_at_laser.y(),
                           -s * robot_velocity_at_laser.x() + c * robot_velocity_at_laser.y()};
  timing.yaw_rate = wz;
  return timing;
}

void PoseFusion::recompute(size_t i) {
  Step& step = steps_[i];
  const int64_t start = i == 0 ? base_utime_ : steps_[i - 1].utime;
  step.posterior = posterior(static_cast<long>(i) - 1);
  ekf_predict(step.posterior, step.delta, step.q, static_cast<double>(step.utime - start) * 1e-6, walk_);
  for (const Measurement& m : step.measurements) apply(step.posterior, m);
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

std::pair<Pose2, Eigen::Matrix3d> PoseFusion::carried_to_latest(const PoseFix& fix) {
  Pose2 pose = fix.map_T_robot;
  Eigen::Matrix3d covariance = fix.covariance;
  if (steps_.empty() || fix.utime >= utime()) return {pose, covariance};
  const long i = step_ending_at(std::max(fix.utime, base_utime_));
  for (size_t j = static_cast<size_t>(i + 1); j < steps_.size(); ++j) {
    covariance = compose_covariance(pose, covariance, steps_[j].delta, steps_[j].q);
    pose = pose * steps_[j].delta;
  }
  return {pose, covariance};
}

void PoseFusion::initialise(const PoseFix& fix) {
  // Everything before the fix is forgotten: the fix becomes the base and the
  // odometry after it is re-applied. A fix newer than the latest odometry is
  // taken as a fix at that time (one encoder period at most). The range bias and
  // the odometry's calibration are the robot's, not the pose's: they are kept, without
  // their correlation with the pose that was lost.
  FusionState carried;
  if (!steps_.empty() && fix.utime < utime()) {
    const long i = step_ending_at(std::max(fix.utime, base_utime_));
    carried = posterior(i);
    base_utime_ = i < 0 ? base_utime_ : steps_[static_cast<size_t>(i)].utime;
    steps_.erase(steps_.begin(), steps_.begin() + (i + 1));
    for (Step& step : steps_) step.measurements.clear();  // accepted by the filter that got lost
  } else {
    carried = state();
    base_utime_ = steps_.empty() && base_utime_ == 0 ? fix.utime : utime();
    steps_.clear();
  }
  if (!initialised_) set_model_prior(carried, config_.model);
  base_ = carried;
  base_.map_T_robot = fix.map_T_robot;
  base_.covariance.topRows<3>().setZero();
  base_.covariance.leftCols<3>().setZero();
  base_.covariance.topLeftCorner<3, 3>() = fix.covariance;
  repropagate_from(0);
  initialised_ = true;
  seam_utime_ = -1;
  lost_by_rejections_ = false;
  consecutive_rejections_ = 0;
  last_accepted_fix_utime_ = fix.utime;
}

bool PoseFusion::waits_for_odometry(int64_t t) const {
  return static_cast<double>(t - utime()) > config_.max_fix_lead * 1e6;
}

void PoseFusion::defer(Measurement m) {
  if (deferred_.size() >= config_.max_deferred_fixes) deferred_.erase(deferred_.begin());
  deferred_.push_back(std::move(m));
}

void PoseFusion::commit(long i, Measurement m) {
  if (i < 0) {
    apply(base_, m);
    repropagate_from(0);
  } else {
    steps_[static_cast<size_t>(i)].measurements.push_back(std::move(m));
    recompute(static_cast<size_t>(i));
    repropagate_from(static_cast<size_t>(i) + 1);
  }
}

FixResult PoseFusion::time_refusal(int64_t t) const {
  if (has_odometry_) {
    if (!(static_cast<double>(t - utime()) <= config_.history * 1e6)) return FixResult::kAheadOfOdometry;
    if (t < base_utime_) return FixResult::kTooOld;
  }
  return FixResult::kAccepted;
}

FixResult PoseFusion::add_fix(const PoseFix& fix) {
  // The time checks come first: they hold for (re-)initialisation too.
  if (const FixResult refused = time_refusal(fix.utime); refused != FixResult::kAccepted) return refused;
  // Lost is judged at the odometry's time, never at the fix's: a fix cannot declare
  // the filter lost by its own stamp.
  if (!initialised_ || lost(utime())) {
    start_agreeing_fixes_ = 0;
    start_span_s_ = 0.0;
    if (fix.quality != FixQuality::kGood) {
      const auto [pose_now, covariance_now] = carried_to_latest(fix);
      if (!agreement_.offer(fix.utime, pose_now, covariance_now)) return FixResult::kWaitingForGood;
      start_agreeing_fixes_ = agreement_.last_agreeing();
      start_span_s_ = agreement_.last_span_s();
    }
    agreement_.clear();
    initialise(fix);
    return FixResult::kInitialised;
  }
  if (fix.utime < base_utime_) return FixResult::kTooOld;
  Measurement m;
  m.utime = fix.utime;
  m.fix = fix;
  if (waits_for_odometry(fix.utime)) {
    defer(std::move(m));
    return FixResult::kDeferred;
  }
  // A fix newer than the latest odometry by at most max_fix_lead is applied to the latest estimate.
  const long i = step_ending_at(std::min(fix.utime, utime()));
  last_mahalanobis_squared_ = pose_mahalanobis_squared(posterior(i), fix.map_T_robot, fix.covariance);
  if (!(last_mahalanobis_squared_ <= config_.gate_chi2)) {  // NaN fails the gate
    if (++consecutive_rejections_ >= config_.max_consecutive_rejections) lost_by_rejections_ = true;
    return FixResult::kRejectedGate;
  }
  consecutive_rejections_ = 0;
  last_accepted_fix_utime_ = std::max(last_accepted_fix_utime_, fix.utime);
  commit(i, std::move(m));
  return FixResult::kAccepted;
}

ScanResult PoseFusion::add_detections(const DetectionScan& scan) {
  if (const FixResult refused = time_refusal(scan.utime); refused != FixResult::kAccepted) return {refused};
  if (needs_initialisation()) return {FixResult::kWaitingForGood};
  if (scan.utime < base_utime_) return {FixResult::kTooOld};
  if (waits_for_odometry(scan.utime)) {
    Measurement m;
    m.utime = scan.utime;
    m.is_scan = true;
    m.detections = scan.detections;
    defer(std::move(m));
    return {FixResult::kDeferred};
  }
  return apply_scan(scan);
}

ScanResult PoseFusion::apply_scan(const DetectionScan& scan) {
  const long i = step_ending_at(std::min(scan.utime, utime()));
  const FusionState& prior = posterior(i);
  const double map_variance = config_.model.map_sigma_m * config_.model.map_sigma_m;
  ScanResult result;
  Measurement m;
  m.utime = scan.utime;
  m.is_scan = true;
  m.timing = scan_timing(i);
  // Every detection is gated against the estimate before this scan, so the order of a
  // scan's detections decides nothing and one wrong association cannot open the gate
  // for another.
  double nis = 0.0;
  for (MatchedDetection d : scan.detections) {
    d.covariance *= noise_inflation_;  // stored inflated: a rollback re-applies the same update
    const DetectionInnovation in =
        detection_innovation(prior, d, config_.model.robot_T_laser, map_variance, m.timing);
    if (in.mahalanobis_squared <= config_.model.detection_gate_chi2) {  // NaN fails the gate
      m.detections.push_back(d);
      nis += in.mahalanobis_squared;
    }
  }
  result.accepted = static_cast<int>(m.detections.size());
  result.rejected = static_cast<int>(scan.detections.size()) - result.accepted;
  last_mahalanobis_squared_ = result.accepted > 0 ? nis / result.accepted : 0.0;
  if (result.accepted == 0 || result.rejected > result.accepted) {
    if (++consecutive_rejections_ >= config_.max_consecutive_rejections) lost_by_rejections_ = true;
    result.result = FixResult::kRejectedGate;
    return result;
  }
  nis_sum_ += nis;
  nis_count_ += result.accepted;
  // Covariance matching: honest detections average 2. Kept ones that average more (a slow host
  // stamping scans late, a sensor noisier than its model) inflate the detections' covariance,
  // so the published covariance stays honest instead of the pose claiming millimetres it lacks.
  // With the prior much tighter than a detection, the distance at inflation 1 is about the
  // inflation times the one measured.
  equivalent_nis_mean_ += 0.02 * (nis / result.accepted * noise_inflation_ - equivalent_nis_mean_);
  noise_inflation_ =
      std::clamp(equivalent_nis_mean_ / 2.0, 1.0, std::max(1.0, config_.model.max_noise_inflation));
  consecutive_rejections_ = 0;
  if (result.accepted >= config_.model.min_detections_for_fix)
    last_accepted_fix_utime_ = std::max(last_accepted_fix_utime_, scan.utime);
  commit(i, std::move(m));
  result.result = FixResult::kAccepted;
  return result;
}

}  // namespace refloc
