#include "beam_crlb.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr double kRadius = 0.06;

ReflectorMap ring_of_reflectors(int n, double ring_radius) {
  ReflectorMap map;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n + 0.3;
    MapReflector r;
    r.id = i + 1;
    r.map_p_center = Eigen::Vector2d(ring_radius * std::cos(a), ring_radius * std::sin(a));
    r.radius = kRadius;
    map.reflectors.push_back(r);
  }
  return map;
}

/// Every 0.5 deg beam from map_T_laser whose axis meets a reflector.
std::vector<ReflectorBeam> beams_on_reflectors(const ReflectorMap& map, const Pose2& map_T_laser) {
  std::vector<ReflectorBeam> beams;
  for (int b = -270; b <= 270; ++b) {
    const double angle = b * 0.5 * M_PI / 180.0;
    for (size_t i = 0; i < map.reflectors.size(); ++i) {
      const auto& r = map.reflectors[i];
      if (std::isfinite(expected_reflector_range(map_T_laser, angle, r.map_p_center, r.radius,
                                                 BeamSpotModel::point_beam()))) {
        beams.push_back({angle, static_cast<int>(i)});
      }
    }
  }
  return beams;
}

TEST(ExpectedReflectorRange, PointBeamMeetsTheCircleOnItsAxis) {
  const Pose2 map_T_laser{0.0, 0.0, 0.0};
  EXPECT_NEAR(expected_reflector_range(map_T_laser, 0.0, {3.0, 0.0}, kRadius, BeamSpotModel::point_beam()),
              3.0 - kRadius, 1e-12);
  // An axis passing `miss` from the centre meets the surface sqrt(R^2 - miss^2) before its foot point.
  const double angle = 0.01;
  const double miss = 3.0 * std::sin(angle);
  const double expected = 3.0 * std::cos(angle) - std::sqrt(kRadius * kRadius - miss * miss);
  EXPECT_NEAR(expected_reflector_range(map_T_laser, angle, {3.0, 0.0}, kRadius, BeamSpotModel::point_beam()),
              expected, 1e-5);
}

TEST(ExpectedReflectorRange, SpotAveragesOverTheCurvedSurfaceBehindTheAxisHit) {
  const Pose2 map_T_laser{0.0, 0.0, 0.0};
  const double point =
      expected_reflector_range(map_T_laser, 0.0, {3.0, 0.0}, kRadius, BeamSpotModel::point_beam());
  const double spot = expected_reflector_range(map_T_laser, 0.0, {3.0, 0.0}, kRadius, BeamSpotModel{});
  // Spot 53 mm wide at 3 m: its rays land on average ~1-2 mm deeper than the axis.
  EXPECT_GT(spot - point, 0.5e-3);
  EXPECT_LT(spot - point, 3e-3);
}

TEST(ExpectedReflectorRange, SpotStillSeesTheReflectorWhenTheAxisJustMissesIt) {
  const Pose2 map_T_laser{0.0, 0.0, 0.0};
  const double angle = std::atan2(kRadius + 0.01, 3.0);  // axis passes 10 mm outside the silhouette
  EXPECT_TRUE(std::isnan(
      expected_reflector_range(map_T_laser, angle, {3.0, 0.0}, kRadius, BeamSpotModel::point_beam())));
  EXPECT_TRUE(
      std::isfinite(expected_reflector_range(map_T_laser, angle, {3.0, 0.0}, kRadius, BeamSpotModel{})));
}

TEST(BeamRangeCrlb, SpotBoundIsLooserThanThePointBeamBound) {
  const ReflectorMap map = ring_of_reflectors(6, 2.5);
  const Pose2 map_T_robot{0.3, -0.2, 0.4};
  const Pose2 robot_T_laser{0.2, 0.0, 0.0};
  const auto beams = beams_on_reflectors(map, map_T_robot * robot_T_laser);
  ASSERT_GE(beams.size(), 12u);
  const auto point =
      beam_range_crlb(map, map_T_robot, robot_T_laser, beams, 0.012, BeamSpotModel::point_beam());
  const auto spot = beam_range_crlb(map, map_T_robot, robot_T_laser, beams, 0.012, BeamSpotModel{});
  ASSERT_TRUE(point && spot);
  const double point_xy = std::sqrt((*point)(0, 0) + (*point)(1, 1));
  const double spot_xy = std::sqrt((*spot)(0, 0) + (*spot)(1, 1));
  EXPECT_GT(spot_xy, point_xy);
  EXPECT_LT(spot_xy, 2.0 * point_xy);  // the spot caps the grazing beams' information, it does not erase it
}

TEST(BeamRangeCrlb, SpotBoundDoesNotDependOnHowFinelyTheSpotIsSampled) {
  const ReflectorMap map = ring_of_reflectors(5, 3.0);
  const Pose2 map_T_robot{-0.1, 0.4, -1.0};
  const Pose2 robot_T_laser{0.0, 0.0, 0.0};
  const auto beams = beams_on_reflectors(map, map_T_robot * robot_T_laser);
  BeamSpotModel coarse, fine;
  coarse.samples = 101;
  fine.samples = 401;
  const auto a = beam_range_crlb(map, map_T_robot, robot_T_laser, beams, 0.012, coarse);
  const auto b = beam_range_crlb(map, map_T_robot, robot_T_laser, beams, 0.012, fine);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR((*a)(0, 0) + (*a)(1, 1), (*b)(0, 0) + (*b)(1, 1), 0.02 * ((*b)(0, 0) + (*b)(1, 1)));
}

TEST(BeamRangeCrlb, FewerThanThreeBeamsGiveNoBound) {
  const ReflectorMap map = ring_of_reflectors(4, 2.0);
  const std::vector<ReflectorBeam> beams{{0.0, 0}, {0.1, 1}};
  EXPECT_FALSE(beam_range_crlb(map, Pose2{}, Pose2{}, beams, 0.012, BeamSpotModel{}).has_value());
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
