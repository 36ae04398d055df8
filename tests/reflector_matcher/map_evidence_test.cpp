// MapEvidence: what repeated OK scans say about each map reflector and about unmapped ones.
// Scans are built by hand (ScanEvidence) along a straight drive, so each rule is seen alone.

#include "reflector_matcher/map_evidence.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

ReflectorMap line_of_reflectors() {
  ReflectorMap map;
  map.info.map_id = "test_hall";
  map.info.version = 3;
  for (int i = 0; i < 6; ++i) map.reflectors.push_back({i + 1, {2.0 * i, 0.0}, 0.06, "", std::nullopt});
  return map;
}

// A laser driving along y = 2 from x = 0, 1 cm a scan.
Eigen::Vector2d viewpoint(int scan) { return {0.01 * scan, 2.0}; }

// Deterministic small noise, +-2 mm.
Eigen::Vector2d jitter(int scan, int salt) {
  return {0.002 * std::sin(1.7 * scan + salt), 0.002 * std::cos(2.3 * scan + 3 * salt)};
}

// One scan: every reflector but those in `absent` seen at its place + shift, with an offset estimate.
ScanEvidence scan_seeing(const ReflectorMap& map, int scan, const std::vector<int>& absent,
                         const Eigen::Vector2d& shift_of_id2 = Eigen::Vector2d::Zero()) {
  ScanEvidence e;
  e.utime = 1'000'000 + 20'000 * static_cast<int64_t>(scan);
  e.map_p_laser = viewpoint(scan);
  for (size_t i = 0; i < map.reflectors.size(); ++i) {
    const MapReflector& r = map.reflectors[i];
    if (std::find(absent.begin(), absent.end(), r.id) != absent.end()) {
      e.expected_unseen.push_back(static_cast<int>(i));
      continue;
    }
    const Eigen::Vector2d shift = r.id == 2 ? shift_of_id2 : Eigen::Vector2d::Zero();
    e.seen.push_back({static_cast<int>(i), r.map_p_center + shift + jitter(scan, r.id), true});
  }
  return e;
}

const ReflectorHealthEntry& entry(const MapHealthReport& report, int id) {
  for (const ReflectorHealthEntry& e : report.reflectors) {
    if (e.id == id) return e;
  }
  throw std::runtime_error("no reflector " + std::to_string(id));
}

TEST(MapEvidence, ReflectorsSeenWhereMappedAreOkAndTheReportNamesTheMap) {
  const ReflectorMap map = line_of_reflectors();
  MapEvidence evidence(map, MapHealthConfig{});
  for (int s = 0; s < 100; ++s) evidence.add(scan_seeing(map, s, {}));
  MapHealthReport report;
  evidence.report(42, report);
  EXPECT_EQ(report.map_id, "test_hall");
  EXPECT_EQ(report.map_version, 3);
  EXPECT_EQ(report.scans_used, 100);
  EXPECT_EQ(report.count(ReflectorHealth::kOk), 6);
  EXPECT_TRUE(report.candidates.empty());
  EXPECT_LT(entry(report, 3).offset.norm(), 0.002);
  EXPECT_NEAR(entry(report, 3).offset_sigma.x(), 0.005, 0.001);  // the floor dominates
}

TEST(MapEvidence, RemovedReflectorBecomesMissingOnceUnseenFromSpreadViewpoints) {
  const ReflectorMap map = line_of_reflectors();
  const MapHealthConfig config;
  MapEvidence evidence(map, config);
  MapHealthReport report;
  for (int s = 0; s < 30; ++s) evidence.add(scan_seeing(map, s, {}));
  // Removed: expected with a clear sight, unseen. 49 expectations in 0.49 m: not yet.
  for (int s = 30; s < 79; ++s) evidence.add(scan_seeing(map, s, {4}));
  evidence.report(0, report);
  EXPECT_NE(entry(report, 4).state, ReflectorHealth::kMissing);
  for (int s = 79; s < 700; ++s) evidence.add(scan_seeing(map, s, {4}));
  evidence.report(0, report);
  EXPECT_EQ(entry(report, 4).state, ReflectorHealth::kMissing);
  EXPECT_EQ(entry(report, 4).seen, 0);
  EXPECT_EQ(entry(report, 4).expected_missing, config.window_expectations);
  EXPECT_EQ(report.count(ReflectorHealth::kOk), 5);
}

