#include "reflector_extractor/fix_velocity_estimator.hpp"

#include "common/angles.hpp"
#include "reflector_extractor/extractor_input_checks.hpp"

#include <cmath>
#include <cstdlib>

namespace refloc {
namespace {

// LMS100 at 50 Hz over the longest window the config allows (2 s) is 100 fixes.
constexpr size_t kReservedFixes = 128;

/// The robot could not have moved from a to b: faster than TwistBounds allow.
bool implausible_step(const LaserPoseFix& a, const LaserPoseFix& b) {
  const double dt = static_cast<double>(b.utime - a.utime) * 1e-6;
  const double distance = std::hypot(b.map_T_robot.x - a.map_T_robot.x, b.map_T_robot.y - a.map_T_robot.y);
  const double turn = std::abs(angle_diff(b.map_T_robot.theta, a.map_T_robot.theta));
  return distance > TwistBounds::kMaxSpeed_mps * dt || turn > TwistBounds::kMaxYawRate_radps * dt;
}

}  // namespace

const char* to_string(FixVelocityStatus status) {
  switch (status) {
    case FixVelocityStatus::kOk:
      return "ok";
    case FixVelocityStatus::kNoFixes:
      return "no OK fix";
    case FixVelocityStatus::kStale:
      return "newest fix too old";
    case FixVelocityStatus::kTooFew:
      return "too few fixes";
    case FixVelocityStatus::kScattered:
      return "fixes scattered";
    case FixVelocityStatus::kImplausible:
      return "implausible twist";
  }
  return "?";
}

FixVelocityEstimator::FixVelocityEstimator(const FixVelocityConfig& config)
    : config_(config),
      window_us_(std::llround(config.window_s * 1e6)),
      max_age_us_(std::llround(config.max_age_s * 1e6)) {
  fixes_.reserve(kReservedFixes);
}

void FixVelocityEstimator::add(const LaserPoseFix& fix) {
  if (!fix.ok) return;
  if (!fixes_.empty()) {
    if (fix.utime <= fixes_.back().utime) return;
    if (implausible_step(fixes_.back(), fix)) fixes_.clear();
  }
  size_t keep_from = 0;
  while (keep_from < fixes_.size() && fix.utime - fixes_[keep_from].utime > window_us_) ++keep_from;
  fixes_.erase(fixes_.begin(), fixes_.begin() + static_cast<std::ptrdiff_t>(keep_from));
  if (fixes_.size() >= kReservedFixes) fixes_.erase(fixes_.begin());  // never reallocate
  fixes_.push_back(fix);
}

FixVelocityEstimate FixVelocityEstimator::estimate(int64_t scan_utime) const {
  FixVelocityEstimate e;
  e.fixes = static_cast<int>(fixes_.size());
  if (fixes_.empty()) return e;
  e.newest_age_s = static_cast<double>(scan_utime - fixes_.back().utime) * 1e-6;
  if (std::llabs(scan_utime - fixes_.back().utime) > max_age_us_) {
    e.status = FixVelocityStatus::kStale;
    return e;
  }
  const double span_s = static_cast<double>(fixes_.back().utime - fixes_.front().utime) * 1e-6;
  if (e.fixes < config_.min_fixes || span_s < config_.min_span_s) {
    e.status = FixVelocityStatus::kTooFew;
    return e;
  }
  // Times relative to the first fix (microsecond stamps lose nothing as doubles then),
  // headings unwrapped along the window.
  const int64_t t0 = fixes_.front().utime;
  const double n = static_cast<double>(fixes_.size());
  double mean_t = 0.0, mean_x = 0.0, mean_y = 0.0, mean_theta = 0.0;
  double theta = fixes_.front().map_T_robot.theta;
  for (size_t i = 0; i < fixes_.size(); ++i) {
    const Pose2& p = fixes_[i].map_T_robot;
    if (i > 0) theta += angle_diff(p.theta, fixes_[i - 1].map_T_robot.theta);
    mean_t += static_cast<double>(fixes_[i].utime - t0) * 1e-6;
    mean_x += p.x;
    mean_y += p.y;
    mean_theta += theta;
  }
  mean_t /= n, mean_x /= n, mean_y /= n, mean_theta /= n;
  double stt = 0.0, stx = 0.0, sty = 0.0, stth = 0.0;
  theta = fixes_.front().map_T_robot.theta;
  for (size_t i = 0; i < fixes_.size(); ++i) {
    const Pose2& p = fixes_[i].map_T_robot;
    if (i > 0) theta += angle_diff(p.theta, fixes_[i - 1].map_T_robot.theta);
    const double tau = static_cast<double>(fixes_[i].utime - t0) * 1e-6 - mean_t;
    stt += tau * tau;
    stx += tau * (p.x - mean_x);
    sty += tau * (p.y - mean_y);
    stth += tau * (theta - mean_theta);
  }
  const Eigen::Vector2d map_v(stx / stt, sty / stt);
  double sum_r2 = 0.0;
  for (const LaserPoseFix& f : fixes_) {
    const double tau = static_cast<double>(f.utime - t0) * 1e-6 - mean_t;
    sum_r2 += std::pow(f.map_T_robot.x - mean_x - map_v.x() * tau, 2) +
              std::pow(f.map_T_robot.y - mean_y - map_v.y() * tau, 2);
  }
  e.rms_residual = std::sqrt(sum_r2 / n);
  if (e.rms_residual > config_.max_rms_residual_m) {
    e.status = FixVelocityStatus::kScattered;
    return e;
  }
  // The slope is the map velocity at the mean time (exact for a constant acceleration), so
  // it is turned into the body frame with the heading at that time, not the newest one.
  const Eigen::Vector2d body_v = Pose2{0.0, 0.0, mean_theta}.rotation().transpose() * map_v;
  e.twist = {body_v.x(), body_v.y(), stth / stt};
  OdometrySample as_odometry;
  as_odometry.twist = e.twist;
  e.status = check_odometry_twist(as_odometry) ? FixVelocityStatus::kImplausible : FixVelocityStatus::kOk;
  return e;
}

}  // namespace refloc
