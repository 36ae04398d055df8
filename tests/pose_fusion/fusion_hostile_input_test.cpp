// pose_fusion facing hostile or broken peers: NaN/inf/1e300 in every consumed field,
// stamps an hour off or at the int64 limits, fixes from the future, teleporting
// odometry. Nothing non-finite comes out, no OK is computed from a refused input,
// every refusal is counted, and the node keeps working on good input after.

#include "pose_fusion/fusion_node.hpp"

#include "common/input_sanity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

/// These tests drive the filter with LASER_POSE alone (detections: detection_fusion_test.cpp).
FusionServiceConfig laser_pose_config() {
  FusionServiceConfig c;
  c.measurements = FusionMeasurements::kLaserPose;
  return c;
}

constexpr int64_t kT0 = 1'700'000'000'000'000;  // a plausible wall-clock stamp [us]
constexpr int64_t kPeriod = 10'000;             // odometry at 100 Hz
constexpr int64_t kLatency = 3'000;             // host clock when a message arrives, after its stamp
constexpr int64_t kHour = 3'600'000'000;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

int count(const std::vector<NodeEvent>& events, const std::string& counter) {
  return static_cast<int>(std::count_if(events.begin(), events.end(), [&](const NodeEvent& e) {
    return e.counter != nullptr && counter == e.counter;
  }));
}

bool finite(const FusionOutput& p) {
  return all_finite({p.map_T_robot.x, p.map_T_robot.y, p.map_T_robot.theta}) && p.covariance.allFinite();
}

/// A robot driving +x at 0.5 m/s from the map origin, odometry and fixes both exact.
class Drive {
 public:
  Drive() : node(laser_pose_config(), OdometryNoise{}) {}

  OdometrySample odometry_at(int k) const {
    return {kT0 + k * kPeriod, {0.5, 0.0, 0.0}, Pose2{0.005 * k, 0.0, 0.0}, 0.005 * k};
  }
  LaserFixInput fix_at(int k) const {
    LaserFixInput in;
    in.utime = kT0 + k * kPeriod;
    in.map_T_robot = {0.005 * k, 0.0, 0.0};
    in.covariance = Eigen::Vector3d(1e-4, 1e-4, 1e-5).asDiagonal();
    in.status = FixStatus::kOk;
    in.reflectors_used = 6;
    return in;
  }
  int64_t mono(int k) const { return k * kPeriod; }
  int64_t host(int k) const { return kT0 + k * kPeriod + kLatency; }

  /// Good odometry for step k, with a fix every other step; the POSE published.
  const FusionOutput* step(int k) {
    const FusionOutput* pose = node.on_odometry(odometry_at(k), mono(k), host(k));
    if (k % 2 == 0) node.on_fix(fix_at(k), mono(k), host(k));
    return pose;
  }
  /// Steps [from, to): the last POSE.
  FusionOutput run(int from, int to) {
    FusionOutput last;
    for (int k = from; k < to; ++k) {
      const FusionOutput* p = step(k);
      if (p != nullptr) last = *p;
    }
    return last;
  }

  FusionNode node;
};

void expect_good_and_ok(const FusionOutput& pose, int k, const std::string& what) {
  EXPECT_TRUE(finite(pose)) << what;
  EXPECT_EQ(pose.status, FusionStatus::kOk) << what;
  EXPECT_NEAR(pose.map_T_robot.x, 0.005 * k, 0.01) << what;
  EXPECT_LT(pose.covariance(0, 0), 1e-3) << what;
}

