#include "common/lcm_conversions.hpp"

#include <gtest/gtest.h>

#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(CovarianceConversion, RowMajorRoundTripKeepsAsymmetricEntriesInPlace) {
  Eigen::Matrix3d c;
  c << 1, 2, 3, 4, 5, 6, 7, 8, 9;  // asymmetric on purpose: a transposed copy would show
  pose2d_t pose{};
  covariance_to_lcm(c, pose.covariance);
  EXPECT_EQ(pose.covariance[1], 2.0);
  EXPECT_EQ(pose.covariance[3], 4.0);
  EXPECT_EQ(pose.covariance[8], 9.0);
  EXPECT_EQ(covariance_from_lcm(pose.covariance), c);
  odometry_t odometry{};
  covariance_to_lcm(c, odometry.covariance);
  EXPECT_EQ(covariance_from_lcm(odometry.covariance), c);
}

TEST(ReflectorConversion, DetectionRoundTrip) {
  ReflectorDetection d;
  d.laser_p_center = {2.5, -1.25};
  d.covariance << 4e-5, 1e-6, 1e-6, 9e-5;
  d.range = d.laser_p_center.norm();
  d.bearing = std::atan2(-1.25, 2.5);
  d.utime = 1700000000123456;
  d.first_beam = 17;
  d.num_beams = 5;
  d.mean_rssi = 61234.0;
  d.roundness_m = 0.004;
  d.fitted_radius_m = 0.061;
  const ReflectorDetection back = from_lcm(to_lcm(d));
  EXPECT_EQ(back.laser_p_center, d.laser_p_center);
  EXPECT_EQ(back.covariance, d.covariance);
  EXPECT_EQ(back.utime, d.utime);
  EXPECT_EQ(back.first_beam, d.first_beam);
  EXPECT_EQ(back.num_beams, d.num_beams);
  EXPECT_NEAR(back.fitted_radius_m, d.fitted_radius_m, 1e-7);  // float on the wire
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
