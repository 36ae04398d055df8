// The odometry noise model (common/odometry_noise.hpp): variance per metre driven
// and per radian turned, read from one JSON section.

#include "common/odometry_noise.hpp"
#include "common/json_config.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(IncrementCovariance, GrowsWithDistanceAndTurn) {
  const OdometryNoise noise;
  const Eigen::Matrix3d straight = increment_covariance({3.0, 4.0, 0.0}, noise);  // 5 m
  EXPECT_NEAR(straight(0, 0), 5.0 * 1e-4, 1e-15);
  EXPECT_NEAR(straight(1, 1), 5.0 * 1e-4, 1e-15);
  EXPECT_NEAR(straight(2, 2), 5.0 * 1e-5, 1e-15);
  EXPECT_EQ(straight(0, 1), 0.0);
  const Eigen::Matrix3d turn = increment_covariance({0.0, 0.0, -2.0}, noise);  // 2 rad either way
  EXPECT_NEAR(turn(0, 0), 2.0 * 1e-5, 1e-15);
  EXPECT_NEAR(turn(2, 2), 2.0 * 2.5e-4, 1e-15);
  EXPECT_EQ(increment_covariance(Pose2{}, noise), Eigen::Matrix3d::Zero());
}

TEST(ParseOdometryNoise, ReadsTheSectionAndNamesABadKey) {
  const JsonConfig good(nlohmann::json::parse(R"({"odometry_noise": {"translation_variance_m2_per_m": 4e-4,
      "heading_variance_rad2_per_m": 1e-6, "heading_variance_rad2_per_rad": 1e-3,
      "translation_variance_m2_per_rad": 0}})"),
                        "robot.json");
  const OdometryNoise n = parse_odometry_noise(good, "/odometry_noise");
  good.reject_unknown_keys();
  EXPECT_DOUBLE_EQ(n.translation_variance_per_m, 4e-4);
  EXPECT_DOUBLE_EQ(n.heading_variance_per_m, 1e-6);
  EXPECT_DOUBLE_EQ(n.heading_variance_per_rad, 1e-3);
  EXPECT_DOUBLE_EQ(n.translation_variance_per_rad, 0.0);
  const JsonConfig bad(nlohmann::json::parse(R"({"odometry_noise": {"heading_variance_rad2_per_rad": -1}})"),
                       "robot.json");
  try {
    parse_odometry_noise(bad, "/odometry_noise");
    FAIL() << "accepted a negative variance";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("robot.json: /odometry_noise/heading_variance_rad2_per_rad:"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
