// Longer than 300 lines because every study on the renderer's scans shares its scene helpers.
// Accuracy and distractor rejection on scans from the LMS100 emulator's renderer
// (services/lms100_emulator): Gaussian beam spot 15 mrad wide, mixed pixels, coverage-
// proportional RSSI, reflective tape and specular metal. The curves are printed so the
// numbers in the README can be regenerated.

#include "reflector_extractor/extractor.hpp"
#include "world_renderer/scan_render_beam.hpp"
#include "world_renderer/scan_renderer.hpp"
#include "world_renderer/world_loader.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using sim::SurfaceKind;

Eigen::Vector2d polar(double range, double bearing) {
  return {range * std::cos(bearing), range * std::sin(bearing)};
}

sim::WorldSegment strip(double range, double bearing, double width, double yaw, SurfaceKind kind) {
  const Eigen::Vector2d center = polar(range, bearing);
  const Eigen::Vector2d along(-std::sin(bearing + yaw), std::cos(bearing + yaw));
  return sim::WorldSegment{center - 0.5 * width * along, center + 0.5 * width * along, kind, 0.5};
}

enum class Target { kCylinder, kTape12cm, kTape30cm, kMetal30cm };

struct Outcome {
  double accepted = 0.0;   ///< share of scans with a detection
  double rms_error = 0.0;  ///< of accepted cylinder centres [m]
  double mean_nees = 0.0;
  double mean_radial_error = 0.0;  ///< mean of |centre| - true range [m] (long is positive)
  double radial_error_sd = 0.0;    ///< its spread over the fits [m]
  int fits = 0;
};

/// wall_behind_m: the diffuse wall's distance behind the target's centre (1 m: beyond the echo
/// merge distance, no mixed pixels with it; ~0.1 m: a reflector mounted on a wall).
Outcome run(Target target, double range, int scans, const ExtractorConfig& config, uint64_t seed,
            double wall_behind_m = 1.0) {
  ReflectorExtractor extractor(config);
  sim::ScanRenderer renderer;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> bearing_draw(-1.5, 1.5);
  std::uniform_real_distribution<double> yaw_draw(-0.5, 0.5);
  LaserScan scan;
  Outcome out;
  double sum_sq = 0.0;
  for (int k = 0; k < scans; ++k) {
    const double bearing = bearing_draw(rng);
    sim::World world;
    switch (target) {
      case Target::kCylinder: {
        MapReflector reflector;
        reflector.id = 1;
        reflector.map_p_center = polar(range, bearing);
        world.reflectors.reflectors.push_back(reflector);
        break;
      }
      case Target::kTape12cm:
        world.segments.push_back(strip(range, bearing, 0.12, 0.0, SurfaceKind::kReflectiveTape));
        break;
      case Target::kTape30cm:
        world.segments.push_back(strip(range, bearing, 0.30, yaw_draw(rng), SurfaceKind::kReflectiveTape));
        break;
      case Target::kMetal30cm:
        world.segments.push_back(strip(range, bearing, 0.30, 0.1 * yaw_draw(rng), SurfaceKind::kMetal));
        break;
    }
    sim::WorldSegment wall = strip(range + wall_behind_m, bearing, 4.0, 0.0, SurfaceKind::kDiffuse);
    wall.remission = 0.6;
    world.segments.push_back(wall);
    renderer.render(world, Pose2{}, 1'000'000, rng, scan);
    const std::vector<ReflectorDetection>& detections = extractor.extract(scan);
    if (detections.empty()) continue;
    out.accepted += 1.0;
    if (target == Target::kCylinder && detections.size() == 1) {
      const Eigen::Vector2d e = detections[0].laser_p_center - polar(range, bearing);
      sum_sq += e.squaredNorm();
      const double radial = detections[0].laser_p_center.norm() - range;
      out.mean_radial_error += radial;
      out.radial_error_sd += radial * radial;
      out.mean_nees += e.dot(detections[0].covariance.inverse() * e);
      ++out.fits;
    }
  }
  out.accepted /= scans;
  if (out.fits > 0) {
    out.rms_error = std::sqrt(sum_sq / out.fits);
    out.mean_nees /= out.fits;
    out.mean_radial_error /= out.fits;
    out.radial_error_sd = std::sqrt(
        std::max(out.radial_error_sd / out.fits - out.mean_radial_error * out.mean_radial_error, 0.0));
  }
  return out;
}

