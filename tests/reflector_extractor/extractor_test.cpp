#include "reflector_extractor/extractor.hpp"

#include "reflector_extractor/energy_filter.hpp"
#include "scenes.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr double kDeg = M_PI / 180.0;

LaserScan render(const SyntheticScene& scene, uint32_t seed) {
  std::mt19937 rng(seed);
  return render_synthetic_scan(scene, SyntheticScanConfig{}, rng);
}

TEST(ReflectorExtractor, FindsACylinderAndFillsEveryField) {
  SyntheticScene scene;
  scene.cylinders = {test::cylinder_at(2.0, 20.0 * kDeg)};
  scene.segments = {test::dull_wall_behind(2.0, 20.0 * kDeg)};
  const LaserScan scan = render(scene, 3);
  ReflectorExtractor extractor;
  const std::vector<ReflectorDetection>& detections = extractor.extract(scan);
  ASSERT_EQ(detections.size(), 1u);
  const ReflectorDetection& d = detections[0];
  EXPECT_NEAR((d.laser_p_center - test::polar(2.0, 20.0 * kDeg)).norm(), 0.0, 0.015);
  EXPECT_NEAR(d.range, d.laser_p_center.norm(), 1e-12);
  EXPECT_NEAR(d.bearing, std::atan2(d.laser_p_center.y(), d.laser_p_center.x()), 1e-12);
  // 0.12 m at 2 m subtends 3.4 deg: 6 or 7 beams at 0.5 deg.
  EXPECT_GE(d.num_beams, 6);
  EXPECT_LE(d.num_beams, 8);
  const int middle = d.first_beam + (d.num_beams - 1) / 2;
  EXPECT_NEAR(static_cast<double>(d.utime), static_cast<double>(scan.beam_utime(static_cast<size_t>(middle))),
              30.0);
  EXPECT_GT(d.mean_rssi, 180.0);
  EXPECT_DOUBLE_EQ(d.fitted_radius_m > 0.0, true);
  EXPECT_GT(d.covariance.determinant(), 0.0);
  EXPECT_EQ(extractor.stats().clusters_considered, 1);
  EXPECT_EQ(extractor.stats().rejected(), 0);
}

TEST(ReflectorExtractor, EightReflectorsAroundTheSensorAreAllFound) {
  SyntheticScene scene;
  for (int k = 0; k < 8; ++k)
    scene.cylinders.push_back(test::cylinder_at(1.0 + 0.5 * k, (-120.0 + 30.0 * k) * kDeg));
  int found = 0;
  ReflectorExtractor extractor;
  for (uint32_t seed = 0; seed < 50; ++seed)
    found += static_cast<int>(extractor.extract(render(scene, seed)).size());
  EXPECT_GE(found, 8 * 50 * 95 / 100);  // the flat-surface test costs ~2 % at 3-5 beams
  EXPECT_LE(found, 8 * 50);
}

TEST(ReflectorExtractor, WideBrightStripsAndPlatesAreRejected) {
  ReflectorExtractor extractor;
  int accepted = 0;
  int trials = 0;
  for (double range = 0.5; range <= 9.0; range += 0.5) {
    for (uint32_t seed = 0; seed < 10; ++seed) {
      SyntheticScene scene;
      scene.segments = {test::flat_strip(range, 0.1 * seed, 0.3, 240.0, 0.05 * seed),
                        test::dull_wall_behind(range, 0.1 * seed)};
      accepted += static_cast<int>(extractor.extract(render(scene, seed)).size());
      ++trials;
    }
  }
  EXPECT_EQ(accepted, 0) << "of " << trials;
}

TEST(ReflectorExtractor, OccludedReflectorIsRejected) {
  // A dull box edge 1 m in front hides the left half of the reflector.
  SyntheticScene scene;
  scene.cylinders = {test::cylinder_at(3.0, 0.0)};
  scene.segments = {SyntheticSegment{{2.0, 0.0}, {2.0, 1.0}, 60.0}};
  ReflectorExtractor extractor;
  EXPECT_TRUE(extractor.extract(render(scene, 1)).empty());
  EXPECT_EQ(extractor.stats().rejected_occluded, 1);
  ExtractorConfig keep;
  keep.reject_occluded = false;
  ReflectorExtractor lenient(keep);
  lenient.extract(render(scene, 1));
  EXPECT_EQ(lenient.stats().rejected_occluded, 0);
  // What is left visible is too narrow for a whole cylinder anyway.
  EXPECT_EQ(lenient.stats().rejected_too_narrow, 1);
}

