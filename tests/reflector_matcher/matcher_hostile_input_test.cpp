// The matcher node fed what a hostile or broken peer can publish on REFLECTORS and POSE:
// a NaN or absurd prior is never used and never yields an OK, broken detections are
// rejected as a whole and counted, and good input afterwards is matched as before.

#include "reflector_matcher/fused_pose_check.hpp"
#include "reflector_matcher/matcher_node.hpp"

#include "synthetic_detections.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 1'700'000'000'000'000;
constexpr int64_t kPeriod = 20'000;
constexpr int64_t kLatency = 3'000;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

MatcherServiceConfig no_startup_window() {
  MatcherServiceConfig config;
  config.prior.relocalize_on_start = 0.0;
  return config;
}

class MatcherHostileInput : public ::testing::Test {
 protected:
  MatcherHostileInput() : node_(map_, no_startup_window(), mount_) {}

  FusedPose good_pose() const {
    FusedPose pose;
    pose.utime = kT0 + k_ * kPeriod - 1'000;
    pose.map_T_robot = map_T_robot_;
    pose.covariance = Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal();
    pose.ok = true;
    return pose;
  }
  const MatcherOutput& good_scan() {
    ++k_;
    count(node_.on_pose(good_pose(), good_pose().utime + kLatency));
    return scan(detections_, kT0 + k_ * kPeriod, k_);
  }
  const MatcherOutput& scan(const std::vector<ReflectorDetection>& detections, int64_t utime,
                            int64_t counter) {
    return scan_at(detections, utime, counter, utime + kLatency);
  }
  const MatcherOutput& scan_at(const std::vector<ReflectorDetection>& detections, int64_t utime,
                               int64_t counter, int64_t host_utime) {
    const MatcherOutput& out = node_.on_detections(utime, counter, detections, host_utime);
    for (const NodeEvent& e : out.events)
      if (e.counter != nullptr) ++counters_[e.counter];
    out.for_each_counter([&](const char* name, int64_t by) { counters_[name] += by; });
    return out;
  }
  void count(const std::vector<NodeEvent>& events) {
    for (const NodeEvent& e : events)
      if (e.counter != nullptr) ++counters_[e.counter];
  }
  void expect_ok_and_finite(const MatcherOutput& out) {
    ASSERT_TRUE(out.accepted);
    EXPECT_TRUE(out.ok());
    EXPECT_TRUE(std::isfinite(out.result.map_T_laser.x) && std::isfinite(out.result.map_T_laser.y) &&
                std::isfinite(out.result.map_T_laser.theta));
    const Pose2 expected = map_T_robot_ * mount_;
    EXPECT_NEAR(out.result.map_T_laser.x, expected.x, 0.1);
    EXPECT_NEAR(out.result.map_T_laser.y, expected.y, 0.1);
  }

  std::mt19937 rng_{11};
  ReflectorMap map_ = testing::random_map(20, 30, 30, 1.0, rng_);
  Pose2 mount_{0.2, 0.0, 0.0};
  Pose2 map_T_robot_{15.0, 15.0, 0.4};
  std::vector<ReflectorDetection> detections_ =
      testing::render_detections(map_, map_T_robot_* mount_, testing::SyntheticSensor{}, rng_).detections;
  MatcherNode node_;
  int64_t k_ = 0;
  std::map<std::string, int64_t> counters_;
};

