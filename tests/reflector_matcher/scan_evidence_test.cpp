// ScanEvidenceBuilder: from one OK match to evidence (line of sight from the scan, offsets
// from a pose fitted without the reflector, unmapped detections placed with a fit that agrees).

#include "reflector_matcher/scan_evidence.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

// A 270 deg scan at 0.5 deg with every beam at range_m.
LaserScan wall_scan(double range_m) {
  LaserScan scan;
  scan.utime = 1000;
  scan.start_angle = -135.0 * M_PI / 180.0;
  scan.angle_increment = 0.5 * M_PI / 180.0;
  scan.ranges.assign(541, static_cast<float>(range_m));
  return scan;
}

size_t beam_at(const LaserScan& scan, double bearing) {
  return static_cast<size_t>(std::lround((bearing - scan.start_angle) / scan.angle_increment));
}

TEST(ScanLineOfSight, ClearWhenTheBeamsReachTheReflectorsPlaceOrReturnNoEcho) {
  LaserScan scan = wall_scan(8.0);
  EXPECT_TRUE(line_of_sight_clear(scan, 5.0, 0.3, 0.06, 0.15));
  scan.ranges[beam_at(scan, 0.3)] = 0.0f;  // no echo
  EXPECT_TRUE(line_of_sight_clear(scan, 5.0, 0.3, 0.06, 0.15));
  scan.ranges[beam_at(scan, 0.3)] = 4.85f;  // the reflector's own face, were it there
  EXPECT_TRUE(line_of_sight_clear(scan, 5.0, 0.3, 0.06, 0.15));
}

TEST(ScanLineOfSight, HiddenBehindSomethingNearerDazzledOrOutsideTheScan) {
  LaserScan scan = wall_scan(8.0);
  scan.ranges[beam_at(scan, 0.3)] = 3.0f;  // a rack in front
  EXPECT_FALSE(line_of_sight_clear(scan, 5.0, 0.3, 0.06, 0.15));
  scan = wall_scan(8.0);
  scan.ranges[beam_at(scan, 0.3) + 1] = 0.001f;  // dazzled next to it
  EXPECT_FALSE(line_of_sight_clear(scan, 5.0, 0.3, 0.06, 0.15));
  EXPECT_FALSE(line_of_sight_clear(wall_scan(8.0), 5.0, 3.0, 0.06, 0.15));  // behind the scanner
  EXPECT_FALSE(line_of_sight_clear(LaserScan{}, 5.0, 0.3, 0.06, 0.15));
}

ReflectorMap square_map() {
  ReflectorMap map;
  const double xy[][2] = {{4, 0}, {4, 3}, {0, 4}, {-2, 3}, {-4, -1}, {1, -4}};
  for (int i = 0; i < 6; ++i) map.reflectors.push_back({i + 1, {xy[i][0], xy[i][1]}, 0.06, "", std::nullopt});
  return map;
}

ReflectorDetection detection_at(const Pose2& map_T_laser, const Eigen::Vector2d& map_p) {
  ReflectorDetection d;
  d.laser_p_center = map_T_laser.inverse() * map_p;
  d.range = d.laser_p_center.norm();
  d.bearing = std::atan2(d.laser_p_center.y(), d.laser_p_center.x());
  return d;
}

TEST(ScanEvidenceBuilder, MovedReflectorsOffsetIsMeasuredWithoutItAndOthersGetNone) {
  const ReflectorMap map = square_map();
  const Pose2 map_T_laser{0.5, 0.2, 0.1};
  std::vector<ReflectorDetection> detections;
  MatchResult result;
  result.status = MatchStatus::kOk;
  for (int i = 0; i < 5; ++i) {  // ids 1..5 matched; id 2 stands 0.1 m off its mapped place
    const Eigen::Vector2d truth =
        map.reflectors[i].map_p_center + (i == 1 ? Eigen::Vector2d(0.1, 0.0) : Eigen::Vector2d::Zero());
    detections.push_back(detection_at(map_T_laser, truth));
    result.matches.push_back({i, i + 1, map.reflectors[i].map_p_center, 0.06});
  }
  detections.push_back(detection_at(map_T_laser, {2.0, -2.0}));  // unmapped
  result.map_T_laser = map_T_laser;
  ScanEvidenceBuilder builder(map, SensorVisibilityConfig{}, MapHealthConfig{});
  ScanEvidence evidence;
  builder.build(5, detections, result, nullptr, evidence);
  ASSERT_EQ(evidence.seen.size(), 5u);
  for (const ReflectorSighting& s : evidence.seen) {
    if (s.map_index == 1) {
      ASSERT_TRUE(s.has_offset);
      EXPECT_NEAR((s.map_p - map.reflectors[1].map_p_center).x(), 0.1, 1e-9);
    } else {
      EXPECT_FALSE(s.has_offset) << "reflector index " << s.map_index << ": its fit held the moved one";
    }
  }
  ASSERT_EQ(evidence.unmapped.size(), 1u);
  EXPECT_LT((evidence.unmapped[0] - Eigen::Vector2d(2.0, -2.0)).norm(), 1e-9);
  EXPECT_TRUE(evidence.expected_unseen.empty());  // no scan: no evidence of absence
}

TEST(ScanEvidenceBuilder, UnseenReflectorCountsOnlyWithAClearLineOfSight) {
  const ReflectorMap map = square_map();
  const Pose2 map_T_laser{0.0, 0.0, 0.0};
  std::vector<ReflectorDetection> detections;
  MatchResult result;
  result.status = MatchStatus::kOk;
  result.map_T_laser = map_T_laser;
  for (int i : {0, 1, 2, 4}) {  // id 4 (-2, 3) and id 6 (1, -4) unseen
    result.matches.push_back(
        {static_cast<int>(detections.size()), i + 1, map.reflectors[i].map_p_center, 0.06});
    detections.push_back(detection_at(map_T_laser, map.reflectors[i].map_p_center));
  }
  LaserScan scan = wall_scan(10.0);
  const Eigen::Vector2d to6 = map.reflectors[5].map_p_center;
  scan.ranges[beam_at(scan, std::atan2(to6.y(), to6.x()))] = 2.0f;  // something in front of id 6
  ScanEvidenceBuilder builder(map, SensorVisibilityConfig{}, MapHealthConfig{});
  ScanEvidence evidence;
  builder.build(5, detections, result, &scan, evidence);
  ASSERT_EQ(evidence.expected_unseen.size(), 1u);
  EXPECT_EQ(map.reflectors[static_cast<size_t>(evidence.expected_unseen[0])].id, 4);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
