#pragma once
// The walls the laser saw, as map occluders: the diffuse echoes of every scan (walls, racks,
// pillars; not the reflectors) put at the survey's optimised poses into a grid, the cells hit
// often enough kept, and straight segments taken out of them one by one, longest line first
// (a Hough vote over the cells, a total-least-squares refit, split where the wall has a gap).
// Simple on purpose: the matcher only needs to know that something opaque stands there.

#include "drive_scan.hpp"

#include "common/reflector_map.hpp"
#include "common/se2.hpp"

#include <vector>

namespace refloc {

struct OccluderConfig {
  double cell_size = 0.05;  ///< grid cell [m]
  /// A cell with fewer echoes is noise (a mixed pixel, a passing person) [-].
  int min_hits = 5;
  /// Echoes farther than this are left out: the beam spot and a heading error grow with range [m].
  double max_range = 12.0;
  double line_tolerance = 0.06;      ///< cells this close to a line belong to it [m]
  double max_gap = 0.3;              ///< a line with a longer gap is two segments [m]
  double min_segment_length = 0.3;   ///< shorter pieces are not written [m]
  double angle_step = M_PI / 360.0;  ///< Hough resolution in direction [rad]
  int max_segments = 500;
};

/// Segments (two-point polylines "wall 1", "wall 2", ...) in the map frame, longest first.
/// map_T_robot: one pose per scan.
std::vector<MapOccluder> trace_occluders(const std::vector<DriveScan>& scans,
                                         const std::vector<Pose2>& map_T_robot, const Pose2& robot_T_laser,
                                         const OccluderConfig& config);

/// The same from cell centres already chosen (the grid step left out), for tests.
std::vector<MapOccluder> segments_from_cells(std::vector<Eigen::Vector2d> cells,
                                             const OccluderConfig& config);

}  // namespace refloc
