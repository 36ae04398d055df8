#include "common/log_rate_limiter.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(LogRateLimiter, FiftyLinesASecondBecomeOneWithTheCountHeldBack) {
  LogRateLimiter limiter(1'000'000);
  int written = 0;
  int64_t suppressed = 0;
  int64_t reported_suppressed = 0;
  for (int i = 0; i < 100; ++i) {  // 2 s at 50 Hz
    if (limiter.allow("rejected_odometry_nonfinite", i * 20'000, suppressed)) {
      ++written;
      reported_suppressed += suppressed;
    }
  }
  EXPECT_EQ(written, 2);
  EXPECT_EQ(reported_suppressed, 49);  // the second line says how many the first second held back
}

TEST(LogRateLimiter, KeysAreLimitedIndependently) {
  LogRateLimiter limiter(1'000'000);
  int64_t suppressed = 0;
  EXPECT_TRUE(limiter.allow("a", 0, suppressed));
  EXPECT_TRUE(limiter.allow("b", 1, suppressed));
  EXPECT_FALSE(limiter.allow("a", 2, suppressed));
  EXPECT_TRUE(limiter.allow("a", 1'000'000, suppressed));
  EXPECT_EQ(suppressed, 1);
}

// heartbeat_t::STATE_* (common/ links no LCM types; HeartbeatStateName's test checks the values).
constexpr int8_t kOk = 1, kDegraded = 2, kError = 3, kStopping = 4;

struct WrittenLine {
  StateChangeLogLimiter::Line line;
  bool is_a_change;  ///< from on_change (the line reports a change itself), not on_tick
};

/// A service whose state flaps OK/DEGRADED every 125 ms (8 Hz) from t=0 for duration_us, with the
/// runtime's 1 s tick, then holds DEGRADED for 20 s more: the lines written, on a fake clock.
std::vector<WrittenLine> flapping_lines(int64_t duration_us) {
  StateChangeLogLimiter limiter(10'000'000);
  std::vector<WrittenLine> lines;
  const auto keep = [&](const std::optional<StateChangeLogLimiter::Line>& line, bool is_a_change) {
    if (line) lines.push_back({*line, is_a_change});
  };
  keep(limiter.on_change(kOk, "", 0), true);
  int64_t next_tick_us = 1'000'000;
  for (int64_t t = 125'000; t <= duration_us + 20'000'000; t += 125'000) {
    if (t <= duration_us) {
      const bool degraded = (t / 125'000) % 2 == 1;
      keep(limiter.on_change(degraded ? kDegraded : kOk, degraded ? "last fix DEGRADED" : "", t), true);
    }
    if (t >= next_tick_us) {
      keep(limiter.on_tick(t), false);
      next_tick_us += 1'000'000;
    }
  }
  return lines;
}

TEST(StateChangeLogLimiter, FlappingForSeventySecondsIsEightLinesNotFiveHundred) {
  const int64_t duration_us = 69'875'000;  // 560 changes: the first, then 559 flaps
  const auto lines = flapping_lines(duration_us);
  EXPECT_EQ(lines.size(), 8u);  // the first change, then one line per 10 s
  EXPECT_EQ(lines.front().line.text, "state OK");
  EXPECT_EQ(lines[1].line.text,
            "state OK (79 changes in the last 10 s not logged one by one: 39x OK, 40x DEGRADED)")
      << "the line names the state now and what was held back";
  int64_t reported = 0;
  for (const auto& [line, is_a_change] : lines) {
    const size_t held = line.text.find(" (");
    if (held != std::string::npos) reported += std::stoll(line.text.substr(held + 2));
    reported += is_a_change ? 1 : 0;
    EXPECT_EQ(line.text.find("state 1"), std::string::npos) << "names, not numbers: " << line.text;
    EXPECT_FALSE(line.error);
  }
  EXPECT_EQ(reported, 560) << "every change is in some line";
  EXPECT_EQ(lines.back().line.text.rfind("state DEGRADED: last fix DEGRADED (", 0), 0u)
      << "after the flapping stops, the state it stopped in is logged: " << lines.back().line.text;
}

TEST(StateChangeLogLimiter, ChangesFarApartAreEachLoggedAtOnceWithThePreviousState) {
  StateChangeLogLimiter limiter(10'000'000);
  EXPECT_EQ(limiter.on_change(kOk, "", 0)->text, "state OK");
  const auto degraded = limiter.on_change(kDegraded, "no fix from the last scan", 15'000'000);
  ASSERT_TRUE(degraded);
  EXPECT_EQ(degraded->text, "state DEGRADED (was OK): no fix from the last scan");
  EXPECT_FALSE(limiter.on_tick(40'000'000)) << "nothing held back: no summary";
}

TEST(StateChangeLogLimiter, ErrorAndStoppingAreNeverHeldBackBehindOtherChanges) {
  StateChangeLogLimiter limiter(10'000'000);
  limiter.on_change(kOk, "", 0);
  EXPECT_FALSE(limiter.on_change(kDegraded, "few reflectors", 100'000));
  const auto error = limiter.on_change(kError, "no scan for 5 s", 200'000);
  ASSERT_TRUE(error);
  EXPECT_TRUE(error->error);
  EXPECT_EQ(error->text, "state ERROR (was OK): no scan for 5 s");
  EXPECT_FALSE(limiter.on_change(kOk, "", 300'000));
  EXPECT_FALSE(limiter.on_change(kError, "no scan for 5 s", 400'000)) << "a second ERROR within 10 s waits";
  const auto stopping = limiter.on_change(kStopping, "signal 15", 500'000);
  ASSERT_TRUE(stopping);
  EXPECT_EQ(stopping->text, "state STOPPING (was ERROR): signal 15");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
