#include "drive_scan.hpp"

#include "calibration_pairs.hpp"
#include "reflector_extractor/motion_compensation.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

DriveScanBuilder::DriveScanBuilder(const ExtractorServiceConfig& extractor, const Pose2& robot_T_laser,
                                   const DriveScanOptions& options)
    : node_(extractor, robot_T_laser),
      energy_threshold_8bit_(extractor.extractor.energy_threshold_8bit),
      odometry_max_age_s_(extractor.motion_compensation ? extractor.odometry_max_age : -1.0),
      robot_T_laser_(robot_T_laser),
      options_(options) {}

void DriveScanBuilder::on_odometry(const OdometrySample& sample) {
  ++counts_.odometry;
  node_.on_odometry(sample);
  latest_twist_ = sample.twist;
  odometry_.push_back(sample);
}

void DriveScanBuilder::on_scan(const LaserScan& scan) {
  ++counts_.scans;
  const ExtractorOutput& out = node_.on_scan(scan);
  if (!out.accepted) {
    ++counts_.scans_rejected;
    return;
  }
  DriveScan s;
  s.utime = out.utime;
  s.angle_increment = std::abs(scan.angle_increment);
  s.detections = out.detections;
  keep_diffuse(scan, out.detections, s);
  scans_.push_back(std::move(s));
}

void DriveScanBuilder::keep_diffuse(const LaserScan& scan, const std::vector<ReflectorDetection>& detections,
                                    DriveScan& out) {
  make_beam_table(scan, table_, node_.rssi_scale());
  in_detection_.assign(table_.size(), 0);
  for (const ReflectorDetection& d : detections) {
    const int end = std::min<int>(d.first_beam + d.num_beams, static_cast<int>(table_.size()));
    for (int i = std::max(0, d.first_beam); i < end; ++i) in_detection_[static_cast<size_t>(i)] = 1;
  }
  // The same exact arc the extractor moves detections along; beams of a scan without fresh
  // odometry stay where they were measured (15 ms of motion, under a grid cell).
  const bool moving =
      !odometry_.empty() &&
      std::abs(static_cast<double>(odometry_.back().utime - scan.utime)) * 1e-6 <= odometry_max_age_s_;
  const int stride = std::max(1, options_.diffuse_stride);
  for (size_t i = 0; i < table_.size(); i += static_cast<size_t>(stride)) {
    const TableBeam& b = table_.beams[i];
    if (b.kind != BeamKind::kEcho || in_detection_[i]) continue;
    if (table_.has_rssi && b.rssi_8bit >= energy_threshold_8bit_) continue;  // bright: not a wall
    Eigen::Vector2d p = b.point;
    if (moving) {
      const double dt = static_cast<double>(table_.beam_utime(i) - scan.utime) * 1e-6;
      p = laser_motion(latest_twist_, robot_T_laser_, dt) * p;
    }
    out.laser_p_diffuse.emplace_back(p.cast<float>());
  }
}

std::vector<DriveScan> DriveScanBuilder::finish() {
  std::vector<TimedPose> odometry;
  odometry.reserve(odometry_.size());
  for (const OdometrySample& o : odometry_)
    odometry.push_back({o.utime, o.odom_T_robot, Eigen::Matrix3d::Zero()});
  std::stable_sort(odometry.begin(), odometry.end(),
                   [](const TimedPose& a, const TimedPose& b) { return a.utime < b.utime; });
  std::stable_sort(scans_.begin(), scans_.end(),
                   [](const DriveScan& a, const DriveScan& b) { return a.utime < b.utime; });
  std::vector<DriveScan> out;
  out.reserve(scans_.size());
  for (DriveScan& s : scans_) {
    const std::optional<Pose2> odom = interpolate_pose(odometry, s.utime, options_.max_odometry_gap_s);
    if (!odom) {
      ++counts_.scans_without_odometry;
      continue;
    }
    s.odom_T_robot = *odom;
    counts_.detections += static_cast<int64_t>(s.detections.size());
    out.push_back(std::move(s));
  }
  scans_.clear();
  return out;
}

}  // namespace refloc
