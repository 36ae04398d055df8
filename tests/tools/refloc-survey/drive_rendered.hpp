#pragma once
// A short survey drive rendered without any process: the robot follows refloc-eval's demo-hall
// loop (DrivePath), the LMS100 renderer casts every beam from the laser's true pose at its own
// time, and odometry integrates the true twist with a wheel-scale error and a heading drift, so
// dead reckoning alone drifts as robot_sim's does. The scans go through DriveScanBuilder, i.e.
// the extractor's own node with its motion compensation, exactly as a logged drive does.

#include "common/se2.hpp"
#include "drive_path.hpp"
#include "drive_scan.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "world_renderer/scan_renderer.hpp"
#include "world_renderer/world_loader.hpp"

#include <refloc/odometry_t.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace refloc::testing {

inline const std::string kDemoWorld = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/world_demo.json";
inline const std::string kDemoMap = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/map_demo.json";

struct RenderedDriveOptions {
  double duration_s = 14.0;
  double scan_period_s =
      0.1;  ///< every fifth LMS100 scan (10 Hz): the survey needs no more, the test is faster
  double speed_mps = 0.8;
  double odometry_scale_error = 0.01;     ///< odometry reads distances 1 % long
  double odometry_heading_drift = 0.004;  ///< [rad per m driven]
  double range_offset_m = 0.0;            ///< the rendered LMS100's systematic range offset
  Pose2 robot_T_laser{0.30, 0.0, 0.0};    ///< deploy/config/robot.json's mount
  uint64_t seed = 1;
};

struct RenderedDrive {
  sim::World world;
  /// What the bus would have carried, in the order fed: odometry samples and raw scans.
  std::vector<OdometrySample> raw_odometry;
  std::vector<LaserScan> raw_scans;
  std::vector<bool> raw_order_is_scan;
  std::vector<DriveScan> scans;
  std::vector<Pose2> true_map_T_robot;  ///< at every kept scan's time
  DriveScanCounts counts;
};

inline RenderedDrive render_drive(const RenderedDriveOptions& o) {
  constexpr int64_t kStartUtime = 1'700'000'000'000'000;
  const auto utime_at = [&](double t) { return kStartUtime + std::llround(t * 1e6); };
  const DrivePath path = DrivePath::demo_hall_loop(o.speed_mps, DrivePath::Heading::kTangent);
  RenderedDrive out;
  out.world = sim::load_world(kDemoWorld);
  sim::ScanRenderConfig render;
  render.sensor.range_offset = o.range_offset_m;
  render.geometry.scan_period = o.scan_period_s;
  sim::ScanRenderer renderer(render);
  const sim::PoseAtTime map_T_laser_at = [&](int64_t utime) {
    return path.at(static_cast<double>(utime - kStartUtime) * 1e-6).map_T_robot * o.robot_T_laser;
  };
  DriveScanBuilder builder(load_extractor_service_config(std::string(REFLOC_SOURCE_DIR) +
                                                         "/deploy/config/reflector_extractor.json"),
                           o.robot_T_laser);
  std::mt19937_64 rng(o.seed);
  OdometrySample odometry;  // odom frame = the start pose
  constexpr double kOdometryPeriod = 0.01;
  double t_odometry = 0.0;
  LaserScan scan;
  for (int k = 0; k * o.scan_period_s <= o.duration_s; ++k) {
    const double t_scan = k * o.scan_period_s;
    while (t_odometry <= t_scan + 0.02) {  // odometry runs ahead of the scans a little, as on the bus
      const BodyTwist truth = path.at(t_odometry).twist;
      BodyTwist read{truth.vx * (1.0 + o.odometry_scale_error), truth.vy * (1.0 + o.odometry_scale_error),
                     truth.wz + o.odometry_heading_drift * std::hypot(truth.vx, truth.vy)};
      odometry.utime = utime_at(t_odometry);
      odometry.twist = read;
      builder.on_odometry(odometry);
      out.raw_odometry.push_back(odometry);
      out.raw_order_is_scan.push_back(false);
      odometry.odom_T_robot = odometry.odom_T_robot * se2_exp(read, kOdometryPeriod);
      t_odometry += kOdometryPeriod;
    }
    renderer.render(out.world, map_T_laser_at, utime_at(t_scan), rng, scan);
    scan.scan_counter = static_cast<uint32_t>(k);
    builder.on_scan(scan);
    out.raw_scans.push_back(scan);
    out.raw_order_is_scan.push_back(true);
  }
  out.scans = builder.finish();
  for (const DriveScan& s : out.scans)
    out.true_map_T_robot.push_back(path.at(static_cast<double>(s.utime - kStartUtime) * 1e-6).map_T_robot);
  out.counts = builder.counts();
  return out;
}

/// The drive every test of this folder uses, rendered once: the default options with a +20 mm
/// range offset.
/// An odometry sample as mecanum_odometry publishes it on ODOMETRY.
inline odometry_t odometry_message(const OdometrySample& s) {
  odometry_t m{};
  m.utime = s.utime;
  m.x = s.odom_T_robot.x;
  m.y = s.odom_T_robot.y;
  m.theta = s.odom_T_robot.theta;
  m.vx = s.twist.vx;
  m.vy = s.twist.vy;
  m.wz = s.twist.wz;
  return m;
}

inline const RenderedDrive& lower_aisle_drive() {
  static const RenderedDrive drive = [] {
    RenderedDriveOptions o;
    o.range_offset_m = 0.02;
    return render_drive(o);
  }();
  return drive;
}

}  // namespace refloc::testing
