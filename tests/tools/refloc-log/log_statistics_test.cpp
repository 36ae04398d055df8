// refloc-log statistics on a log written with lcm::LogFile: counts, rates,
// bytes, duration, the largest gap per channel and where, gaps over a threshold.

#include "common/json_config.hpp"
#include "lcm_log_fixture.hpp"
#include "log_analysis.hpp"
#include "log_report.hpp"

#include <refloc/heartbeat_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/twist_t.hpp>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using testing::kT0;

/// POSE at 100 Hz for 2 s with a 0.35 s hole starting at 1.0 s; CMD_VEL at 50 Hz.
std::string write_log_with_hole() {
  const std::string path = testing::temp_path("hole.lcmlog");
  testing::LcmLogWriter log(path);
  EXPECT_TRUE(log.good());
  for (int i = 0; i <= 200; ++i) {
    const int64_t t = kT0 + i * 10'000;
    if (t > kT0 + 1'000'000 && t < kT0 + 1'350'000) continue;
    pose2d_t pose{};
    pose.utime = t;
    log.write("POSE", t, pose);
    if (i % 2 == 0) {
      twist_t cmd{};
      cmd.utime = t;
      log.write("CMD_VEL", t + 1000, cmd);
    }
  }
  return path;
}

const ChannelSummary& channel(const LogSummary& s, const std::string& name) {
  for (const auto& c : s.channels) {
    if (c.channel == name) return c;
  }
  throw std::runtime_error("no channel " + name);
}

TEST(LogStatistics, CountsRatesBytesAndDuration) {
  const MessageDecoder decoder;
  const auto s = analyze_log(write_log_with_hole(), {}, decoder).summary;
  const auto& pose = channel(s, "POSE");
  EXPECT_EQ(pose.count, 201 - 34);  // 1.01 .. 1.34 s are missing
  EXPECT_EQ(pose.type, "pose2d_t");
  EXPECT_EQ(pose.bytes, pose.count * pose2d_t{}.getEncodedSize());
  EXPECT_NEAR(pose.rate_hz, 166.0 / 2.0, 1e-9);
  const auto& cmd = channel(s, "CMD_VEL");
  EXPECT_EQ(cmd.count, 101 - 17);
  EXPECT_EQ(cmd.type, "twist_t");
  EXPECT_EQ(s.events, pose.count + cmd.count);
  EXPECT_NEAR(s.duration_s, 2.001, 1e-9);  // last CMD_VEL is logged 1 ms after the last POSE
  EXPECT_EQ(s.channels.size(), 2u);
}

TEST(LogStatistics, LargestGapAndWhereItStarts) {
  const MessageDecoder decoder;
  const auto s = analyze_log(write_log_with_hole(), {}, decoder).summary;
  const auto& pose = channel(s, "POSE");
  EXPECT_NEAR(pose.largest_gap_s, 0.35, 1e-9);
  EXPECT_NEAR(pose.largest_gap_at_s, 1.0, 1e-9);
  const auto& cmd = channel(s, "CMD_VEL");
  EXPECT_NEAR(cmd.largest_gap_s, 0.36, 1e-9);  // 1.00 -> 1.36 s
  EXPECT_NEAR(cmd.largest_gap_at_s, 1.001, 1e-9);
  EXPECT_NEAR(s.largest_gap_s, 0.349, 1e-9);  // whole log: CMD_VEL at 1.001 s .. POSE at 1.35 s
}

TEST(LogStatistics, GapsOverThresholdAreListedInTimeOrder) {
  const MessageDecoder decoder;
  LogAnalysisOptions options;
  options.gap_threshold_s = 0.3;
  const auto s = analyze_log(write_log_with_hole(), options, decoder).summary;
  ASSERT_EQ(s.gaps.size(), 2u);
  EXPECT_EQ(s.gaps[0].channel, "POSE");
  EXPECT_NEAR(s.gaps[0].start_s, 1.0, 1e-9);
  EXPECT_NEAR(s.gaps[0].length_s, 0.35, 1e-9);
  EXPECT_EQ(s.gaps[1].channel, "CMD_VEL");
  EXPECT_NEAR(s.gaps[1].length_s, 0.36, 1e-9);
  options.gap_threshold_s = 0.355;
  EXPECT_EQ(analyze_log(write_log_with_hole(), options, decoder).summary.gaps.size(), 1u);
  options.gap_threshold_s = 0.5;
  EXPECT_TRUE(analyze_log(write_log_with_hole(), options, decoder).summary.gaps.empty());
}

