#include "reflector_matcher/matcher_node.hpp"

#include "synthetic_detections.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 50'000'000;

std::map<std::string, int64_t> counters_of(const MatcherOutput& out) {
  std::map<std::string, int64_t> c;
  out.for_each_counter([&](const char* name, int64_t by) { c[name] += by; });
  return c;
}

struct Scene {
  std::mt19937 rng{11};
  ReflectorMap map = testing::random_map(20, 30, 30, 1.0, rng);
  Pose2 mount{0.2, 0.0, 0.0};
  Pose2 map_T_robot{15.0, 15.0, 0.4};
  std::vector<ReflectorDetection> detections =
      testing::render_detections(map, map_T_robot* mount, testing::SyntheticSensor{}, rng).detections;
};

TEST(MatcherNode, StartsWithoutPriorRelocalizesGloballyThenTracksFromTheFusedPose) {
  Scene s;
  MatcherNode node(s.map, MatcherServiceConfig{}, s.mount);
  FusedPose pose;
  pose.utime = kT0;
  pose.map_T_robot = s.map_T_robot;
  pose.covariance = Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal();
  pose.ok = true;
  node.on_pose(pose);

  const MatcherOutput& first = node.on_detections(kT0, s.detections);
  EXPECT_EQ(first.prior_source, PriorSource::kStartupWindow);
  EXPECT_EQ(first.result.status, MatchStatus::kOk);
  EXPECT_EQ(first.result.mode, MatchMode::kGlobal);
  EXPECT_EQ(first.startup_event, StartupEvent::kRelocalized);
  EXPECT_TRUE(first.ok());
  EXPECT_EQ(counters_of(first), (std::map<std::string, int64_t>{{"startup_scans_without_prior", 1},
                                                                {"global_relocalizations", 1}}));

  const MatcherOutput& second = node.on_detections(kT0 + 20'000, s.detections);
  EXPECT_EQ(second.prior_source, PriorSource::kFusedPose);
  EXPECT_EQ(second.result.mode, MatchMode::kTracking);
  EXPECT_EQ(second.result.status, MatchStatus::kOk);
  EXPECT_TRUE(counters_of(second).empty());
}

TEST(MatcherNode, TooFewDetectionsIsLostAndDegradedWithItsDetail) {
  Scene s;
  MatcherServiceConfig config;
  config.prior.relocalize_on_start = 0.0;
  MatcherNode node(s.map, config, s.mount);
  const std::vector<ReflectorDetection> two(s.detections.begin(), s.detections.begin() + 2);
  const MatcherOutput& out = node.on_detections(kT0, two);
  EXPECT_EQ(out.prior_source, PriorSource::kNone);
  EXPECT_EQ(out.result.status, MatchStatus::kLost);
  EXPECT_FALSE(out.ok());
  EXPECT_STREQ(out.degraded_detail(), "last scan LOST");
  EXPECT_EQ(counters_of(out).at("lost_scans"), 1);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
