#include "reflector_extractor/motion_compensation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

ReflectorDetection detection_at(double x, double y, int64_t utime) {
  ReflectorDetection d;
  d.laser_p_center = {x, y};
  d.covariance << 4e-4, 0.0, 0.0, 1e-4;
  d.range = std::hypot(x, y);
  d.bearing = std::atan2(y, x);
  d.utime = utime;
  return d;
}

TEST(MotionCompensation, PureTranslationMovesADetectionByVelocityTimesDt) {
  // Seen 10 ms after the reference while driving 1.5 m/s forward and 0.5 m/s left: in the
  // reference frame the point is 15 mm farther ahead and 5 mm farther left.
  std::vector<ReflectorDetection> detections = {detection_at(3.0, 1.0, 1'010'000)};
  compensate_motion(detections, 1'000'000, BodyTwist{1.5, 0.5, 0.0});
  EXPECT_NEAR(detections[0].laser_p_center.x(), 3.015, 1e-12);
  EXPECT_NEAR(detections[0].laser_p_center.y(), 1.005, 1e-12);
  EXPECT_NEAR(detections[0].range, std::hypot(3.015, 1.005), 1e-12);
  EXPECT_EQ(detections[0].utime, 1'010'000);  // the measurement time is kept
}

TEST(MotionCompensation, DetectionAtTheReferenceTimeIsUntouched) {
  std::vector<ReflectorDetection> detections = {detection_at(2.0, -1.0, 5'000)};
  compensate_motion(detections, 5'000, BodyTwist{2.0, 1.0, 1.0});
  EXPECT_DOUBLE_EQ(detections[0].laser_p_center.x(), 2.0);
  EXPECT_DOUBLE_EQ(detections[0].laser_p_center.y(), -1.0);
}

TEST(MotionCompensation, PureRotationRotatesCentreAndCovariance) {
  // 0.5 rad/s for 20 ms = 0.01 rad counter-clockwise: the point appears rotated by +0.01.
  std::vector<ReflectorDetection> detections = {detection_at(4.0, 0.0, 20'000)};
  compensate_motion(detections, 0, BodyTwist{0.0, 0.0, 0.5});
  EXPECT_NEAR(detections[0].laser_p_center.x(), 4.0 * std::cos(0.01), 1e-12);
  EXPECT_NEAR(detections[0].laser_p_center.y(), 4.0 * std::sin(0.01), 1e-12);
  EXPECT_NEAR(detections[0].bearing, 0.01, 1e-12);
  EXPECT_NEAR(detections[0].covariance(0, 1), (4e-4 - 1e-4) * std::sin(0.01) * std::cos(0.01), 1e-15);
}

TEST(MotionCompensation, LaserMotionFollowsTheExactArc) {
  // A quarter circle of radius 2 m: v = 1 m/s, w = 0.5 rad/s for pi seconds.
  const Pose2 end = laser_motion(BodyTwist{1.0, 0.0, 0.5}, Pose2{}, M_PI);
  EXPECT_NEAR(end.x, 2.0, 1e-12);
  EXPECT_NEAR(end.y, 2.0, 1e-12);
  EXPECT_NEAR(end.theta, M_PI / 2, 1e-12);
  const Pose2 tiny = laser_motion(BodyTwist{1.0, 0.0, 1e-9}, Pose2{}, 1.0);
  EXPECT_NEAR(tiny.x, 1.0, 1e-12);
  EXPECT_NEAR(tiny.y, 0.5e-9, 1e-15);
}

TEST(MotionCompensation, OffsetMountSeesTheLeverArmOfARotation) {
  // Laser 0.5 m ahead of the robot centre, robot turning in place at 1 rad/s for 10 ms:
  // the laser translates sideways by ~5 mm as well as rotating.
  const Pose2 robot_T_laser{0.5, 0.0, 0.0};
  const Pose2 motion = laser_motion(BodyTwist{0.0, 0.0, 1.0}, robot_T_laser, 0.01);
  EXPECT_NEAR(motion.theta, 0.01, 1e-12);
  EXPECT_NEAR(motion.x, 0.5 * std::cos(0.01) - 0.5, 1e-12);
  EXPECT_NEAR(motion.y, 0.5 * std::sin(0.01), 1e-12);
  // A robot driving straight moves a laser mounted facing left sideways in its own frame.
  const Pose2 side = laser_motion(BodyTwist{1.0, 0.0, 0.0}, Pose2{0.0, 0.0, M_PI / 2}, 0.1);
  EXPECT_NEAR(side.x, 0.0, 1e-12);
  EXPECT_NEAR(side.y, -0.1, 1e-12);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
