#pragma once
// The places refloc-plan looks at: square cells over the drivable area (the world file's
// rectangles), or, for a map without one, over everything the map holds minus the inside of
// its small closed occluders (racks, pillars).

#include "common/reflector_map.hpp"
#include "world_renderer/world.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

struct PlanGrid {
  double resolution = 0.25;                          ///< cell side [m]
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< lower-left corner of cell (0, 0) [m]
  int columns = 0, rows = 0;                         ///< of the bounding box [-]
  std::vector<Eigen::Vector2d> map_p_cells;          ///< centres of the cells planned for [m]
};

/// Cells of side resolution [m] whose centre lies in one of drivable (with none, in the
/// bounding box of the map's reflectors and occluders) and outside every closed occluder that
/// covers less than half of that box (racks and pillars; the hall's outline stays). Throws
/// std::invalid_argument for resolution <= 0 or a grid of more than max_cells.
PlanGrid make_plan_grid(const ReflectorMap& map, const std::vector<sim::DrivableArea>& drivable,
                        double resolution, size_t max_cells = 4000000);

/// Whether map_p lies inside the closed polygon points (even-odd rule).
bool inside_polygon(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& map_p);

}  // namespace refloc
