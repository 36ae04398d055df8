#include "reflector_extractor/paper_centre.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr double kDeg = M_PI / 180.0;
constexpr double kRadius = 0.06;  // the paper's 120 mm reflector
constexpr double kSigma = 0.012;  // LMS100 range noise [m]

/// Beams of a 0.5 deg scanner (beam i at angle first + i * 0.5 deg) hitting the circle, ideal
/// point beams with Gaussian range noise sigma.
std::vector<FitBeam> circle_beams(const Eigen::Vector2d& center, double sigma, std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<FitBeam> beams;
  for (double angle = -135.0 * kDeg; angle <= 135.0 * kDeg + 1e-9; angle += 0.5 * kDeg) {
    const Eigen::Vector2d u(std::cos(angle), std::sin(angle));
    const double b = u.dot(center);
    const double disc = b * b - center.squaredNorm() + kRadius * kRadius;
    if (disc < 0.0 || b <= 0.0) continue;
    FitBeam beam;
    beam.direction = u;
    beam.range = b - std::sqrt(disc) + (sigma > 0.0 ? noise(rng) : 0.0);
    beam.point = beam.range * u;
    beam.weight = 1.0 / (kSigma * kSigma);
    beams.push_back(beam);
  }
  return beams;
}

TEST(PaperCentre, ReadingsHaveStableNames) {
  EXPECT_STREQ(to_string(PaperCentreReading::kAlgebraicFreeRadius), "kasa");
  EXPECT_STREQ(to_string(PaperCentreReading::kKnownRadius), "known_radius");
  EXPECT_STREQ(to_string(PaperCentreReading::kPolar), "polar");
}

TEST(PaperCentre, KnownRadiusFitIsExactOnNoiseFreeBeams) {
  std::mt19937 rng(1);
  for (const Eigen::Vector2d& center : {Eigen::Vector2d(1.0, 0.2), Eigen::Vector2d(-0.5, 2.5)}) {
    const std::vector<FitBeam> beams = circle_beams(center, 0.0, rng);
    ASSERT_GE(beams.size(), 3u);
    CircleFit fit;
    ASSERT_TRUE(paper_known_radius_centre(beams, kRadius, fit));
    EXPECT_NEAR((fit.center - center).norm(), 0.0, 1e-7);
    EXPECT_DOUBLE_EQ(fit.radius, kRadius);
    EXPECT_NEAR(fit.chi2, 0.0, 1e-6);
  }
}

TEST(PaperCentre, PolarReadingIsTheMeanAngleAndTheCentralRangesPlusTheRadius) {
  // Three beams at 10, 10.5, 11 deg with ranges 2.0, 1.9, 2.1 m: C_theta = 10.5 deg, and with
  // one point dropped each side C_r = 1.9 + 0.06 m.
  std::vector<FitBeam> beams(3);
  const double ranges[3] = {2.0, 1.9, 2.1};
  for (int i = 0; i < 3; ++i) {
    const double a = (10.0 + 0.5 * i) * kDeg;
    FitBeam& b = beams[static_cast<size_t>(i)];
    b.direction = {std::cos(a), std::sin(a)};
    b.range = ranges[i];
    b.point = b.range * b.direction;
  }
  CircleFit fit;
  ASSERT_TRUE(paper_polar_centre(beams, kRadius, 1, kSigma, fit));
  EXPECT_NEAR(std::atan2(fit.center.y(), fit.center.x()), 10.5 * kDeg, 1e-12);
  EXPECT_NEAR(fit.center.norm(), 1.96, 1e-12);
  // Along the line of sight sigma_r^2 / 1 central beam; across (0.5 deg * C_r)^2 / 12.
  const Eigen::Vector2d along = fit.center.normalized();
  const Eigen::Vector2d across(-along.y(), along.x());
  EXPECT_NEAR(along.dot(fit.covariance * along), kSigma * kSigma, 1e-12);
  EXPECT_NEAR(across.dot(fit.covariance * across), std::pow(0.5 * kDeg * 1.96, 2) / 12.0, 1e-12);
  EXPECT_NEAR(across.dot(fit.covariance * along), 0.0, 1e-15);
  // All beams dropped: no reading.
  EXPECT_FALSE(paper_polar_centre(beams, kRadius, 2, kSigma, fit));
}