TEST(ReflectorExtractor, ReflectorNextToADazzledBeamIsRejected) {
  SyntheticScene scene;
  scene.cylinders = {test::cylinder_at(1.0, 0.0)};
  LaserScan scan = render(scene, 1);
  ReflectorExtractor extractor;
  const std::vector<ReflectorDetection> clean = extractor.extract(scan);
  ASSERT_EQ(clean.size(), 1u);
  scan.ranges[static_cast<size_t>(clean[0].first_beam - 1)] = 0.001f;  // sensor code 1
  EXPECT_TRUE(extractor.extract(scan).empty());
  EXPECT_EQ(extractor.stats().rejected_occluded, 1);
}

TEST(ReflectorExtractor, ClustersOfOneBeamAreRejectedByDefault) {
  // 0.12 m at 14 m subtends less than one 0.5 deg step.
  SyntheticScene scene;
  scene.cylinders = {test::cylinder_at(14.0, 0.0)};
  ReflectorExtractor extractor;
  int single = 0;
  for (uint32_t seed = 0; seed < 20; ++seed) {
    EXPECT_TRUE(extractor.extract(render(scene, seed)).empty());
    single += extractor.stats().rejected_too_few_beams;
  }
  EXPECT_GT(single, 0);
}

TEST(ReflectorExtractor, WithMinBeams1AFarSingleBeamGetsABeamStepWideCovariance) {
  SyntheticScene scene;
  scene.cylinders = {test::cylinder_at(14.0, 0.3)};
  ExtractorConfig config;
  config.min_beams = 1;
  ReflectorExtractor extractor(config);
  for (uint32_t seed = 0; seed < 20; ++seed) {
    const std::vector<ReflectorDetection>& detections = extractor.extract(render(scene, seed));
    if (detections.empty() || detections[0].num_beams != 1) continue;
    const ReflectorDetection& d = detections[0];
    const Eigen::Vector2d along = d.laser_p_center.normalized();
    const Eigen::Vector2d across(-along.y(), along.x());
    const double step = 0.5 * kDeg * d.range;
    EXPECT_NEAR(along.dot(d.covariance * along), 0.012 * 0.012, 1e-9);
    EXPECT_NEAR(across.dot(d.covariance * across), step * step / 12.0 + std::pow(0.002 * d.range, 2), 1e-9);
    return;
  }
  FAIL() << "no single-beam detection in 20 scans";
}

TEST(ReflectorExtractor, EveryBrightClusterIsRecordedWithItsOutcomeInBeamOrder) {
  // Left to right in the scan (beams run counter-clockwise): a reflector far enough for one beam,
  // a bright tape strip, a reflector, a reflector half hidden behind a box edge.
  SyntheticScene scene;
  scene.cylinders = {test::cylinder_at(16.0, -60.0 * kDeg), test::cylinder_at(3.0, 20.0 * kDeg),
                     test::cylinder_at(3.0, 90.0 * kDeg)};
  scene.segments = {test::flat_strip(2.0, -20.0 * kDeg, 0.3, 240.0, 0.0),
                    SyntheticSegment{{-0.2, 2.0}, {0.0, 2.0}, 60.0}};
  ReflectorExtractor extractor;
  const std::vector<ReflectorDetection>& detections = extractor.extract(render(scene, 3));
  const std::vector<ClusterRecord>& clusters = extractor.clusters();
  ASSERT_EQ(clusters.size(), 4u);
  EXPECT_EQ(clusters[0].outcome, ClusterOutcome::kTooFewBeams);
  EXPECT_NE(clusters[1].outcome, ClusterOutcome::kAccepted) << cluster_outcome_name(clusters[1].outcome);
  EXPECT_EQ(clusters[2].outcome, ClusterOutcome::kAccepted);
  EXPECT_EQ(clusters[3].outcome, ClusterOutcome::kOccluded);
  EXPECT_EQ(extractor.stats().clusters_considered, 4);
  EXPECT_EQ(extractor.stats().rejected(), 3);
  // The accepted ones are the detections, in order; every record says where it is.
  ASSERT_EQ(detections.size(), 1u);
  EXPECT_EQ(clusters[2].first_beam, detections[0].first_beam);
  EXPECT_EQ(clusters[2].num_beams, detections[0].num_beams);
  EXPECT_NEAR(clusters[2].range, 3.0 - 0.06, 0.03);  // the front of the cylinder
  EXPECT_NEAR(clusters[2].bearing, 20.0 * kDeg, 0.5 * kDeg);
  EXPECT_NEAR(clusters[0].range, 16.0 - 0.06, 0.06);
  int previous_last = -1;
  for (const ClusterRecord& c : clusters) {
    EXPECT_GT(c.first_beam, previous_last);
    EXPECT_GE(c.last_beam, c.first_beam);
    EXPECT_GE(c.max_rssi_8bit, ExtractorConfig{}.energy_threshold_8bit);
    previous_last = c.last_beam;
  }
  // A scan without bright beams leaves no record from the one before.
  extractor.extract(render(SyntheticScene{}, 4));
  EXPECT_TRUE(extractor.clusters().empty());
}

