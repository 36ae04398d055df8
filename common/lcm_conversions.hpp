#pragma once
// Conversions between plain library structs and LCM messages, used at the edge
// by main.cpp files and tools.

#include "common/laser_scan.hpp"
#include "common/reflector_detection.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>
#include <refloc/laser_scan_t.hpp>
#include <refloc/reflector_matches_t.hpp>
#include <refloc/reflector_t.hpp>

#include <vector>

namespace refloc {

laser_scan_t to_lcm(const LaserScan& scan);
/// Returns false (leaving out untouched) when the message is inconsistent
/// (nrssi neither 0 nor nranges, non-positive increment).
bool from_lcm(const laser_scan_t& msg, LaserScan& out);
/// Every field as it came, judged by nobody (for a caller that judges the scan itself).
void copy_from_lcm(const laser_scan_t& msg, LaserScan& out);

reflector_t to_lcm(const ReflectorDetection& detection);
ReflectorDetection from_lcm(const reflector_t& msg);

/// The matches of one REFLECTOR_MATCHES message. Each match carries its detection, so
/// its readers (pose_solver, pose_fusion) see them as detections 0..n-1.
void matches_from_message(const reflector_matches_t& msg, std::vector<ReflectorDetection>& detections,
                          std::vector<ReflectorMatch>& matches);

/// The row-major 3x3 (x, y, theta) covariance of pose2d_t and odometry_t.
void covariance_to_lcm(const Eigen::Matrix3d& covariance, double (&out)[9]);
Eigen::Matrix3d covariance_from_lcm(const double (&in)[9]);

}  // namespace refloc
