#include "lms100_driver/link_health.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(LinkHealth, StreamingWithRecentScanIsOk) {
  const LinkVerdict v = judge_link(SessionState::kStreaming, "streaming 50 Hz", 0.02, 5.0);
  EXPECT_EQ(v.level, LinkLevel::kOk);
  EXPECT_EQ(v.detail, "streaming 50 Hz");
}

TEST(LinkHealth, StreamingButSilentForASecondIsDegraded) {
  EXPECT_EQ(judge_link(SessionState::kStreaming, "x", 1.0, 5.0).level, LinkLevel::kDegraded);
}

TEST(LinkHealth, ReconnectingBeforeErrorAfterIsDegraded) {
  EXPECT_EQ(judge_link(SessionState::kBackoff, "retry in 0.5 s", 0.1, 5.0).level, LinkLevel::kDegraded);
  EXPECT_EQ(judge_link(SessionState::kConnecting, "connecting", 4.99, 5.0).level, LinkLevel::kDegraded);
}

TEST(LinkHealth, SilentForErrorAfterIsErrorWithTheSilenceInTheDetail) {
  const LinkVerdict v = judge_link(SessionState::kBackoff, "connect refused", 6.2, 5.0);
  EXPECT_EQ(v.level, LinkLevel::kError);
  EXPECT_EQ(v.detail, "no scan for 6 s: connect refused");
}

TEST(LinkHealth, SilenceCountsFromStartUntilTheFirstScan) {
  LinkHealth health(5.0, 1'000'000);
  health.on_state(SessionState::kConnecting, "connecting");
  EXPECT_EQ(health.verdict(5'900'000).level, LinkLevel::kDegraded);
  EXPECT_EQ(health.verdict(6'100'000).level, LinkLevel::kError);
}

TEST(LinkHealth, ScanResetsSilenceAndStreamingStateMakesOk) {
  LinkHealth health(5.0, 0);
  health.on_state(SessionState::kStreaming, "streaming");
  health.on_scan_published(10'000'000, 150, true);
  EXPECT_EQ(health.verdict(10'500'000).level, LinkLevel::kOk);
  EXPECT_EQ(health.verdict(11'000'000).level, LinkLevel::kDegraded);
  EXPECT_EQ(health.verdict(15'000'000).level, LinkLevel::kError);
}

TEST(LinkHealth, FailedPublishIsCountedAndPublishTimeIsTakenOnce) {
  LinkHealth health(5.0, 0);
  health.on_scan_published(100, 40, false);
  health.on_scan_published(200, 70, true);
  EXPECT_EQ(health.publish_failures(), 1u);
  EXPECT_EQ(health.take_publish_time_us(), 70);
  EXPECT_EQ(health.take_publish_time_us(), 0);
}

TEST(LinkHealth, CountersCarrySessionCountsAndPublishFailuresByName) {
  Lms100SessionCounters c;
  c.reconnects = 3;
  c.lost_scans = 7;
  c.held_scans = 4;
  c.held_scan_max_delay_us = 81'000;
  const auto counters = link_counters(c, 2);
  ASSERT_EQ(counters.size(), 29u);
  EXPECT_STREQ(counters.front().first, "connects");
  std::map<std::string, int64_t> by_name;
  for (const auto& [name, value] : counters) by_name[name] = value;
  EXPECT_EQ(by_name.size(), 29u);  // no name twice
  EXPECT_EQ(by_name.at("reconnects"), 3);
  EXPECT_EQ(by_name.at("lost_scans"), 7);
  EXPECT_EQ(by_name.at("held_scans"), 4);
  EXPECT_EQ(by_name.at("held_scan_max_delay_us"), 81'000);
  EXPECT_EQ(by_name.at("utime_not_increasing"), 0);
  EXPECT_EQ(by_name.at("multi_layer_scans"), 0);
  EXPECT_EQ(by_name.at("publish_failures"), 2);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