TEST(ExtractorOnEmulatorScans, CylindersAreFoundUpTo4p5mAndTheCurveBeyondIsReported) {
  const ExtractorConfig config;
  for (double range : {0.5, 1.0, 1.5, 2.0, 3.0, 4.5, 6.0, 7.5, 9.0, 12.0, 15.0}) {
    const Outcome o = run(Target::kCylinder, range, 200, config, 11);
    std::printf("cylinder %5.1f m: recall %5.1f %%  rms %5.1f mm  NEES %.2f\n", range, 100.0 * o.accepted,
                1e3 * o.rms_error, o.mean_nees);
    if (range <= 4.5) {
      EXPECT_GE(o.accepted, 0.94) << range;
      EXPECT_LT(o.rms_error, 0.025) << range;
      EXPECT_GT(o.mean_nees, 1.4) << range;
      EXPECT_LT(o.mean_nees, 3.0) << range;
    }
  }
}

// The beam spot (15 mrad) averages the range over the cylinder's face: past ~6 m every beam
// reads the face's mean depth, and a central-ray fit puts the centre up to 10 mm too far, a
// range error growing with range that scales a surveyed map (issue 14). Printed per range: mean
// radial error (and the standard error of that mean) with the spot model and without it.
TEST(ExtractorOnEmulatorScans, SpotModelRemovesTheRadialBiasThatGrowsWithRange) {
  ExtractorConfig spot;
  spot.min_beams = 1;
  ExtractorConfig central_ray = spot;
  central_ray.fit.spot.enabled = false;
  for (double range : {1.0, 2.0, 3.0, 4.5, 6.0, 8.0, 10.0, 12.0, 15.0}) {
    const Outcome with_spot = run(Target::kCylinder, range, 600, spot, 13);
    const Outcome without = run(Target::kCylinder, range, 600, central_ray, 13);
    std::printf(
        "cylinder %5.1f m: radial bias %+6.2f mm (se %.2f) with the spot model, %+6.2f mm (se %.2f) "
        "central ray; rms %.1f / %.1f mm\n",
        range, 1e3 * with_spot.mean_radial_error,
        1e3 * with_spot.radial_error_sd / std::sqrt(std::max(with_spot.fits, 1)),
        1e3 * without.mean_radial_error, 1e3 * without.radial_error_sd / std::sqrt(std::max(without.fits, 1)),
        1e3 * with_spot.rms_error, 1e3 * without.rms_error);
    EXPECT_LT(std::abs(with_spot.mean_radial_error), 0.004) << range;
    EXPECT_LT(with_spot.rms_error, without.rms_error * 1.05) << range;
    if (range >= 10.0) {
      EXPECT_GT(without.mean_radial_error, 0.005) << range;
    }
  }
}

TEST(ExtractorOnEmulatorScans, MinBeams1ExtendsTheRangeWithConsistentCovariance) {
  ExtractorConfig config;
  config.min_beams = 1;
  for (double range : {7.5, 9.0, 10.5, 12.0, 13.5, 15.0}) {
    const Outcome o = run(Target::kCylinder, range, 200, config, 12);
    std::printf("min_beams 1, cylinder %5.1f m: recall %5.1f %%  rms %5.1f mm  NEES %.2f\n", range,
                100.0 * o.accepted, 1e3 * o.rms_error, o.mean_nees);
    if (range <= 10.5) {
      EXPECT_GE(o.accepted, 0.8) << range;
      EXPECT_LT(o.rms_error, 0.04) << range;
      EXPECT_LT(o.mean_nees, 3.0) << range;
    }
  }
}

TEST(ExtractorOnEmulatorScans, PaperModeCentreReadingsAt1To3m) {
  // Paper mode's centre with the designed radius (its default since issue 12), the free
  // algebraic circle it used before, the polar reading, and default mode, on the same scans.
  ExtractorConfig paper = ExtractorConfig::paper();
  paper.paper_roundness.offset = 1.0;  // accept all: compare centres, not roundness lines
  ExtractorConfig kasa = paper;
  kasa.paper_centre = PaperCentreReading::kAlgebraicFreeRadius;
  ExtractorConfig polar = paper;
  polar.paper_centre = PaperCentreReading::kPolar;
  for (double range : {1.0, 2.0, 3.0}) {
    const Outcome ours = run(Target::kCylinder, range, 200, ExtractorConfig{}, 5);
    const Outcome known = run(Target::kCylinder, range, 200, paper, 5);
    const Outcome free_circle = run(Target::kCylinder, range, 200, kasa, 5);
    const Outcome polar_reading = run(Target::kCylinder, range, 200, polar, 5);
    std::printf(
        "%3.1f m: centre rms default %5.1f mm, paper known radius %5.1f mm, kasa %6.1f mm, polar %5.1f mm\n",
        range, 1e3 * ours.rms_error, 1e3 * known.rms_error, 1e3 * free_circle.rms_error,
        1e3 * polar_reading.rms_error);
    EXPECT_LT(2.0 * known.rms_error, free_circle.rms_error) << range;
    EXPECT_LT(2.0 * ours.rms_error, free_circle.rms_error) << range;
  }
}

