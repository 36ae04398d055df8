#include "roundness_calibration.hpp"
#include "reflector_extractor/synthetic_scan.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(RoundnessCalibration, LineFitRecoversAnExactLineAndRaisesIt) {
  std::vector<RoundnessSample> samples;
  for (double d = 0.25; d <= 4.0; d += 0.25) samples.push_back({d, 0.0, 0.004 + 0.002 * d});
  samples.push_back({5.0, 0.0, 1.0});  // outside the fit range: ignored
  const RoundnessLineFit fit = fit_roundness_line(samples, 0.75, 3.0, 0.03);
  EXPECT_EQ(fit.samples_used, 10);
  EXPECT_NEAR(fit.line.offset, 0.034, 1e-12);
  EXPECT_NEAR(fit.line.slope, 0.002, 1e-12);
  EXPECT_NEAR(fit.residual_rms, 0.0, 1e-12);
}

TEST(RoundnessCalibration, TooFewSamplesGiveNoLine) {
  EXPECT_EQ(fit_roundness_line({{1.0, 0.0, 0.01}}, 0.75, 3.0, 0.03).samples_used, 0);
  EXPECT_EQ(fit_roundness_line({{1.0, 0.0, 0.01}, {1.0, 0.1, 0.02}}, 0.75, 3.0, 0.03).samples_used, 0);
}

TEST(RoundnessCalibration, SimulationGivesThePapers276SetsAndSmallDBar) {
  std::mt19937 rng(4);
  const ReflectorScanRenderer render = [&rng](double distance, double angle, LaserScan& scan) {
    SyntheticScene scene;
    SyntheticCylinder c;
    c.laser_p_center = {distance * std::cos(angle), distance * std::sin(angle)};
    scene.cylinders.push_back(c);
    scan = render_synthetic_scan(scene, SyntheticScanConfig{}, rng);
  };
  const std::vector<RoundnessSample> samples = simulate_roundness_samples(PlacementGrid{}, 1, render);
  EXPECT_EQ(samples.size(), 276u);  // 12 distances x 23 angles, every reflector found
  for (const RoundnessSample& s : samples) {
    EXPECT_GE(s.d_bar, 0.0);
    EXPECT_LT(s.d_bar, 0.03) << s.distance;  // a cylinder never needs the 30 mm margin alone
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
