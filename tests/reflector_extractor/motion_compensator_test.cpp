#include "reflector_extractor/motion_compensator.hpp"

#include "reflector_extractor/motion_compensation.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::vector<ReflectorDetection> one_detection(int64_t utime) {
  ReflectorDetection d;
  d.laser_p_center = {3.0, 1.0};
  d.covariance << 4e-4, 0.0, 0.0, 1e-4;
  d.utime = utime;
  return {d};
}

const Pose2 kMount{0.2, 0.0, 0.0};
const OdometrySample kDriving{1'000'000, {1.5, 0.5, 0.2}, Pose2{}, 0.0};

TEST(MotionCompensator, OdometryWithinMaxAgeEitherSideOfTheScanCompensatesExactlyLikeCompensateMotion) {
  MotionCompensator compensator(true, 0.2, kMount);
  compensator.on_odometry(kDriving);
  for (int64_t scan_utime : {800'000, 1'000'000, 1'200'000}) {
    std::vector<ReflectorDetection> got = one_detection(scan_utime + 10'000);
    std::vector<ReflectorDetection> expected = got;
    EXPECT_EQ(compensator.apply(got, scan_utime), CompensationOutcome::kOdometry) << scan_utime;
    compensate_motion(expected, scan_utime, kDriving.twist, kMount);
    EXPECT_EQ(got[0].laser_p_center, expected[0].laser_p_center);
    EXPECT_EQ(got[0].covariance, expected[0].covariance);
  }
}

TEST(MotionCompensator, OdometryOlderOrNewerThanMaxAgeLeavesDetectionsAsMeasured) {
  MotionCompensator compensator(true, 0.2, kMount);
  compensator.on_odometry(kDriving);
  for (int64_t scan_utime : {799'999, 1'200'001}) {
    std::vector<ReflectorDetection> got = one_detection(scan_utime + 10'000);
    EXPECT_EQ(compensator.apply(got, scan_utime), CompensationOutcome::kNoMotionSource);
    EXPECT_EQ(got[0].laser_p_center, Eigen::Vector2d(3.0, 1.0));
  }
}

TEST(MotionCompensator, NoOdometryYetIsNotFresh) {
  MotionCompensator compensator(true, 0.2, kMount);
  std::vector<ReflectorDetection> got = one_detection(10'000);
  EXPECT_FALSE(compensator.fresh(0));
  EXPECT_EQ(compensator.apply(got, 0), CompensationOutcome::kNoMotionSource);
}

TEST(MotionCompensator, DisabledNeverCompensatesNorCountsMissingOdometry) {
  MotionCompensator compensator(false, 0.2, kMount);
  compensator.on_odometry(kDriving);
  std::vector<ReflectorDetection> got = one_detection(1'010'000);
  EXPECT_EQ(compensator.apply(got, 1'000'000), CompensationOutcome::kOff);
  EXPECT_EQ(got[0].laser_p_center, Eigen::Vector2d(3.0, 1.0));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