TEST(ExtractorOnEmulatorScans, WideTapeAndMetalPlatesAreRejected) {
  const ExtractorConfig config;
  double tape_accepted = 0.0;
  double metal_accepted = 0.0;
  int ranges = 0;
  for (double range = 0.5; range <= 9.0; range += 0.5) {
    const Outcome tape = run(Target::kTape30cm, range, 50, config, 21);
    const Outcome metal = run(Target::kMetal30cm, range, 50, config, 22);
    std::printf("%4.1f m: accepted 30 cm tape %5.1f %%, 30 cm metal plate %5.1f %%\n", range,
                100.0 * tape.accepted, 100.0 * metal.accepted);
    tape_accepted += tape.accepted;
    metal_accepted += metal.accepted;
    ++ranges;
  }
  EXPECT_LT(tape_accepted / ranges, 0.05);
  EXPECT_LT(metal_accepted / ranges, 0.20);
}

TEST(ExtractorOnEmulatorScans, NarrowTapeIsRejectedUpCloseWhereCurvatureShows) {
  // 12 cm tape face on is as wide as a reflector: only the missing curvature gives it
  // away, and beyond ~1.5 m the 12 mm range noise hides that (see README).
  for (double range : {0.5, 1.0}) {
    const Outcome tape = run(Target::kTape12cm, range, 200, ExtractorConfig{}, 31);
    std::printf("%3.1f m: accepted 12 cm tape %5.1f %%\n", range, 100.0 * tape.accepted);
    EXPECT_LT(tape.accepted, 0.2) << range;
  }
}

// Without noise the spot model explains the rendered echoes: centres' range within 1.5 mm RMS
// over 3-10 m, where the central-ray fit is 6-9 mm long at 8-10 m.
TEST(ExtractorOnEmulatorScans, NoiseFreeCentresWithTheSpotModel) {
  sim::ScanRenderConfig render;
  render.sensor.range_sigma = 0.0;
  render.sensor.rssi_sigma = 0.0;
  render.sensor.quantize_to_mm = false;
  sim::ScanRenderer renderer(render);
  for (const bool spot : {true, false}) {
    ExtractorConfig config;
    config.min_beams = 1;
    config.fit.spot.enabled = spot;
    ReflectorExtractor extractor(config);
    for (double range : {3.0, 4.5, 6.0, 8.0, 10.0}) {
      double sum_sq = 0.0;
      int fits = 0;
      for (int k = 0; k < 50; ++k) {  // bearings across one beam step
        const double bearing = 0.3 + k * (0.5 * M_PI / 180.0) / 50.0;
        sim::World world;
        MapReflector reflector;
        reflector.id = 1;
        reflector.map_p_center = polar(range, bearing);
        world.reflectors.reflectors.push_back(reflector);
        world.segments.push_back(strip(range + 1.0, bearing, 4.0, 0.0, SurfaceKind::kDiffuse));
        LaserScan scan;
        std::mt19937_64 rng(1);
        renderer.render(world, Pose2{}, 1'000'000, rng, scan);
        const std::vector<ReflectorDetection>& detections = extractor.extract(scan);
        if (detections.size() != 1) continue;
        const double radial = detections[0].laser_p_center.norm() - range;
        sum_sq += radial * radial;
        ++fits;
      }
      ASSERT_GT(fits, 45) << range;
      const double rms = std::sqrt(sum_sq / fits);
      std::printf("noise-free %s %4.1f m: radial rms %.2f mm\n", spot ? "spot model " : "central ray", range,
                  1e3 * rms);
      if (spot) {
        EXPECT_LT(rms, 0.0015) << range;
      } else if (range >= 8.0) {
        EXPECT_GT(rms, 0.004) << range;
      }
    }
  }
}