TEST(ReflectorExtractor, ExtractDoesNotReallocateItsOutputOnceWarm) {
  SyntheticScene scene;
  for (int k = 0; k < 8; ++k)
    scene.cylinders.push_back(test::cylinder_at(2.0 + k, (-100.0 + 25.0 * k) * kDeg));
  const LaserScan scan = render(scene, 9);
  ReflectorExtractor extractor;
  const ReflectorDetection* first = extractor.extract(scan).data();
  for (int k = 0; k < 10; ++k) EXPECT_EQ(extractor.extract(scan).data(), first);
}

TEST(ReflectorExtractor, RandomGarbageScansGiveFiniteDetectionsOnly) {
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_real_distribution<float> range(0.0f, 25.0f);
  std::uniform_int_distribution<int32_t> rssi(0, 65535);
  ReflectorExtractor default_mode;
  ReflectorExtractor paper_mode(ExtractorConfig::paper());
  LaserScan scan;
  scan.start_angle = -135.0 * kDeg;
  scan.angle_increment = 0.5 * kDeg;
  scan.rssi_bits = 16;
  size_t total = 0;
  for (int k = 0; k < 2000; ++k) {
    const int n = k % 7 == 0 ? k % 5 : 541;
    scan.ranges.resize(static_cast<size_t>(n));
    scan.rssi.resize(static_cast<size_t>(n));
    float previous = 2.0f;
    for (int i = 0; i < n; ++i) {
      const int what = kind(rng);
      // Mostly smooth runs (so clusters form), with no-echo, dazzled, NaN and jumps.
      float r = what < 6 ? previous + 0.01f * (range(rng) - 12.5f) / 12.5f : range(rng);
      if (what == 7) r = 0.0f;
      if (what == 8) r = 0.001f;
      if (what == 9 && k % 3 == 0) r = std::nanf("");
      scan.ranges[static_cast<size_t>(i)] = r;
      if (std::isfinite(r)) previous = r;
      scan.rssi[static_cast<size_t>(i)] = what < 5 ? 60000 : rssi(rng);
    }
    for (ReflectorExtractor* extractor : {&default_mode, &paper_mode}) {
      for (const ReflectorDetection& d : extractor->extract(scan)) {
        ASSERT_TRUE(d.laser_p_center.allFinite());
        ASSERT_TRUE(d.covariance.allFinite());
        ASSERT_GE(d.covariance(0, 0), 0.0);
        ASSERT_GE(d.covariance(1, 1), 0.0);
        ++total;
      }
    }
  }
  std::printf("%zu detections in 4000 garbage extractions\n", total);
}

// --- Paper mode (§3.2-3.4) ---