TEST(LogStatistics, MaxGapsLimitsTheListAndCountsTheRest) {
  LogStatistics stats(0.05, 2);
  for (int i = 0; i < 5; ++i) stats.add("A", kT0 + i * 100'000, 10, i, nullptr);
  const auto s = stats.summary();
  EXPECT_EQ(s.gaps.size(), 2u);
  EXPECT_EQ(s.gaps_not_listed, 2u);
  EXPECT_EQ(s.channels[0].type, "?");
  EXPECT_NEAR(s.channels[0].rate_hz, 10.0, 1e-9);
}

TEST(LogStatistics, SingleMessageChannelHasZeroRateAndGap) {
  LogStatistics stats;
  stats.add("ONCE", kT0, 5, 0, nullptr);
  const auto s = stats.summary();
  EXPECT_EQ(s.channels[0].count, 1);
  EXPECT_EQ(s.channels[0].rate_hz, 0.0);
  EXPECT_EQ(s.channels[0].largest_gap_s, 0.0);
  EXPECT_EQ(s.duration_s, 0.0);
}

TEST(LogStatistics, SummaryTextAndJsonCarryTheNumbers) {
  const MessageDecoder decoder;
  LogAnalysisOptions options;
  options.gap_threshold_s = 0.3;
  const auto s = analyze_log(write_log_with_hole(), options, decoder).summary;
  const std::string text = format_log_summary(s);
  EXPECT_NE(text.find("251 events on 2 channels over 2.001 s"), std::string::npos) << text;
  EXPECT_NE(text.find("83.00"), std::string::npos) << text;  // POSE rate
  EXPECT_NE(text.find("gaps longer than 0.300 s: 2"), std::string::npos) << text;
  const auto j = log_summary_to_json(s);
  EXPECT_EQ(j["events"].get<int>(), 251);
  EXPECT_EQ(j["channels"][1]["channel"], "POSE");
  EXPECT_NEAR(j["channels"][1]["largest_gap_s"].get<double>(), 0.35, 1e-9);
}

TEST(LogStatistics, HeartbeatGapsAreJudgedPerServiceAgainstThreeSeconds) {
  const std::string path = testing::temp_path("heartbeats.lcmlog");
  {
    testing::LcmLogWriter log(path);
    for (int s = 0; s <= 10; ++s) {
      for (const char* service : {"pose_solver", "navigator"}) {
        // navigator is down from 3 s to 8 s: its beats at 4..7 s are missing.
        if (std::string(service) == "navigator" && s > 3 && s < 8) continue;
        heartbeat_t hb{};
        hb.service = service;
        log.write("HEARTBEAT", kT0 + s * 1'000'000 + 1'000, hb);
      }
    }
  }
  const MessageDecoder decoder;
  const auto s = analyze_log(path, {}, decoder).summary;  // threshold 0.5 s < the 1 s heartbeat period
  ASSERT_EQ(s.gaps.size(), 1u);
  EXPECT_EQ(s.gaps[0].channel, "HEARTBEAT(navigator)");
  EXPECT_NEAR(s.gaps[0].start_s, 3.0, 1e-9);
  EXPECT_NEAR(s.gaps[0].length_s, 5.0, 1e-9);
  EXPECT_EQ(channel(s, "HEARTBEAT").count, 11 + 7);
}

TEST(LogReader, MissingFileIsAConfigError) {
  const MessageDecoder decoder;
  EXPECT_THROW(analyze_log("/nonexistent/refloc.lcmlog", {}, decoder), ConfigError);
}

TEST(LogReader, EmptyLogHasNoEvents) {
  const std::string path = testing::temp_path("empty.lcmlog");
  { testing::LcmLogWriter log(path); }
  const MessageDecoder decoder;
  const auto s = analyze_log(path, {}, decoder).summary;
  EXPECT_EQ(s.events, 0);
  EXPECT_EQ(format_log_summary(s), "empty log: no events\n");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