// The spot model's background: a beam's echo off a reflector 4 or 8 m away with a wall 0.1 m
// behind its centre (the renderer's energy-weighted blend within the merge distance) is what the
// model predicts, edge beams included, given the wall's range and its energy ratio.
TEST(ExtractorOnEmulatorScans, SpotModelWithTheWallBehindPredictsTheRenderersMixedEchoes) {
  const sim::Lms100ErrorModel model;
  const sim::BeamProfile profile = sim::make_beam_profile(model);
  KnownRadiusFitConfig with_wall;
  with_wall.spot.background = true;
  for (double range : {4.0, 8.0}) {
    sim::World world;
    MapReflector reflector;
    reflector.id = 1;
    reflector.map_p_center = {range, 0.0};
    world.reflectors.reflectors.push_back(reflector);
    world.segments.push_back({{range + 0.1, -2.0}, {range + 0.1, 2.0}, SurfaceKind::kDiffuse, 0.6});
    sim::World wall_only = world;
    wall_only.reflectors.reflectors.clear();
    const double ratio = sim::trace_beam(wall_only, profile, model, {0, 0}, 0.0).rssi /
                         sim::trace_beam(world, profile, model, {0, 0}, 0.0).rssi;
    double worst_without = 0.0;
    for (double lateral = -0.06; lateral <= 0.0; lateral += 0.01) {  // the bright half of the face
      const double angle = std::atan2(lateral, range);
      const sim::BeamEcho echo = sim::trace_beam(world, profile, model, {0, 0}, angle);
      FitBeam b;
      b.direction = {std::cos(angle), std::sin(angle)};
      b.range = echo.range;
      b.point = echo.range * b.direction;
      worst_without = std::max(worst_without, std::abs(range_residual(b, {range, 0.0}, 0.06, with_wall)));
      b.background_range = (range + 0.1) / std::cos(angle);
      b.background_energy_ratio = ratio;
      EXPECT_LT(std::abs(range_residual(b, {range, 0.0}, 0.06, with_wall)), 0.0035)
          << range << " " << lateral;
    }
    EXPECT_GT(worst_without, 0.010) << range;  // the wall's pull the model accounts for
  }
}

// Maps average thousands of detections, so their bias matters, not one detection's noise: on
// rendered scans of the demo hall the service's extractor reads reflectors at 3-6 m ~1.3 mm too
// close (the fit's second-order bias beats the wall's pull), and mapping_corrections() removes it.
TEST(ExtractorOnEmulatorScans, MappingCorrectionsRemoveTheRadialBiasOfDemoHallDetections) {
  const sim::World world = sim::load_world(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/world_demo.json");
  sim::ScanRenderer renderer;
  ReflectorExtractor service{ExtractorConfig{}};
  ReflectorExtractor mapping{mapping_corrections(ExtractorConfig{})};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(0.5, 19.5), y(0.5, 11.5), theta(-M_PI, M_PI);
  double sum[2] = {0.0, 0.0};
  int count[2] = {0, 0};
  LaserScan scan;
  for (int k = 0; k < 2000; ++k) {
    const Pose2 map_T_laser{x(rng), y(rng), theta(rng)};
    if (!world.is_drivable(map_T_laser.translation())) continue;
    renderer.render(world, map_T_laser, 1'000'000, rng, scan);
    for (int e = 0; e < 2; ++e) {
      for (const ReflectorDetection& d : (e == 0 ? service : mapping).extract(scan)) {
        for (const MapReflector& r : world.reflectors.reflectors) {
          if ((r.map_p_center - map_T_laser * d.laser_p_center).norm() > 0.15) continue;
          const double range = (map_T_laser.inverse() * r.map_p_center).norm();
          if (range < 3.0 || range > 6.0) continue;
          sum[e] += d.laser_p_center.norm() - range;
          ++count[e];
        }
      }
    }
  }
  ASSERT_GT(count[0], 2000);
  ASSERT_GT(count[1], 2000);
  const double service_bias = sum[0] / count[0], mapping_bias = sum[1] / count[1];
  std::printf(
      "demo hall, reflectors at 3-6 m: mean radial error %+.2f mm (%d) as the service extracts, "
      "%+.2f mm (%d) with mapping_corrections()\n",
      1e3 * service_bias, count[0], 1e3 * mapping_bias, count[1]);
  EXPECT_LT(service_bias, -0.0008);
  EXPECT_LT(std::abs(mapping_bias), 0.0006);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
