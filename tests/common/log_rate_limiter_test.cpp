#include "common/log_rate_limiter.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace {

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

}  // namespace
}  // namespace refloc
