// ClientQueue (bounded, drops counted, a stalled reader seen) and PoseTrail's ring.

#include "web_console/client_queue.hpp"
#include "web_console/pose_trail.hpp"
#include "web_console/rate_decimator.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::shared_ptr<const std::string> text(const std::string& s) {
  return std::make_shared<const std::string>(s);
}

TEST(ClientQueue, FramesBeyondCapacityAreDroppedAndCounted) {
  ClientQueue queue(3);
  for (int i = 0; i < 5; ++i) queue.push(text(std::to_string(i)));
  EXPECT_EQ(queue.size(), 3u);
  EXPECT_EQ(queue.dropped(), 2);
  EXPECT_EQ(*queue.start_write(0), "0") << "the oldest frames are kept, new ones dropped";
}

TEST(ClientQueue, OneWriteAtATimeAndAPendingWriteBeyondTheTimeoutIsAStall) {
  ClientQueue queue(4);
  queue.push(text("a"));
  queue.push(text("b"));
  ASSERT_NE(queue.start_write(1'000'000), nullptr);
  EXPECT_EQ(queue.start_write(1'000'001), nullptr) << "a write is pending";
  EXPECT_FALSE(queue.stalled(5'000'000, 5'000'000));
  EXPECT_TRUE(queue.stalled(6'000'001, 5'000'000));
  queue.write_done();
  EXPECT_FALSE(queue.stalled(9'000'000, 5'000'000)) << "an idle client is not stalled";
  EXPECT_EQ(*queue.start_write(9'000'000), "b");
}

TEST(PoseTrail, KeepsTheNewestPointsOldestFirstAndSkipsSmallSteps) {
  PoseTrail trail(3, 0.1);
  EXPECT_TRUE(trail.add(0.0, 0.0));
  EXPECT_FALSE(trail.add(0.05, 0.0));
  for (int i = 1; i <= 4; ++i) trail.add(0.2 * i, 0.0);
  std::vector<double> xs;
  trail.for_each([&](const std::array<double, 2>& p) { xs.push_back(p[0]); });
  ASSERT_EQ(xs.size(), 3u);
  EXPECT_NEAR(xs[0], 0.4, 1e-12);
  EXPECT_NEAR(xs[2], 0.8, 1e-12);
}

TEST(RateDecimator, AnyStampIsSafeAndALogStartedAgainRestartsIt) {
  RateDecimator rate(10.0);
  EXPECT_TRUE(rate.accept(INT64_MAX));
  EXPECT_TRUE(rate.accept(INT64_MIN)) << "far back: restarted";
  EXPECT_FALSE(rate.accept(INT64_MIN + 1000));
  EXPECT_TRUE(rate.accept(0));
  EXPECT_FALSE(rate.accept(50'000));
  EXPECT_TRUE(rate.accept(100'000));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
