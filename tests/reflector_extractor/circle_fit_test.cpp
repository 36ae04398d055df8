#include "reflector_extractor/circle_fit.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <cmath>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr double kDeg = M_PI / 180.0;
constexpr double kSigma = 0.012;  // LMS100 range noise [m]

/// These beams are ideal central rays (no spot), so the fits model them as such; the spot
/// model is tested on rendered scans (extractor_emulator_test).
KnownRadiusFitConfig central_ray_fit() {
  KnownRadiusFitConfig config;
  config.spot.enabled = false;
  return config;
}

/// Beams of a 0.5 deg scanner that hit a circle (centre, radius), with range noise.
std::vector<FitBeam> noisy_beams(const Eigen::Vector2d& center, double radius, double sigma,
                                 std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<FitBeam> beams;
  for (double angle = -135.0 * kDeg; angle <= 135.0 * kDeg + 1e-9; angle += 0.5 * kDeg) {
    const Eigen::Vector2d u(std::cos(angle), std::sin(angle));
    const double b = u.dot(center);
    const double disc = b * b - center.squaredNorm() + radius * radius;
    if (disc < 0.0 || b <= 0.0) continue;  // b <= 0: the circle is behind the sensor
    FitBeam beam;
    beam.direction = u;
    beam.range = b - std::sqrt(disc) + noise(rng);
    beam.point = beam.range * u;
    beam.weight = 1.0 / (kSigma * kSigma);
    beams.push_back(beam);
  }
  return beams;
}

struct FitErrors {
  Eigen::Vector2d mean_error = Eigen::Vector2d::Zero();
  double rms_error = 0.0;
  double mean_nees = 0.0;
  int fits = 0;
};

template <class Fit>
FitErrors run_draws(double range, int draws, Fit fit) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> bearing(-1.0, 1.0);
  FitErrors errors;
  double sum_sq = 0.0;
  for (int k = 0; k < draws; ++k) {
    const double phi = bearing(rng);  // the beam phase relative to the reflector varies too
    const Eigen::Vector2d truth(range * std::cos(phi), range * std::sin(phi));
    const std::vector<FitBeam> beams = noisy_beams(truth, 0.06, kSigma, rng);
    CircleFit result;
    // One beam leaves the centre's lateral position unknown: the extractor never fits it.
    if (beams.size() < 2 || !fit(beams, result)) continue;
    // Error in the frame of the line of sight, so a bias cannot average out over bearings.
    const Eigen::Vector2d radial = truth.normalized();
    const Eigen::Vector2d e = result.center - truth;
    errors.mean_error += Eigen::Vector2d(e.dot(radial), radial.x() * e.y() - radial.y() * e.x());
    sum_sq += e.squaredNorm();
    errors.mean_nees += e.dot(result.covariance.inverse() * e);
    ++errors.fits;
  }
  errors.mean_error /= errors.fits;
  errors.rms_error = std::sqrt(sum_sq / errors.fits);
  errors.mean_nees /= errors.fits;
  return errors;
}

bool known_radius(const std::vector<FitBeam>& beams, CircleFit& out) {
  return fit_circle_known_radius(beams, 0.06, central_ray_fit(), out);
}

bool algebraic(const std::vector<FitBeam>& beams, CircleFit& out) {
  return fit_circle_algebraic(beams, kSigma, out);
}

TEST(CircleFit, KnownRadiusFitIsUnbiasedWithin3mmAt5mWith12mmNoise) {
  const FitErrors e = run_draws(5.0, 4000, known_radius);
  std::printf("known radius at 5 m: bias radial %.2f mm lateral %.2f mm, rms %.2f mm, NEES %.2f\n",
              e.mean_error.x() * 1e3, e.mean_error.y() * 1e3, e.rms_error * 1e3, e.mean_nees);
  EXPECT_GT(e.fits, 3900);
  EXPECT_LT(e.mean_error.norm(), 0.003);
  EXPECT_LT(e.rms_error, 0.016);  // 2-3 beams at 5 m: ~13 mm
}

TEST(CircleFit, KnownRadiusFitBeatsTheAlgebraicFitAt2And5m) {
  for (double range : {2.0, 5.0}) {
    const FitErrors known = run_draws(range, 2000, known_radius);
    const FitErrors free = run_draws(range, 2000, algebraic);
    std::printf("range %.0f m: rms known radius %.1f mm, algebraic %.1f mm (%d fits)\n", range,
                known.rms_error * 1e3, free.rms_error * 1e3, free.fits);
    EXPECT_LT(known.rms_error * 3.0, free.rms_error) << range;
  }
}

TEST(CircleFit, KnownRadiusCovarianceIsConsistentNeesNear2) {
  for (double range : {1.0, 3.0, 5.0, 8.0}) {
    const FitErrors e = run_draws(range, 3000, known_radius);
    std::printf("range %.0f m: mean NEES %.2f (2 expected)\n", range, e.mean_nees);
    EXPECT_GT(e.mean_nees, 1.6) << range;
    EXPECT_LT(e.mean_nees, 2.6) << range;
  }
}

TEST(CircleFit, TwoBeamsPutTheCentreBehindTheSurface) {
  const Eigen::Vector2d truth(9.0, 0.0);
  std::mt19937 rng(1);
  std::vector<FitBeam> beams = noisy_beams(truth, 0.06, 0.0, rng);
  ASSERT_GE(beams.size(), 1u);
  CircleFit out;
  ASSERT_TRUE(known_radius(beams, out));
  EXPECT_GT(out.center.norm(), beams.front().range);
  EXPECT_NEAR((out.center - truth).norm(), 0.0, 1e-3) << beams.size() << " beams";
}

TEST(CircleFit, AlgebraicFitRecoversAnExactCircle) {
  std::mt19937 rng(1);
  const std::vector<FitBeam> beams = noisy_beams({1.0, 0.5}, 0.06, 0.0, rng);
  CircleFit out;
  ASSERT_TRUE(fit_circle_algebraic(beams, kSigma, out));
  EXPECT_NEAR(out.center.x(), 1.0, 1e-9);
  EXPECT_NEAR(out.center.y(), 0.5, 1e-9);
  EXPECT_NEAR(out.radius, 0.06, 1e-9);
}

TEST(CircleFit, FreeRadiusFitFindsTheTrueRadiusOfA10cmCylinder) {
  std::mt19937 rng(1);
  const std::vector<FitBeam> beams = noisy_beams({1.0, 0.0}, 0.10, 0.0, rng);
  CircleFit known;
  ASSERT_TRUE(known_radius(beams, known));
  CircleFit out;
  ASSERT_TRUE(fit_circle_free_radius(beams, known.center, known.radius, central_ray_fit(), out));
  EXPECT_NEAR(out.radius, 0.10, 1e-6);
  EXPECT_NEAR(out.center.x(), 1.0, 1e-6);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