TEST(MapEvidence, ReflectorUnseenFromOneSpotIsNotMissing) {
  const ReflectorMap map = line_of_reflectors();
  MapEvidence evidence(map, MapHealthConfig{});
  for (int s = 0; s < 300; ++s) {
    ScanEvidence e = scan_seeing(map, 0, {4});  // standing still: something may stand in front
    evidence.add(e);
  }
  MapHealthReport report;
  evidence.report(0, report);
  EXPECT_EQ(entry(report, 4).state, ReflectorHealth::kUnconfirmed);
}

TEST(MapEvidence, MovedReflectorIsReportedWithItsOffset) {
  const ReflectorMap map = line_of_reflectors();
  MapEvidence evidence(map, MapHealthConfig{});
  const Eigen::Vector2d moved_by(0.1, -0.02);
  for (int s = 0; s < 200; ++s) evidence.add(scan_seeing(map, s, {}, moved_by));
  MapHealthReport report;
  evidence.report(0, report);
  const ReflectorHealthEntry& r2 = entry(report, 2);
  EXPECT_EQ(r2.state, ReflectorHealth::kMoved);
  EXPECT_NEAR(r2.offset.x(), 0.1, 0.001);
  EXPECT_NEAR(r2.offset.y(), -0.02, 0.001);
  EXPECT_GT(r2.offset_sigma.x(), 0.0);
  EXPECT_EQ(report.count(ReflectorHealth::kMoved), 1);
}

TEST(MapEvidence, SmallConsistentOffsetIsNoMove) {
  const ReflectorMap map = line_of_reflectors();
  MapEvidence evidence(map, MapHealthConfig{});
  for (int s = 0; s < 200; ++s) evidence.add(scan_seeing(map, s, {}, {0.03, 0.0}));  // under 5 cm
  MapHealthReport report;
  evidence.report(0, report);
  EXPECT_EQ(entry(report, 2).state, ReflectorHealth::kOk);
  EXPECT_NEAR(entry(report, 2).offset.x(), 0.03, 0.001);
}

// Unmapped sightings of a cylinder at centre c seen from viewpoint(s), +-2 mm.
void add_unmapped(MapEvidence& evidence, const ReflectorMap& map, int from, int to,
                  const Eigen::Vector2d& c) {
  for (int s = from; s < to; ++s) {
    ScanEvidence e = scan_seeing(map, s, {});
    e.unmapped.push_back(c + jitter(s, 7));
    evidence.add(e);
  }
}

TEST(MapEvidence, UnmappedReflectorSeenRepeatedlyBecomesACandidate) {
  const ReflectorMap map = line_of_reflectors();
  MapEvidence evidence(map, MapHealthConfig{});
  const Eigen::Vector2d c(3.0, 0.5);
  add_unmapped(evidence, map, 0, 20, c);  // 20 sightings over 0.2 m: not yet
  MapHealthReport report;
  evidence.report(0, report);
  EXPECT_TRUE(report.candidates.empty());
  add_unmapped(evidence, map, 20, 100, c);  // 1 m travelled, but seen from directions only 14 deg apart
  evidence.report(0, report);
  EXPECT_TRUE(report.candidates.empty());
  add_unmapped(evidence, map, 100, 250, c);
  evidence.report(0, report);
  ASSERT_EQ(report.candidates.size(), 1u);
  EXPECT_LT((report.candidates[0].map_p - c).norm(), 0.002);
  EXPECT_EQ(report.candidates[0].sightings, 250);
  EXPECT_EQ(report.candidates[0].moved_reflector_id, -1);
  EXPECT_NEAR(report.candidates[0].viewpoint_spread, 2.49, 1e-9);
  EXPECT_EQ(report.new_candidates(), 1);
}

TEST(MapEvidence, AFewStraySightingsDoNotHideACandidate) {
  // Seen from a stretch of the drive, then from one spot (the robot stopped): 1 sighting in 20
  // is 10-14 cm off (a scan placed with a pose off while turning). The plain std dev of all
  // sightings is > 2 cm; the robust spread of the last 64 is the jitter's.
  const ReflectorMap map = line_of_reflectors();
  MapEvidence evidence(map, MapHealthConfig{});
  const Eigen::Vector2d c(3.0, 0.5);
  for (int s = 0; s < 400; ++s) {
    ScanEvidence e = scan_seeing(map, std::min(s, 250), {});
    const Eigen::Vector2d stray =
        s % 20 == 3 ? Eigen::Vector2d(0.09 + 0.0001 * s, -0.04) : Eigen::Vector2d::Zero();
    e.unmapped.push_back(c + jitter(s, 7) + stray);
    evidence.add(e);
  }
  MapHealthReport report;
  evidence.report(0, report);
  ASSERT_EQ(report.candidates.size(), 1u);
  EXPECT_LT((report.candidates[0].map_p - c).norm(), 0.01);
}