TEST_F(MatcherHostileInput, ANanOrAbsurdPriorIsRejectedAndNeverUsed) {
  for (int i = 0; i < 3; ++i) expect_ok_and_finite(good_scan());
  const std::vector<std::function<void(FusedPose&)>> hostile = {
      [](FusedPose& p) { p.map_T_robot.x = kNan; },
      [](FusedPose& p) { p.map_T_robot.theta = kInf; },
      [](FusedPose& p) { p.map_T_robot.y = 1e300; },
      [](FusedPose& p) { p.covariance(0, 0) = kNan; },
      [](FusedPose& p) { p.covariance(0, 1) = 1.0; },  // not symmetric
      [](FusedPose& p) { p.covariance = -Eigen::Matrix3d::Identity(); },
      [](FusedPose& p) { p.covariance = Eigen::Matrix3d::Identity() * 1e300; },
      [](FusedPose& p) { p.utime += 3'600'000'000; },
  };
  for (const auto& spoil : hostile) {
    FusedPose pose = good_pose();
    pose.map_T_robot = {3.0, 3.0, 2.0};  // were it used, tracking from here would fail
    pose.utime += 500;
    spoil(pose);
    const std::vector<NodeEvent>& events = node_.on_pose(pose, good_pose().utime + kLatency + 500);
    ASSERT_EQ(events.size(), 1u);
    count(events);
    ++k_;
    const MatcherOutput& out = scan(detections_, kT0 + k_ * kPeriod, k_);
    expect_ok_and_finite(out);
    EXPECT_EQ(out.prior_source, PriorSource::kFusedPose);  // the last good POSE, still fresh
  }
  EXPECT_EQ(counters_["rejected_pose_nonfinite"], 2);
  EXPECT_EQ(counters_["rejected_pose_out_of_bounds"], 1);
  EXPECT_EQ(counters_["rejected_pose_covariance"], 4);
  EXPECT_EQ(counters_["rejected_pose_stamp_ahead"], 1);
}

TEST_F(MatcherHostileInput, ANanPriorAloneNeverProducesAnOk) {
  MatcherNode node(map_, no_startup_window(), mount_);
  FusedPose pose = good_pose();
  pose.map_T_robot.x = kNan;
  EXPECT_EQ(node.on_pose(pose, pose.utime + kLatency).size(), 1u);
  std::vector<ReflectorDetection> three(detections_.begin(), detections_.begin() + 3);
  const MatcherOutput& out = node.on_detections(kT0 + kPeriod, 1, three, kT0 + kPeriod + kLatency);
  ASSERT_TRUE(out.accepted);
  EXPECT_NE(out.prior_source, PriorSource::kFusedPose);
  EXPECT_TRUE(std::isfinite(out.result.map_T_laser.x));
}

TEST_F(MatcherHostileInput, BrokenDetectionsRejectTheWholeMessageAndTheNextScanMatches) {
  for (int i = 0; i < 3; ++i) expect_ok_and_finite(good_scan());
  const std::vector<std::function<void(ReflectorDetection&)>> nonfinite = {
      [](ReflectorDetection& d) { d.laser_p_center.x() = kNan; },
      [](ReflectorDetection& d) { d.covariance(1, 1) = kInf; },
      [](ReflectorDetection& d) { d.range = kNan; },
      [](ReflectorDetection& d) { d.bearing = -kInf; },
      [](ReflectorDetection& d) { d.mean_rssi = kNan; },
  };
  const std::vector<std::function<void(ReflectorDetection&)>> out_of_bounds = {
      [](ReflectorDetection& d) { d.laser_p_center.y() = 1e300; },
      [](ReflectorDetection& d) { d.range = 1e300; },
      [](ReflectorDetection& d) { d.fitted_radius_m = -1.0; },
  };
  const std::vector<std::function<void(ReflectorDetection&)>> covariance = {
      [](ReflectorDetection& d) { d.covariance << 1.0, 2.0, 2.0, 1.0; },  // indefinite
      [](ReflectorDetection& d) { d.covariance *= 1e12; },
  };
  int sent = 0;
  for (const auto* group : {&nonfinite, &out_of_bounds, &covariance}) {
    for (const auto& spoil : *group) {
      std::vector<ReflectorDetection> broken = detections_;
      spoil(broken[1]);
      const MatcherOutput& rejected = scan(broken, kT0 + k_ * kPeriod + kPeriod / 2, 50'000);
      EXPECT_FALSE(rejected.accepted);
      EXPECT_TRUE(rejected.ok());  // an isolated rejection is counted, not a state flip
      ++sent;
      expect_ok_and_finite(good_scan());
    }
  }
  EXPECT_EQ(counters_["rejected_detections_nonfinite"], static_cast<int64_t>(nonfinite.size()));
  EXPECT_EQ(counters_["rejected_detections_out_of_bounds"], static_cast<int64_t>(out_of_bounds.size()));
  EXPECT_EQ(counters_["rejected_detections_covariance"], static_cast<int64_t>(covariance.size()));
  EXPECT_EQ(counters_["gap_detections_messages"], 0);
  EXPECT_EQ(sent, 10);
}

TEST_F(MatcherHostileInput, BadStampsAreRejectedAndMissingScanCountersCounted) {
  for (int i = 0; i < 3; ++i) expect_ok_and_finite(good_scan());
  const int64_t hour = 3'600'000'000;
  for (int64_t stamp : {kT0 + hour, std::numeric_limits<int64_t>::max(), int64_t{0}, kT0 - hour}) {
    EXPECT_FALSE(scan_at(detections_, stamp, k_ + 1, kT0 + k_ * kPeriod + kPeriod / 2).accepted);
    expect_ok_and_finite(good_scan());
  }
  EXPECT_EQ(counters_["rejected_detections_stamp_ahead"], 2);
  EXPECT_EQ(counters_["rejected_detections_stamp_behind"], 2);
  k_ += 3;
  expect_ok_and_finite(good_scan());
  EXPECT_EQ(counters_["gap_detections_messages"], 3);
}

TEST_F(MatcherHostileInput, OnlyRejectedDetectionsForOverASecondDegradeWithTheReason) {
  expect_ok_and_finite(good_scan());
  std::vector<ReflectorDetection> broken = detections_;
  broken[0].laser_p_center.x() = kNan;
  const MatcherOutput* out = nullptr;
  for (int i = 1; i <= 60; ++i) out = &scan(broken, kT0 + (k_ + i) * kPeriod, k_ + i);
  EXPECT_FALSE(out->ok());
  EXPECT_NE(std::string(out->degraded_detail()).find("no usable detections"), std::string::npos);
}

TEST(FusedPoseCheck, ANonOkPoseNeedsNoCovarianceButAFinitePose) {
  FusedPose lost;
  lost.ok = false;
  lost.covariance = Eigen::Matrix3d::Identity() * kNan;
  EXPECT_FALSE(check_fused_pose(lost));
  lost.map_T_robot.x = kNan;
  EXPECT_STREQ(check_fused_pose(lost).reason, "nonfinite");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