TEST(FusionHostileInput, NonFiniteOrAbsurdOdometryInEveryFieldIsRefusedCountedAndThePoseStaysGood) {
  const std::vector<std::pair<std::string, std::function<void(OdometrySample&, double)>>> fields = {
      {"x", [](OdometrySample& s, double v) { s.odom_T_robot.x = v; }},
      {"y", [](OdometrySample& s, double v) { s.odom_T_robot.y = v; }},
      {"theta", [](OdometrySample& s, double v) { s.odom_T_robot.theta = v; }},
      {"vx", [](OdometrySample& s, double v) { s.twist.vx = v; }},
      {"vy", [](OdometrySample& s, double v) { s.twist.vy = v; }},
      {"wz", [](OdometrySample& s, double v) { s.twist.wz = v; }},
      {"distance", [](OdometrySample& s, double v) { s.distance = v; }},
  };
  for (const auto& [name, set] : fields) {
    for (const double bad : {kNaN, kInf, -kInf, 1e300, -1e300}) {
      const std::string what = name + " = " + std::to_string(bad);
      Drive d;
      d.run(0, 50);
      OdometrySample sample = d.odometry_at(50);
      set(sample, bad);
      EXPECT_EQ(d.node.on_odometry(sample, d.mono(50), d.host(50)), nullptr) << what;
      const bool finite_value = std::isfinite(bad);
      EXPECT_EQ(count(d.node.events(),
                      finite_value ? "rejected_odometry_out_of_bounds" : "rejected_odometry_nonfinite"),
                1)
          << what;
      EXPECT_TRUE(d.node.events()[0].level == NodeEvent::Level::kWarn) << what;
      expect_good_and_ok(d.run(51, 100), 99, what);
    }
  }
}

TEST(FusionHostileInput, OdometryStampedFarFromTheClockIsRefusedAndNeitherStallsNorInflatesTheFilter) {
  const std::vector<std::pair<int64_t, std::string>> stamps = {
      {kT0 + 50 * kPeriod + kHour, "rejected_odometry_stamp_ahead"},
      {std::numeric_limits<int64_t>::max(), "rejected_odometry_stamp_ahead"},
      {0, "rejected_odometry_stamp_behind"},
      {kT0 + 50 * kPeriod - kHour, "rejected_odometry_stamp_behind"},
      {std::numeric_limits<int64_t>::min(), "rejected_odometry_stamp_behind"},
      {-kHour, "rejected_odometry_stamp_behind"},
  };
  for (const auto& [stamp, counter] : stamps) {
    Drive d;
    d.run(0, 50);
    OdometrySample sample = d.odometry_at(50);
    sample.utime = stamp;
    EXPECT_EQ(d.node.on_odometry(sample, d.mono(50), d.host(50)), nullptr) << stamp;
    EXPECT_EQ(count(d.node.events(), counter), 1) << stamp;
    const FusionOutput* next = d.step(50);  // the genuine message for the same step
    ASSERT_NE(next, nullptr) << stamp;
    expect_good_and_ok(*next, 50, counter);
    EXPECT_EQ(count(d.node.events(), "initialisations"), 0) << stamp;
    expect_good_and_ok(d.run(51, 100), 99, counter);
  }
}

TEST(FusionHostileInput, APersistentStreamOfInt64LimitStampsNeverBecomesTheStreamsClock) {
  for (const int64_t stamp :
       {std::numeric_limits<int64_t>::min(), std::numeric_limits<int64_t>::max(), int64_t{0}}) {
    Drive d;
    d.run(0, 50);
    int reanchored = 0;
    for (int k = 50; k < 150; ++k) {  // one forged message before each genuine one, for 1 s
      OdometrySample forged = d.odometry_at(k);
      forged.utime = stamp;
      EXPECT_EQ(d.node.on_odometry(forged, d.mono(k), d.host(k)), nullptr);
      reanchored += count(d.node.events(), "reanchored_odometry");
      ASSERT_NE(d.step(k), nullptr) << stamp << " at " << k;
    }
    EXPECT_EQ(reanchored, 0) << stamp;
    expect_good_and_ok(d.run(150, 160), 159, std::to_string(stamp));
  }
}

