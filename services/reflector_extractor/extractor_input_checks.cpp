#include "reflector_extractor/extractor_input_checks.hpp"

#include "common/input_sanity.hpp"

#include <fmt/format.h>

#include <cmath>

namespace refloc {
namespace {

InputFault nonfinite(std::string detail) { return {"nonfinite", std::move(detail)}; }
InputFault out_of_bounds(std::string detail) { return {"out_of_bounds", std::move(detail)}; }

InputFault check_scan_header(const LaserScan& s) {
  if (!all_finite(
          {s.start_angle, s.angle_increment, s.time_increment, s.scan_period, s.range_min, s.range_max}))
    return nonfinite("non-finite angle, time or range limit in the header");
  const size_t n = s.ranges.size();
  if (n == 0 || n > ScanBounds::kMaxBeams) return out_of_bounds(fmt::format("{} beams", n));
  if (!(std::abs(s.start_angle) <= ScanBounds::kMaxAbsStartAngle))
    return out_of_bounds(fmt::format("start_angle {} rad", s.start_angle));
  const double span = static_cast<double>(n - 1) * std::abs(s.angle_increment);
  if (!(s.angle_increment != 0.0) || !(span <= 2.0 * M_PI + 1e-6))
    return out_of_bounds(fmt::format("{} beams of {} rad span more than one turn", n, s.angle_increment));
  if (!(s.scan_period > 0.0 && s.scan_period <= ScanBounds::kMaxScanPeriod_s))
    return out_of_bounds(fmt::format("scan_period {} s", s.scan_period));
  // 1e-3: the float fields' rounding on a 360 deg sensor whose beams fill the whole period.
  if (!(s.time_increment >= 0.0 && static_cast<double>(n) * s.time_increment <= s.scan_period * (1.0 + 1e-3)))
    return out_of_bounds(fmt::format("{} beams of {} s take longer than the scan period {} s", n,
                                     s.time_increment, s.scan_period));
  if (!(s.range_min >= 0.0 && s.range_min < s.range_max && s.range_max <= ScanBounds::kMaxRange_m))
    return out_of_bounds(fmt::format("range limits [{}, {}] m", s.range_min, s.range_max));
  return {};
}

InputFault check_scan_rssi(const LaserScan& s) {
  if (s.rssi.empty()) {
    if (s.rssi_bits == 0 || s.rssi_bits == 8 || s.rssi_bits == 16) return {};
    return out_of_bounds(fmt::format("rssi_bits {}", s.rssi_bits));
  }
  if (s.rssi.size() != s.ranges.size())
    return out_of_bounds(fmt::format("{} RSSI values for {} beams", s.rssi.size(), s.ranges.size()));
  if (s.rssi_bits != 8 && s.rssi_bits != 16) return out_of_bounds(fmt::format("rssi_bits {}", s.rssi_bits));
  const int32_t max_rssi = s.rssi_bits == 8 ? 255 : 65535;
  for (size_t i = 0; i < s.rssi.size(); ++i) {
    if (s.rssi[i] < 0 || s.rssi[i] > max_rssi)
      return out_of_bounds(fmt::format("beam {}: RSSI {} outside {} bits", i, s.rssi[i], s.rssi_bits));
  }
  return {};
}

}  // namespace

InputFault check_scan(const LaserScan& s) {
  for (size_t i = 0; i < s.ranges.size(); ++i) {
    if (!std::isfinite(s.ranges[i])) return nonfinite(fmt::format("beam {}: range {}", i, s.ranges[i]));
  }
  if (InputFault f = check_scan_header(s)) return f;
  for (size_t i = 0; i < s.ranges.size(); ++i) {
    if (!(s.ranges[i] >= 0.0f && s.ranges[i] <= ScanBounds::kMaxRange_m))
      return out_of_bounds(fmt::format("beam {}: range {} m", i, s.ranges[i]));
  }
  return check_scan_rssi(s);
}

InputFault check_odometry_twist(const OdometrySample& sample) {
  const BodyTwist& t = sample.twist;
  if (!all_finite({t.vx, t.vy, t.wz})) return nonfinite(fmt::format("twist ({}, {}, {})", t.vx, t.vy, t.wz));
  if (!finite_abs_at_most(t.vx, TwistBounds::kMaxSpeed_mps) ||
      !finite_abs_at_most(t.vy, TwistBounds::kMaxSpeed_mps) ||
      !finite_abs_at_most(t.wz, TwistBounds::kMaxYawRate_radps))
    return out_of_bounds(fmt::format("twist ({} m/s, {} m/s, {} rad/s)", t.vx, t.vy, t.wz));
  return {};
}

InputFault check_laser_pose(const LaserPoseFix& fix) {
  const Pose2& p = fix.map_T_robot;
  if (!all_finite({p.x, p.y, p.theta})) return nonfinite(fmt::format("pose ({}, {}, {})", p.x, p.y, p.theta));
  if (!finite_abs_at_most(p.x, LaserPoseBounds::kMaxAbsCoordinate_m) ||
      !finite_abs_at_most(p.y, LaserPoseBounds::kMaxAbsCoordinate_m) ||
      !finite_abs_at_most(p.theta, LaserPoseBounds::kMaxAbsTheta))
    return out_of_bounds(fmt::format("pose ({} m, {} m, {} rad)", p.x, p.y, p.theta));
  if (!is_usable_covariance(fix.covariance, LaserPoseBounds::kMaxVariance))
    return {"covariance", fmt::format("covariance diagonal ({}, {}, {})", fix.covariance(0, 0),
                                      fix.covariance(1, 1), fix.covariance(2, 2))};
  return {};
}

}  // namespace refloc
