#include "drive_study.hpp"

#include "common/angles.hpp"
#include "world_renderer/scan_renderer.hpp"

#include <cmath>
#include <random>

namespace refloc {
namespace {

constexpr int64_t kStartUtime = 1'700'000'000'000'000;

int64_t utime_at(double t) { return kStartUtime + std::llround(t * 1e6); }
double time_of(int64_t utime) { return static_cast<double>(utime - kStartUtime) * 1e-6; }

/// Sums of the scored fixes' errors.
struct ErrorSums {
  double along = 0.0, along2 = 0.0, cross = 0.0, cross2 = 0.0, heading = 0.0, heading2 = 0.0;
  int n = 0;
  void add(double along_m, double cross_m, double heading_rad) {
    along += along_m, along2 += along_m * along_m;
    cross += cross_m, cross2 += cross_m * cross_m;
    heading += heading_rad, heading2 += heading_rad * heading_rad;
    ++n;
  }
};

}  // namespace

const char* to_string(DriveMotionSource source) {
  switch (source) {
    case DriveMotionSource::kOdometry:
      return "odometry";
    case DriveMotionSource::kNoOdometry:
      return "no_odometry";
    case DriveMotionSource::kNoCompensation:
      return "no_compensation";
  }
  return "?";
}

DriveSummary run_drive(const sim::World& world, const ReflectorMap& map, const Pose2& robot_T_laser,
                       PipelineConfigs configs, const DrivePath& path, DriveMotionSource source,
                       const DriveConfig& config) {
  configs.extractor.motion_compensation = source != DriveMotionSource::kNoCompensation;
  LocalizationPipeline pipeline(PipelineMode::kDefault, configs, map, robot_T_laser);
  sim::ScanRenderConfig render_config;
  render_config.sensor = config.sensor;
  render_config.geometry.scan_period = config.scan_period_s;
  sim::ScanRenderer renderer(render_config);
  std::mt19937_64 rng(config.seed);  // the same scans for every source: a paired comparison
  const sim::PoseAtTime map_T_laser_at = [&](int64_t utime) {
    return path.at(time_of(utime)).map_T_robot * robot_T_laser;
  };
  const double scan_duration_s =
      render_config.geometry.time_increment * static_cast<double>(render_config.geometry.num_beams);

  DriveSummary s;
  s.source = source;
  s.trace.start_utime = kStartUtime;
  ErrorSums sums;
  ConsistencyAccumulator consistency;
  LaserScan scan;
  int odometry_index = 0;
  for (int k = 0;; ++k) {
    const double t_scan = k * config.scan_period_s;
    if (t_scan > config.duration_s) break;
    // ODOMETRY that reached the extractor before the scan did: samples up to its last beam.
    for (;; ++odometry_index) {
      const double t_odometry = odometry_index * config.odometry_period_s;
      if (t_odometry > t_scan + scan_duration_s) break;
      if (source == DriveMotionSource::kNoOdometry) continue;
      OdometrySample sample;
      sample.utime = utime_at(t_odometry);
      sample.twist = path.at(t_odometry).twist;
      pipeline.on_odometry(sample);
    }
    renderer.render(world, map_T_laser_at, utime_at(t_scan), rng, scan);
    scan.scan_counter = static_cast<uint32_t>(k);
    const PipelineOutput& out = pipeline.on_scan(scan);
    // LASER_POSE back to the extractor before the next scan, as over LCM (the solver publishes
    // within ~1 ms): pose2d_t carries these doubles unchanged, and laser_pose_from_message
    // reads them into exactly this.
    pipeline.on_laser_pose(
        {out.fix->utime, out.fix->map_T_robot, out.fix->covariance, out.fix->status == LaserFixStatus::kOk});

    ++s.scans;
    s.trace.samples.push_back({"GROUND_TRUTH", utime_at(t_scan), path.at(t_scan).map_T_robot, NAN});
    if (t_scan < config.warmup_s) continue;
    ++s.scored_scans;
    const CompensationOutcome c = out.extraction->compensation;
    s.compensated_odometry += c == CompensationOutcome::kOdometry;
    s.compensated_fixes += c == CompensationOutcome::kFixes;
    s.not_compensated += c == CompensationOutcome::kNoMotionSource || c == CompensationOutcome::kOff;
    if (out.fix->status == LaserFixStatus::kDegraded) ++s.degraded_fixes;
    if (!out.fix->has_pose) ++s.fixes_without_pose;
    if (out.fix->status != LaserFixStatus::kOk) continue;
    const DriveState truth = path.at(time_of(out.fix->utime));
    const Eigen::Vector2d error = out.fix->map_T_robot.translation() - truth.map_T_robot.translation();
    if (error.norm() > config.wrong_distance) {
      ++s.wrong_fixes;
      continue;
    }
    ++s.ok_fixes;
    s.trace.samples.push_back({"LASER_POSE", out.fix->utime, out.fix->map_T_robot, error.norm()});
    const Eigen::Vector2d& u = truth.map_direction;
    const double heading_error = angle_diff(out.fix->map_T_robot.theta, truth.map_T_robot.theta);
    sums.add(error.dot(u), error.dot(Eigen::Vector2d(-u.y(), u.x())), heading_error);
    consistency.add(Eigen::Vector3d(error.x(), error.y(), heading_error), out.fix->covariance);
  }
  if (sums.n > 0) {
    const double n = sums.n;
    s.along_mean_mm = 1e3 * sums.along / n;
    s.along_rms_mm = 1e3 * std::sqrt(sums.along2 / n);
    s.cross_mean_mm = 1e3 * sums.cross / n;
    s.cross_rms_mm = 1e3 * std::sqrt(sums.cross2 / n);
    s.position_rmse_mm = 1e3 * std::sqrt((sums.along2 + sums.cross2) / n);
    s.heading_mean_mdeg = 1e3 * sums.heading / n * 180.0 / M_PI;
    s.heading_rms_mdeg = 1e3 * std::sqrt(sums.heading2 / n) * 180.0 / M_PI;
  }
  s.consistency = consistency.summary();
  return s;
}

nlohmann::json to_json(const DriveSummary& s) {
  nlohmann::json j = {{"source", to_string(s.source)},
                      {"scans", s.scans},
                      {"scored_scans", s.scored_scans},
                      {"ok_fixes", s.ok_fixes},
                      {"degraded_fixes", s.degraded_fixes},
                      {"fixes_without_pose", s.fixes_without_pose},
                      {"wrong_fixes", s.wrong_fixes},
                      {"scans_compensated_odometry", s.compensated_odometry},
                      {"scans_compensated_fixes", s.compensated_fixes},
                      {"scans_not_compensated", s.not_compensated},
                      {"along_track_mean_mm", s.along_mean_mm},
                      {"along_track_rms_mm", s.along_rms_mm},
                      {"cross_track_mean_mm", s.cross_mean_mm},
                      {"cross_track_rms_mm", s.cross_rms_mm},
                      {"position_rmse_mm", s.position_rmse_mm},
                      {"heading_mean_mdeg", s.heading_mean_mdeg},
                      {"heading_rms_mdeg", s.heading_rms_mdeg}};
  j.update(consistency_json(s.consistency));
  return j;
}

}  // namespace refloc
