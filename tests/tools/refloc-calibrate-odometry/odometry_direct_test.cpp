#include "odometry_direct.hpp"
#include "synthetic_drive.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

OdometryCalibrationResult solve_exact(const test::SyntheticDriveSpec& spec, double segment_s) {
  const CalibrationDrive drive = test::make_synthetic_drive(spec);
  DirectOdometryOptions o;
  o.segment_s = segment_s;
  return calibrate_odometry_exact(drive, spec.nominal, spec.nominal.robot_T_laser, spec.truth.robot_T_laser,
                                  o);
}

// Noise-free fixes: the step-by-step scaled integration is exact on every motion of the profile,
// the 8 s arc included; what is left is the encoders' quantization (29 um per tick).
TEST(OdometryCalibrationExact, NoiseFreeFixesGiveTheScalesWithinFiveMillionths) {
  test::SyntheticDriveSpec spec = test::brief_spec(1.01, 1.02);
  spec.fix_sigma_m = 1e-6;
  spec.fix_sigma_rad = 1e-7;
  for (const double segment_s : {4.0, 20.0, 1000.0}) {
    const OdometryCalibrationResult r = solve_exact(spec, segment_s);
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_NEAR(r.radius_scale / 1.01, 1.0, 5e-6) << segment_s;
    EXPECT_NEAR(r.geometry_scale / 1.02, 1.0, 5e-6) << segment_s;
  }
}

// The end-pose scaling of refloc-calibrate-mount's direct model on the same noise-free drive:
// a segment that turns and then translates (or drives the arc) misplaces the end by (h - 1) x
// angle x distance, which biases the scales.
TEST(OdometryCalibrationExact, TheEndPoseScalingIsBiasedWhereTheStepwiseModelIsNot) {
  test::SyntheticDriveSpec spec = test::brief_spec(1.01, 1.02);
  spec.fix_sigma_m = 1e-6;
  spec.fix_sigma_rad = 1e-7;
  const CalibrationDrive drive = test::make_synthetic_drive(spec);
  const OdometryCalibrationResult endpoint = calibrate_odometry_direct(
      drive, spec.nominal, spec.nominal.robot_T_laser, spec.truth.robot_T_laser, 20.0);
  ASSERT_TRUE(endpoint.ok) << endpoint.message;
  EXPECT_GT(std::abs(endpoint.geometry_scale / 1.02 - 1.0), 1e-4);
}

TEST(OdometryCalibrationExact, NoisyFixesRecoverTheScalesWithinATenthOfAPercentAndTheirSigma) {
  const test::SyntheticDriveSpec spec = test::brief_spec(1.01, 1.02);
  const OdometryCalibrationResult r = solve_exact(spec, 20.0);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_NEAR(r.radius_scale, 1.01, 0.001 * 1.01);
  EXPECT_NEAR(r.geometry_scale, 1.02, 0.001 * 1.02);
  EXPECT_LT(std::abs(r.radius_scale - 1.01), 3.0 * std::sqrt(r.covariance(0, 0)));
  EXPECT_LT(std::abs(r.geometry_scale - 1.02), 3.0 * std::sqrt(r.covariance(1, 1)));
  // Independent fixes: no inflation beyond the sampling noise of the autocorrelation.
  EXPECT_LT(r.correlation_factor, 1.3);
}

// Fix errors with an AR(1) correlation rho between consecutive fixes: their integrated
// autocorrelation is (1 + rho) / (1 - rho) = 3 for rho = 0.5 (in the whitened residuals a
// little less: the segments' start poses absorb part of it).
TEST(OdometryCalibrationExact, CorrelatedFixErrorsInflateTheSigma) {
  test::SyntheticDriveSpec spec = test::brief_spec(1.01, 1.02);
  spec.fix_correlation = 0.5;
  const OdometryCalibrationResult r = solve_exact(spec, 20.0);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_GT(r.correlation_factor, 2.2);
  EXPECT_LT(r.correlation_factor, 3.5);
}

TEST(OdometryCalibrationExact, RefusesADriveThatDoesNotTurnEnough) {
  test::SyntheticDriveSpec spec = test::brief_spec(1.01, 1.02);
  CalibrationDrive drive = test::make_synthetic_drive(spec);
  DirectOdometryOptions o;
  o.min_total_rotation_rad = 100.0;
  const OdometryCalibrationResult r =
      calibrate_odometry_exact(drive, spec.nominal, spec.nominal.robot_T_laser, spec.truth.robot_T_laser, o);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("not observable"), std::string::npos) << r.message;
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