TEST(PaperMode, UsesThePapersThresholdAndDropsOnePointEachSide) {
  const ExtractorConfig paper = ExtractorConfig::paper();
  EXPECT_EQ(paper.mode, ExtractorConfig::Mode::kPaper);
  EXPECT_DOUBLE_EQ(paper.energy_threshold_8bit, 180.0);
  EXPECT_EQ(paper.paper_drop_points, 1);
  EXPECT_EQ(paper.paper_centre, PaperCentreReading::kKnownRadius);  // the designed 120 mm diameter
  EXPECT_NEAR(paper.clustering.lambda, 10.0 * kDeg, 1e-12);
  EXPECT_DOUBLE_EQ(paper.clustering.range_sigma, 0.012);
}

TEST(PaperMode, RoundnessIndexLeavesOutTheFirstAndLastNPoints) {
  // Five points, the outer two 50 mm off the circle, the inner three 2, 4 and 6 mm.
  std::vector<FitBeam> beams(5);
  const double offsets[5] = {0.05, 0.002, -0.004, 0.006, -0.05};
  for (int i = 0; i < 5; ++i) {
    const double a = (-60.0 + 30.0 * i) * kDeg;
    beams[static_cast<size_t>(i)].point = (0.06 + offsets[i]) * Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  EXPECT_NEAR(paper_roundness_index(beams, Eigen::Vector2d::Zero(), 0.06, 1), 0.004, 1e-12);
  EXPECT_NEAR(paper_roundness_index(beams, Eigen::Vector2d::Zero(), 0.06, 0), 0.112 / 5.0, 1e-12);
  EXPECT_LT(paper_roundness_index(beams, Eigen::Vector2d::Zero(), 0.06, 3), 0.0);
}

TEST(PaperMode, CentreIsTheKnownRadiusFitOfTheClusterAndDBarIsReported) {
  SyntheticScene scene;
  scene.cylinders = {test::cylinder_at(1.0, 0.0)};
  const LaserScan scan = render(scene, 5);
  ExtractorConfig config = ExtractorConfig::paper();
  config.paper_roundness.offset = 1.0;  // accept anything round-ish: this test is about the fit
  ReflectorExtractor extractor(config);
  const std::vector<ReflectorDetection>& detections = extractor.extract(scan);
  ASSERT_EQ(detections.size(), 1u);
  std::vector<FitBeam> beams;
  for (int i = detections[0].first_beam; i < detections[0].first_beam + detections[0].num_beams; ++i) {
    FitBeam b;
    const double a = scan.beam_angle(static_cast<size_t>(i));
    b.point =
        static_cast<double>(scan.ranges[static_cast<size_t>(i)]) * Eigen::Vector2d(std::cos(a), std::sin(a));
    beams.push_back(b);
  }
  CircleFit fit;
  ASSERT_TRUE(paper_known_radius_centre(beams, 0.06, fit));
  EXPECT_NEAR((detections[0].laser_p_center - fit.center).norm(), 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(detections[0].fitted_radius_m, 0.06);
  EXPECT_LT((detections[0].laser_p_center - Eigen::Vector2d(1.0, 0.0)).norm(), 0.02);
  EXPECT_NEAR(detections[0].roundness_m, paper_roundness_index(beams, fit.center, fit.radius, 1), 1e-12);
}

TEST(PaperMode, EnergyJustBelow180IsScreenedOut) {
  SyntheticScene scene;
  scene.cylinders = {test::cylinder_at(1.0, 0.0)};
  LaserScan scan = render(scene, 5);
  ReflectorExtractor extractor(ExtractorConfig::paper());
  ASSERT_EQ(extractor.extract(scan).size(), 1u);
  for (int32_t& r : scan.rssi) r = std::min(r, 179 * 257 + 256);  // 179.99 on the 8-bit scale
  EXPECT_TRUE(extractor.extract(scan).empty());
  EXPECT_EQ(extractor.stats().clusters_considered, 0);
}

TEST(PaperMode, DBarAboveTheLineIsRejected) {
  SyntheticScene scene;
  scene.cylinders = {test::cylinder_at(1.0, 0.0)};
  const LaserScan scan = render(scene, 5);
  ExtractorConfig config = ExtractorConfig::paper();
  config.paper_roundness.offset = 0.0;
  config.paper_roundness.slope = 0.0;  // nothing noisy is that round
  ReflectorExtractor extractor(config);
  EXPECT_TRUE(extractor.extract(scan).empty());
  EXPECT_EQ(extractor.stats().rejected_not_round, 1);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
