#include "robot_sim/pose_history.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(PoseHistory, InterpolatesBetweenSamplesAndClampsOutside) {
  PoseHistory history(4);
  EXPECT_TRUE(approx_equal(history.at(5), Pose2{}, 0.0, 0.0));
  history.add(1000, {0.0, 0.0, 3.0});
  history.add(2000, {1.0, 2.0, -3.0});  // heading crosses pi: interpolate the short way
  const Pose2 mid = history.at(1500);
  EXPECT_NEAR(mid.x, 0.5, 1e-12);
  EXPECT_NEAR(mid.y, 1.0, 1e-12);
  EXPECT_NEAR(std::abs(mid.theta), M_PI, 1e-12);
  EXPECT_NEAR(history.at(0).x, 0.0, 1e-12);
  EXPECT_NEAR(history.at(9999).x, 1.0, 1e-12);
}

TEST(PoseHistory, KeepsOnlyTheNewestSamples) {
  PoseHistory history(3);
  for (int i = 1; i <= 10; ++i) history.add(i * 1000, {static_cast<double>(i), 0.0, 0.0});
  EXPECT_NEAR(history.at(0).x, 8.0, 1e-12);  // oldest kept
  EXPECT_NEAR(history.at(8500).x, 8.5, 1e-12);
  history.add(5000, {99.0, 0.0, 0.0});  // out of order: ignored
  EXPECT_NEAR(history.at(20000).x, 10.0, 1e-12);
}

TEST(PoseHistory, ConcurrentWriterAndReaderSeeConsistentPoses) {
  PoseHistory history(100);
  std::thread writer([&] {
    for (int i = 1; i <= 20000; ++i) history.add(i, {static_cast<double>(i), 2.0 * i, 0.0});
  });
  for (int i = 0; i < 20000; ++i) {
    const Pose2 p = history.at(i);
    ASSERT_NEAR(p.y, 2.0 * p.x, 1e-9);
  }
  writer.join();
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