TEST(PaperCentre, PolarReadingAveragesAcrossThePlusMinusPiSeam) {
  std::vector<FitBeam> beams(3);
  const double angles[3] = {179.5 * kDeg, 180.0 * kDeg, -179.5 * kDeg};
  for (int i = 0; i < 3; ++i) {
    FitBeam& b = beams[static_cast<size_t>(i)];
    b.direction = {std::cos(angles[i]), std::sin(angles[i])};
    b.range = 1.0;
    b.point = b.direction;
  }
  CircleFit fit;
  ASSERT_TRUE(paper_polar_centre(beams, kRadius, 1, kSigma, fit));
  EXPECT_NEAR(fit.center.x(), -1.06, 1e-9);
  EXPECT_NEAR(fit.center.y(), 0.0, 1e-9);
}

/// Centre error over draws at range [m] on ideal point beams (no beam spot, no mixed pixels).
struct ReadingErrors {
  double radial_bias_mm = 0.0;
  double rms_mm = 0.0;
};

ReadingErrors reading_errors(PaperCentreReading reading, double range, int draws) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> bearing(-1.0, 1.0);
  double radial_sum = 0.0, squared_sum = 0.0;
  int fits = 0;
  for (int k = 0; k < draws; ++k) {
    const double b = bearing(rng);
    const Eigen::Vector2d center = range * Eigen::Vector2d(std::cos(b), std::sin(b));
    const std::vector<FitBeam> beams = circle_beams(center, kSigma, rng);
    CircleFit fit;
    bool ok = false;
    if (reading == PaperCentreReading::kAlgebraicFreeRadius) ok = fit_circle_algebraic(beams, kSigma, fit);
    if (reading == PaperCentreReading::kKnownRadius) ok = paper_known_radius_centre(beams, kRadius, fit);
    if (reading == PaperCentreReading::kPolar) ok = paper_polar_centre(beams, kRadius, 1, kSigma, fit);
    if (!ok) continue;
    const Eigen::Vector2d error = fit.center - center;
    radial_sum += error.dot(center.normalized());
    squared_sum += error.squaredNorm();
    ++fits;
  }
  return {1000.0 * radial_sum / fits, 1000.0 * std::sqrt(squared_sum / fits)};
}

TEST(PaperCentre, TheDesignedRadiusMakesTheCentreAccurateWhereTheFreeCircleIsNot) {
  // Ideal ray-circle scans, sigma 12 mm, 1000 draws a range (regenerate:
  // build/bin/reflector_extractor_unit_tests --gtest_filter='PaperCentre.*'): the free circle
  // pulls the centre ~20 mm towards the sensor and scatters it 3-4 x more than the known radius.
  std::printf("range  kasa bias/RMS   known radius bias/RMS   polar bias/RMS [mm]\n");
  for (const double range : {1.0, 2.0, 3.0}) {
    const ReadingErrors kasa = reading_errors(PaperCentreReading::kAlgebraicFreeRadius, range, 1000);
    const ReadingErrors known = reading_errors(PaperCentreReading::kKnownRadius, range, 1000);
    const ReadingErrors polar = reading_errors(PaperCentreReading::kPolar, range, 1000);
    std::printf("%3.1f m  %7.1f / %6.1f   %7.1f / %6.1f   %7.1f / %6.1f\n", range, kasa.radial_bias_mm,
                kasa.rms_mm, known.radial_bias_mm, known.rms_mm, polar.radial_bias_mm, polar.rms_mm);
    EXPECT_LT(std::abs(known.radial_bias_mm), 2.0);
    EXPECT_LT(known.rms_mm, 12.0);
    EXPECT_LT(polar.rms_mm, 14.0);
    EXPECT_GT(polar.radial_bias_mm, 2.0);  // off-axis beams hit the circle behind its front point
    EXPECT_GT(kasa.rms_mm, 2.5 * known.rms_mm);
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
