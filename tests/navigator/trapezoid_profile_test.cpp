#include "navigator/trapezoid_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

struct Profile1d {
  double peak_speed = 0.0;
  double peak_accel = 0.0;
  double overshoot = 0.0;
  double final_error = 0.0;
  double time_to_creep = 0.0;  ///< first time within creep distance [s]
};

// Follow the profile with an ideal plant at 50 Hz.
Profile1d follow(double distance, const ProfileLimits& limits, double duration) {
  const double dt = 0.02;
  Profile1d out;
  double p = 0.0, v = 0.0;
  for (int i = 0; i < static_cast<int>(duration / dt); ++i) {
    const double remaining = distance - p;
    const double wanted = std::copysign(approach_speed(std::abs(remaining), limits), remaining);
    const double next = rate_limit(v, wanted, limits.max_accel * dt);
    out.peak_accel = std::max(out.peak_accel, std::abs(next - v) / dt);
    v = next;
    out.peak_speed = std::max(out.peak_speed, std::abs(v));
    p += v * dt;
    out.overshoot = std::max(out.overshoot, p - distance);
    if (out.time_to_creep == 0.0 && std::abs(distance - p) <= limits.creep_distance)
      out.time_to_creep = i * dt;
  }
  out.final_error = std::abs(distance - p);
  return out;
}

TEST(TrapezoidProfile, RespectsMaxSpeedAndAccelerationAndReachesTheTarget) {
  const ProfileLimits limits{1.0, 0.5, 0.8, 0.03, 0.03, 2.0};
  const Profile1d run = follow(3.0, limits, 12.0);
  EXPECT_LE(run.peak_speed, 1.0 + 1e-12);
  EXPECT_NEAR(run.peak_speed, 1.0, 1e-12);  // long enough to cruise: a trapezoid
  EXPECT_LE(run.peak_accel, 0.5 + 1e-9);
  EXPECT_LE(run.overshoot, 0.0);
  EXPECT_LT(run.final_error, 1e-4);
  // Ideal trapezoid: 3 m at 1 m/s with 0.5 m/s^2 ramps takes 5 s; braking at 80 % costs 0.5 s more.
  EXPECT_GT(run.time_to_creep, 5.0);
  EXPECT_LT(run.time_to_creep, 6.0);
}

TEST(TrapezoidProfile, ShortMoveIsATriangleBelowMaxSpeed) {
  const ProfileLimits limits{1.0, 0.5, 0.8, 0.03, 0.03, 2.0};
  const Profile1d run = follow(0.5, limits, 6.0);
  EXPECT_LT(run.peak_speed, 0.6);  // sqrt(0.5 m * 0.5 m/s^2) = 0.5 m/s for a symmetric triangle
  EXPECT_LE(run.peak_accel, 0.5 + 1e-9);
  EXPECT_LE(run.overshoot, 0.0);
  EXPECT_LT(run.final_error, 1e-4);
}

TEST(TrapezoidProfile, FinalApproachIsProportionalAndCappedAtCreepSpeed) {
  const ProfileLimits limits{1.0, 0.5, 0.8, 0.03, 0.03, 2.0};
  EXPECT_DOUBLE_EQ(approach_speed(0.0, limits), 0.0);
  EXPECT_DOUBLE_EQ(approach_speed(0.005, limits), 0.01);
  EXPECT_DOUBLE_EQ(approach_speed(0.03, limits), 0.03);
  EXPECT_DOUBLE_EQ(approach_speed(100.0, limits), 1.0);
}

TEST(TrapezoidProfile, VectorRateLimitBoundsTheNormOfTheChange) {
  const Eigen::Vector2d next = rate_limit(Eigen::Vector2d(0, 0), Eigen::Vector2d(3, 4), 0.5);
  EXPECT_NEAR(next.norm(), 0.5, 1e-12);
  EXPECT_NEAR(next.x() / next.y(), 0.75, 1e-12);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