TEST(MapEvidence, FlatStripWhoseFittedCentreFollowsTheLineOfSightIsNoCandidate) {
  const ReflectorMap map = line_of_reflectors();
  MapEvidence evidence(map, MapHealthConfig{});
  const Eigen::Vector2d strip(3.0, 0.5);
  for (int s = 0; s < 300; ++s) {
    ScanEvidence e = scan_seeing(map, s, {});
    // The fitted centre lies one radius behind the strip along the line of sight.
    e.unmapped.push_back(strip - 0.06 * (e.map_p_laser - strip).normalized() + jitter(s, 5));
    evidence.add(e);
  }
  MapHealthReport report;
  evidence.report(0, report);
  EXPECT_TRUE(report.candidates.empty());
}

TEST(MapEvidence, MissingReflectorWithACandidateNearItsPlaceMovedThere) {
  const ReflectorMap map = line_of_reflectors();
  MapEvidence evidence(map, MapHealthConfig{});
  const Eigen::Vector2d new_place = map.reflectors[2].map_p_center + Eigen::Vector2d(0.3, 0.1);  // id 3
  for (int s = 0; s < 400; ++s) {
    ScanEvidence e = scan_seeing(map, s, {3});
    e.unmapped.push_back(new_place + jitter(s, 2));
    evidence.add(e);
  }
  MapHealthReport report;
  evidence.report(0, report);
  const ReflectorHealthEntry& r3 = entry(report, 3);
  EXPECT_EQ(r3.state, ReflectorHealth::kMoved);
  EXPECT_NEAR(r3.offset.x(), 0.3, 0.002);
  EXPECT_NEAR(r3.offset.y(), 0.1, 0.002);
  ASSERT_EQ(report.candidates.size(), 1u);
  EXPECT_EQ(report.candidates[0].moved_reflector_id, 3);
  EXPECT_EQ(report.new_candidates(), 0);
}

// The laser drives straight at reflector 3's new place from 6 m: the view turns by < 1 degree,
// far from the 20 the face test needs. Beside a missing reflector that place is its new one
// after candidate_min_sightings; the same cluster with reflector 3 in place stays no candidate.
TEST(MapEvidence, NewPlaceApproachedHeadOnMakesAMissingReflectorMovedWithoutTheFaceTest) {
  const ReflectorMap map = line_of_reflectors();
  const Eigen::Vector2d new_place = map.reflectors[2].map_p_center + Eigen::Vector2d(0.3, 0.0);  // id 3
  const auto drive = [&](const std::vector<int>& absent, MapEvidence& evidence, int scans) {
    for (int s = 0; s < scans; ++s) {
      ScanEvidence e = scan_seeing(map, s, absent);
      e.map_p_laser = new_place + Eigen::Vector2d(0.02, 6.0 - 0.01 * s);  // 1 cm a scan toward it
      e.unmapped.push_back(new_place + jitter(s, 4));
      evidence.add(e);
    }
  };
  MapEvidence moved(map, MapHealthConfig{});
  drive({3}, moved, 100);  // 1 m driven: missing (50 expectations, 0.5 m apart), new place 100 sightings
  MapHealthReport report;
  moved.report(0, report);
  const ReflectorHealthEntry& r3 = entry(report, 3);
  EXPECT_EQ(r3.state, ReflectorHealth::kMoved);
  EXPECT_NEAR(r3.offset.x(), 0.3, 0.003);
  ASSERT_EQ(report.candidates.size(), 1u);
  EXPECT_EQ(report.candidates[0].moved_reflector_id, 3);

  MapEvidence unchanged(map, MapHealthConfig{});
  drive({}, unchanged, 100);
  unchanged.report(0, report);
  EXPECT_TRUE(report.candidates.empty());
  EXPECT_EQ(entry(report, 3).state, ReflectorHealth::kOk);
}

TEST(MapEvidence, ClustersBeyondTheLimitForgetTheStalest) {
  const ReflectorMap map = line_of_reflectors();
  MapHealthConfig config;
  config.max_clusters = 4;
  MapEvidence evidence(map, config);
  for (int k = 0; k < 10; ++k) add_unmapped(evidence, map, 0, 1, {20.0 + k, 5.0});  // ten one-offs
  add_unmapped(evidence, map, 0, 250, {3.0, 0.5});
  MapHealthReport report;
  evidence.report(0, report);
  EXPECT_EQ(report.candidates.size(), 1u);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
