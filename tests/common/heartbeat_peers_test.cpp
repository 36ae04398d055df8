// Two processes under one service name, from HEARTBEAT alone (common/heartbeat_peers).

#include "common/heartbeat_peers.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

HeartbeatIdentity sender(int32_t pid, int64_t start_utime = 1'000'000'000, bool stopping = false) {
  return {"pose_solver", pid, start_utime, stopping};
}

TEST(DuplicateInstanceDetector, TwoProcessesSendingSideBySideAreDuplicates) {
  DuplicateInstanceDetector d;
  for (int i = 0; i < 3; ++i) {
    d.observe(sender(100), i * 1.0);
    d.observe(sender(200, 2'000'000'000), i * 1.0 + 0.5);
  }
  const auto dup = d.duplicates("pose_solver", 2.5);
  ASSERT_EQ(dup.size(), 2u);
  EXPECT_EQ(dup[0].pid, 100);
  EXPECT_EQ(dup[1].pid, 200);
  EXPECT_EQ(describe_duplicates(dup), "two instances: pid 100, pid 200");
  EXPECT_EQ(d.duplicated_services(2.5), std::vector<std::string>{"pose_solver"});
}

TEST(DuplicateInstanceDetector, DetectedByTheSecondHeartbeatOfTheNewcomer) {
  DuplicateInstanceDetector d;
  d.observe(sender(100), 0.0);
  d.observe(sender(200, 2'000'000'000), 0.5);
  d.observe(sender(100), 1.0);
  EXPECT_TRUE(d.duplicates("pose_solver", 1.0).empty());  // one heartbeat of 200: could be a restart
  d.observe(sender(200, 2'000'000'000), 1.5);
  EXPECT_EQ(d.duplicates("pose_solver", 1.5).size(), 2u);
}

TEST(DuplicateInstanceDetector, RestartAfterKillIsNotADuplicate) {
  DuplicateInstanceDetector d;
  for (int i = 0; i < 5; ++i) d.observe(sender(100), i * 1.0);  // killed after t = 4
  for (int i = 0; i < 5; ++i) d.observe(sender(300, 6'000'000'000), 4.2 + i * 1.0);
  for (double t = 4.2; t < 9.0; t += 0.5) EXPECT_TRUE(d.duplicates("pose_solver", t).empty()) << t;
}

TEST(DuplicateInstanceDetector, CleanStopThenStartIsNotADuplicate) {
  DuplicateInstanceDetector d;
  d.observe(sender(100), 0.0);
  d.observe(sender(100), 1.0);
  d.observe(sender(300, 3'000'000'000), 1.05);       // the successor's first, a hair early
  d.observe(sender(100, 1'000'000'000, true), 1.1);  // the old one's STOPPING heartbeat
  d.observe(sender(300, 3'000'000'000), 2.05);
  EXPECT_TRUE(d.duplicates("pose_solver", 2.1).empty());
}

TEST(DuplicateInstanceDetector, ClearsWhenTheOtherIsNotHeardForTheWindow) {
  DuplicateInstanceDetector d(3.0);
  for (int i = 0; i < 3; ++i) {
    d.observe(sender(100), i * 1.0);
    d.observe(sender(200, 2'000'000'000), i * 1.0 + 0.5);
  }
  for (int i = 3; i < 6; ++i) d.observe(sender(100), i * 1.0);  // 200 went away after 2.5
  EXPECT_EQ(d.duplicates("pose_solver", 5.0).size(), 2u);       // 2.5 s unheard: still within 3 s
  d.observe(sender(100), 6.0);
  EXPECT_TRUE(d.duplicates("pose_solver", 6.0).empty());
}

TEST(DuplicateInstanceDetector, SamePidOnTwoHostsToldApartByStartTime) {
  DuplicateInstanceDetector d;
  for (int i = 0; i < 3; ++i) {
    d.observe(sender(4242, 1'000'000'000), i * 1.0);
    d.observe(sender(4242, 1'500'000'000), i * 1.0 + 0.5);  // started 500 s later elsewhere
  }
  EXPECT_EQ(describe_duplicates(d.duplicates("pose_solver", 2.5)), "two instances: pid 4242, pid 4242");
}

TEST(DuplicateInstanceDetector, StartTimeJitterOfOneProcessIsOneInstance) {
  DuplicateInstanceDetector d;
  for (int i = 0; i < 6; ++i) d.observe(sender(100, 1'000'000'000 + (i % 2) * 900'000), i * 1.0);
  EXPECT_TRUE(d.duplicates("pose_solver", 5.0).empty());
}

TEST(DuplicateInstanceDetector, OtherServicesAreIndependent) {
  DuplicateInstanceDetector d;
  for (int i = 0; i < 3; ++i) {
    d.observe(sender(100), i * 1.0);
    d.observe({"pose_fusion", 200, 2'000'000'000, false}, i * 1.0 + 0.5);
  }
  EXPECT_TRUE(d.duplicated_services(2.5).empty());
}

TEST(DescribeDuplicates, ThreeOrMoreAreCounted) {
  std::vector<HeardInstance> three{{1, 0, 0, 0}, {2, 0, 0, 0}, {3, 0, 0, 0}};
  EXPECT_EQ(describe_duplicates(three), "3 instances: pid 1, pid 2, pid 3");
  EXPECT_EQ(describe_duplicates({three[0]}), "");
}

TEST(OwnNameMonitor, AnotherPidUnderOurNameIsAConflictOurOwnEchoIsNot) {
  OwnNameMonitor own("pose_solver", 100);
  own.observe_own(1'000'000'000, 0.0);
  EXPECT_FALSE(own.observe(sender(100, 1'000'000'010), 0.001));  // our heartbeat looped back
  EXPECT_TRUE(own.observe(sender(200, 2'000'000'000), 0.5));
  own.observe_own(1'000'000'000, 1.0);
  EXPECT_TRUE(own.observe(sender(200, 2'000'000'000), 1.5));
  own.observe_own(1'000'000'000, 2.0);
  EXPECT_EQ(own.conflict(2.0), "two instances: pid 100, pid 200");
  EXPECT_FALSE(own.observe({"pose_fusion", 300, 0, false}, 2.1));
  EXPECT_EQ(own.conflict(6.0), "");  // 200 not heard for 3 s
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
