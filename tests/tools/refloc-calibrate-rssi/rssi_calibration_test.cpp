#include "rssi_calibration.hpp"

#include "reflector_extractor/extractor.hpp"
#include "reflector_extractor/synthetic_scan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::vector<double> sorted_0_to_100() {
  std::vector<double> v;
  for (int i = 0; i <= 100; ++i) v.push_back(i);
  return v;
}

TEST(RssiCalibrationPercentile, InterpolatesLinearlyBetweenRanks) {
  const std::vector<double> v = sorted_0_to_100();
  EXPECT_DOUBLE_EQ(percentile(v, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(percentile(v, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(percentile(v, 99.9), 99.9);
  EXPECT_DOUBLE_EQ(percentile(v, 100.0), 100.0);
  EXPECT_DOUBLE_EQ(percentile({}, 50.0), 0.0);
  EXPECT_DOUBLE_EQ(percentile({7.0}, 99.9), 7.0);
}

TEST(RssiCalibrationRecommendation, MidwayBetweenOtherP999AndReflectorP1WithTheMargins) {
  // Other beams uniform on 20..120, reflector beams uniform on 200..250, at 1.5 m and 5 m.
  std::vector<RssiSample> samples;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> other(20.0, 120.0), reflector(200.0, 250.0);
  for (int i = 0; i < 100'000; ++i) samples.push_back({i % 2 == 0 ? 1.5 : 5.0, other(rng), false});
  for (int i = 0; i < 20'000; ++i) samples.push_back({i % 2 == 0 ? 1.5 : 5.0, reflector(rng), true});
  const RssiCalibration c = calibrate_rssi(samples, {1.0, 2.0, 4.0, 8.0});
  const ThresholdRecommendation& r = c.recommendation;
  ASSERT_TRUE(r.have_both);
  ASSERT_TRUE(r.separable);
  EXPECT_NEAR(r.other_p999, 119.9, 0.1);
  EXPECT_NEAR(r.reflector_p1, 200.5, 0.2);
  EXPECT_NEAR(r.threshold, 160.2, 0.2);
  EXPECT_NEAR(r.margin_below, r.threshold - r.other_p999, 1e-9);
  EXPECT_NEAR(r.margin_above, r.reflector_p1 - r.threshold, 1e-9);
  EXPECT_NEAR(r.margin_below, r.margin_above, 1e-9);
  ASSERT_EQ(c.bands.size(), 5u);
  EXPECT_EQ(c.bands[0].other.count, 0u);
  EXPECT_EQ(c.bands[1].other.count, 50'000u);      // 1..2 m
  EXPECT_EQ(c.bands[3].reflector.count, 10'000u);  // 4..8 m
  EXPECT_TRUE(std::isinf(c.bands[4].range_max));
  EXPECT_NE(rssi_histogram_svg(samples, c).find("threshold 160"), std::string::npos);
  const ThresholdShares at_110 = shares_at(samples, 110.0);  // 10 % of 20..120 is above 110
  EXPECT_NEAR(at_110.other_at_or_above, 0.1, 0.005);
  EXPECT_DOUBLE_EQ(at_110.reflector_below, 0.0);
  EXPECT_NEAR(shares_at(samples, 210.0).reflector_below, 0.2, 0.01);
}

TEST(RssiCalibrationRecommendation, OverlapIsNotSeparableAndNoReflectorIsNoRecommendation) {
  std::vector<RssiSample> samples;
  for (int i = 0; i < 1000; ++i) samples.push_back({2.0, 150.0 + i % 100, false});  // 150..249
  for (int i = 0; i < 1000; ++i) samples.push_back({2.0, 190.0 + i % 60, true});
  const RssiCalibration overlap = calibrate_rssi(samples, {});
  EXPECT_TRUE(overlap.recommendation.have_both);
  EXPECT_FALSE(overlap.recommendation.separable);
  EXPECT_LT(overlap.recommendation.margin_below, 0.0);
  std::vector<RssiSample> only_other(samples.begin(), samples.begin() + 1000);
  EXPECT_FALSE(calibrate_rssi(only_other, {}).recommendation.have_both);
}

TEST(RssiCalibrationLabels, BeamsOnTheExtractedCylinderAreReflectorBeamsTheWallIsNot) {
  SyntheticScene scene;
  SyntheticCylinder cylinder;
  cylinder.laser_p_center = {2.0, 0.0};
  scene.cylinders = {cylinder};
  scene.segments = {{{3.0, -2.0}, {3.0, 2.0}, 60.0}};
  std::mt19937 rng(4);
  const LaserScan scan = render_synthetic_scan(scene, SyntheticScanConfig{}, rng);
  BeamTable table;
  make_beam_table(scan, table);
  ReflectorExtractor extractor;
  const std::vector<ReflectorDetection>& found = extractor.extract(table);
  ASSERT_EQ(found.size(), 1u);
  std::vector<RssiSample> samples;
  const size_t left_out = label_beams(table, found, BeamLabelConfig{}, samples);
  EXPECT_GE(left_out, 1u);  // the cylinder's edge beams
  int on = 0;
  for (const RssiSample& s : samples) {
    if (s.on_reflector) {
      ++on;
      EXPECT_GT(s.rssi_8bit, 130.0);  // 240 * (0.6 .. 1) minus noise
    } else {
      EXPECT_LT(s.rssi_8bit, 80.0);
    }
  }
  EXPECT_GE(on, 3);
  EXPECT_LE(on, found[0].num_beams);
  EXPECT_GT(samples.size() - static_cast<size_t>(on), 50u);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
