// Two processes under one service name, from HEARTBEAT alone (common/heartbeat_peers).

#include "common/heartbeat_peers.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace refloc {
namespace {

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

// heartbeat_t as LCM encodes it: fingerprint, utime, service, pid, state, state_detail, uptime_us, ...
std::vector<uint8_t> encoded_heartbeat(int64_t fingerprint, const std::string& service, int32_t pid,
                                       int8_t state, const std::string& detail, int64_t utime,
                                       int64_t uptime_us) {
  std::vector<uint8_t> b;
  auto put = [&b](uint64_t v, int bytes) {
    for (int i = bytes - 1; i >= 0; --i) b.push_back(static_cast<uint8_t>(v >> (8 * i)));
  };
  auto put_string = [&](const std::string& s) {
    put(s.size() + 1, 4);
    b.insert(b.end(), s.begin(), s.end());
    b.push_back(0);
  };
  put(static_cast<uint64_t>(fingerprint), 8);
  put(static_cast<uint64_t>(utime), 8);
  put_string(service);
  put(static_cast<uint32_t>(pid), 4);
  put(static_cast<uint8_t>(state), 1);
  put_string(detail);
  put(static_cast<uint64_t>(uptime_us), 8);
  put(0, 8 * 3);  // messages in/out, decode errors: not read
  return b;
}

constexpr int64_t kFingerprint = 0x1234567890abcdefLL;

TEST(PeekHeartbeatIdentity, ReadsServicePidStateAndStartTime) {
  const auto bytes =
      encoded_heartbeat(kFingerprint, "pose_solver", 4321, 4, "signal 15", 5'000'000, 1'500'000);
  const auto id = peek_heartbeat_identity(bytes.data(), bytes.size(), kFingerprint, 4);
  ASSERT_TRUE(id.has_value());
  EXPECT_EQ(id->service, "pose_solver");
  EXPECT_EQ(id->pid, 4321);
  EXPECT_EQ(id->start_utime, 3'500'000);
  EXPECT_TRUE(id->stopping);
}

TEST(PeekHeartbeatIdentity, RefusesOtherTypesTruncationAndLyingLengths) {
  auto bytes = encoded_heartbeat(kFingerprint, "pose_solver", 1, 1, "", 5, 1);
  EXPECT_FALSE(peek_heartbeat_identity(bytes.data(), bytes.size(), kFingerprint + 1, 4).has_value());
  for (size_t cut = 0; cut < 8 + 8 + 4 + 12 + 4 + 1 + 5 + 8; ++cut)
    EXPECT_FALSE(peek_heartbeat_identity(bytes.data(), cut, kFingerprint, 4).has_value()) << cut;
  bytes[16] = 0x7f;  // service length 2^31-ish
  EXPECT_FALSE(peek_heartbeat_identity(bytes.data(), bytes.size(), kFingerprint, 4).has_value());
  bytes[16] = 0xff;  // negative length
  EXPECT_FALSE(peek_heartbeat_identity(bytes.data(), bytes.size(), kFingerprint, 4).has_value());
}

}  // namespace
}  // namespace refloc