TEST(FusionHostileInput, FixStampedInTheFutureNeitherReinitialisesNorMovesThePose) {
  for (const int64_t ahead : {kHour, int64_t{2'000'000}, int64_t{300'000}}) {
    Drive d;
    d.run(0, 50);
    LaserFixInput far = d.fix_at(50);
    far.utime += ahead;
    far.map_T_robot = {66.0, 0.0, 0.0};
    EXPECT_FALSE(d.node.on_fix(far, d.mono(50), d.host(50)));
    EXPECT_EQ(count(d.node.events(), "rejected_laser_pose_stamp_ahead"), 1) << ahead;
    EXPECT_EQ(count(d.node.events(), "initialisations"), 0) << ahead;
    expect_good_and_ok(d.run(50, 100), 99, "after a fix " + std::to_string(ahead) + " us ahead");
  }
}

TEST(FusionHostileInput, NonFiniteOrAbsurdFixValuesAreRefusedAndNeverReachTheFilter) {
  const std::vector<std::pair<std::string, std::function<void(LaserFixInput&, double)>>> fields = {
      {"x", [](LaserFixInput& f, double v) { f.map_T_robot.x = v; }},
      {"y", [](LaserFixInput& f, double v) { f.map_T_robot.y = v; }},
      {"theta", [](LaserFixInput& f, double v) { f.map_T_robot.theta = v; }},
      {"cov_xx", [](LaserFixInput& f, double v) { f.covariance(0, 0) = v; }},
      {"cov_tt", [](LaserFixInput& f, double v) { f.covariance(2, 2) = v; }},
      {"cov_xy", [](LaserFixInput& f, double v) { f.covariance(0, 1) = v; }},
  };
  for (const auto& [name, set] : fields) {
    for (const double bad : {kNaN, kInf, -kInf, 1e300, -1e300, -1e-4, 0.0}) {
      const bool is_variance = name == "cov_xx" || name == "cov_tt";
      if ((bad == 0.0 || bad == -1e-4) && !is_variance) continue;  // a legitimate position / correlation
      const std::string what = name + " = " + std::to_string(bad);
      Drive d;
      d.run(0, 51);
      LaserFixInput fix = d.fix_at(51);
      set(fix, bad);
      EXPECT_FALSE(d.node.on_fix(fix, d.mono(51), d.host(51))) << what;
      const std::string reason = !std::isfinite(bad) ? "nonfinite"
                                 : (name[0] == 'c')  ? "covariance"
                                                     : "out_of_bounds";
      EXPECT_EQ(count(d.node.events(), "rejected_laser_pose_" + reason), 1) << what;
      EXPECT_EQ(count(d.node.events(), "fixes_accepted"), 0) << what;
      expect_good_and_ok(d.run(52, 100), 99, what);
    }
  }
}

TEST(FusionHostileInput, TeleportingOdometryIsRefusedAndAPersistentNewReferenceBecomesANewFrame) {
  Drive d;
  d.run(0, 50);
  OdometrySample jump = d.odometry_at(50);
  jump.odom_T_robot.x += 1000.0;
  EXPECT_EQ(d.node.on_odometry(jump, d.mono(50), d.host(50)), nullptr);
  EXPECT_EQ(count(d.node.events(), "rejected_odometry_jump"), 1);
  expect_good_and_ok(d.run(51, 100), 99, "after one teleport");
  // The odometry frame itself moved by 1000 m (a reference that was bad): refused five
  // times, then a restart seam, DEGRADED until a fix, never a 1000 m jump of POSE.
  int refused = 0;
  for (int k = 100; k < 110; ++k) {
    OdometrySample s = d.odometry_at(k);
    s.odom_T_robot.x += 1000.0;
    const FusionOutput* p = d.node.on_odometry(s, d.mono(k), d.host(k));
    refused += p == nullptr;
    if (p != nullptr) {
      EXPECT_NEAR(p->map_T_robot.x, 0.005 * k, 0.05) << k;
      EXPECT_NE(p->status, FusionStatus::kOk) << k;
    }
  }
  EXPECT_EQ(refused, OdometryContinuity::kResyncAfter);
}

TEST(FusionHostileInput, MissingOdometryAndLaserPoseMessagesAreCountedAsGaps) {
  Drive d;
  d.run(0, 50);
  int gaps = 0;
  for (int k = 54; k < 60; ++k) {  // odometry 50..53 never arrive
    d.node.on_odometry(d.odometry_at(k), d.mono(k), d.host(k));
    gaps += count(d.node.events(), "gap_odometry_messages");
  }
  EXPECT_EQ(gaps, 4);
  int fix_gaps = 0;
  for (int k = 70; k < 80; k += 2) {  // fixes every 20 ms; the ten of steps 50..68 lost
    d.node.on_fix(d.fix_at(k), d.mono(k), d.host(k));
    fix_gaps += count(d.node.events(), "gap_laser_pose_messages");
  }
  EXPECT_EQ(fix_gaps, 10);
}

TEST(FusionHostileInput, OdometryArrivingButAllRefusedIsDegradedNotOk) {
  Drive d;
  d.run(0, 50);
  EXPECT_TRUE(d.node.health(d.mono(50)).ok);
  for (int k = 50; k < 200; ++k) {
    OdometrySample s = d.odometry_at(k);
    s.odom_T_robot.x = kNaN;
    d.node.on_odometry(s, d.mono(k), d.host(k));
  }
  const FusionHealth h = d.node.health(d.mono(200));
  EXPECT_FALSE(h.ok);
  EXPECT_EQ(h.detail, "no POSE published for 1 s: input refused (rejected_odometry_nonfinite)");
  d.run(200, 202);
  EXPECT_TRUE(d.node.health(d.mono(202)).ok);
}

TEST(PoseFusionTimeChecks, AFixAheadOfOdometryCannotReinitialiseALostFilter) {
  PoseFusion fusion{FusionConfig{}};
  ASSERT_EQ(fusion.add_fix({kT0, Pose2{}, Eigen::Matrix3d::Identity() * 1e-4, FixQuality::kGood}),
            FixResult::kInitialised);
  for (int k = 1; k <= 700; ++k)
    fusion.add_odometry(kT0 + k * kPeriod, Pose2{}, Eigen::Matrix3d::Identity() * 1e-8);
  ASSERT_EQ(fusion.status(fusion.utime()), FusionStatus::kLost);  // 7 s without a fix
  const PoseFix future{fusion.utime() + 2'000'000, Pose2{66.0, 0.0, 0.0}, Eigen::Matrix3d::Identity() * 1e-4,
                       FixQuality::kGood};
  EXPECT_EQ(fusion.add_fix(future), FixResult::kAheadOfOdometry);
  EXPECT_NEAR(fusion.estimate().map_T_robot.x, 0.0, 1e-9);
  const PoseFix now{fusion.utime(), Pose2{1.0, 0.0, 0.0}, Eigen::Matrix3d::Identity() * 1e-4,
                    FixQuality::kGood};
  EXPECT_EQ(fusion.add_fix(now), FixResult::kInitialised);
}

TEST(PoseFusionTimeChecks, ANaNMahalanobisDistanceFailsTheGate) {
  PoseFusion fusion{FusionConfig{}};
  fusion.add_odometry(kT0, Pose2{}, Eigen::Matrix3d::Zero());
  ASSERT_EQ(fusion.add_fix({kT0, Pose2{}, Eigen::Matrix3d::Identity() * 1e-4, FixQuality::kGood}),
            FixResult::kInitialised);
  fusion.add_odometry(kT0 + kPeriod, Pose2{}, Eigen::Matrix3d::Identity() * 1e-8);
  const PoseFix nan{kT0 + kPeriod, Pose2{kNaN, 0.0, 0.0}, Eigen::Matrix3d::Identity() * 1e-4,
                    FixQuality::kGood};
  EXPECT_EQ(fusion.add_fix(nan), FixResult::kRejectedGate);
  EXPECT_TRUE(std::isfinite(fusion.estimate().map_T_robot.x));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
