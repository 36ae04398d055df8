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
  double line_tolerance = 0.06;     ///< cells this close to a line belong to it [m]
  double max_gap = 0.3;             ///< a line with a longer gap is two segments [m]
  double min_segment_length = 0.3;  ///< shorter pieces are not written [m]
  /// Cells along a piece per cell of its length, at least [-] (a wall 1-2 cells thick: 1-2).
  double min_density = 0.7;
  double angle_step = M_PI / 360.0;  ///< Hough resolution in direction [rad]
  int max_segments = 500;
  /// Echoes of beams passing this close to a reflector's centre are left out [m]: a beam grazing
  /// its edge blends cylinder and wall (the mixed pixel, too dim to count as bright), and
  /// thousands of them, seen along a wall, drew a "wall" through the reflector. Other beams see
  /// the wall behind it.
  double landmark_clearance = 0.12;
};

/// Segments (two-point polylines "wall 1", "wall 2", ...) in the map frame, longest first.
/// map_T_robot: one pose per scan; range_bias: the sensor's offset, taken off every echo [m];
/// landmarks: reflector centres whose surroundings stay out of the grid (landmark_clearance).
std::vector<MapOccluder> trace_occluders(const std::vector<DriveScan>& scans,
                                         const std::vector<Pose2>& map_T_robot, const Pose2& robot_T_laser,
                                         double range_bias, const std::vector<Eigen::Vector2d>& landmarks,
                                         const OccluderConfig& config);

/// The same from cell centres already chosen (the grid step left out), for tests.
std::vector<MapOccluder> segments_from_cells(std::vector<Eigen::Vector2d> cells,
                                             const OccluderConfig& config);

}  // namespace refloc
