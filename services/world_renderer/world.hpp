#pragma once
// A simulated world for the LMS100 renderer: the cylindrical retro-reflectors
// (a ReflectorMap, so the very same file the localization loads), diffuse walls
// and obstacles, and distractors that fool a naive reflector detector: flat
// reflective tape (bright, but not round) and shiny metal (bright only when hit
// near-normal). Everything else is plain data; loading lives in world_loader.hpp.

#include "common/reflector_map.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace refloc::sim {

/// How a straight surface returns the laser light.
enum class SurfaceKind {
  kDiffuse,         ///< painted wall, rack, pillar: RSSI falls with range and incidence
  kReflectiveTape,  ///< flat retro-reflective tape: reflector-bright up to a steep incidence
  kMetal,           ///< polished metal: reflector-bright only near-normal, dim otherwise
};

/// Name used in world files and messages ("diffuse", "tape", "metal").
const char* surface_kind_name(SurfaceKind kind);

/// One straight piece of a wall, obstacle or distractor, in the map frame.
struct WorldSegment {
  Eigen::Vector2d map_p_a = Eigen::Vector2d::Zero();  ///< [m]
  Eigen::Vector2d map_p_b = Eigen::Vector2d::Zero();  ///< [m]
  SurfaceKind surface = SurfaceKind::kDiffuse;
  double remission = 0.5;  ///< diffuse reflectance, 0.02 (black) .. 1 (white paper) [-]
};

/// Axis-aligned rectangle in which the robot's laser may be placed (tests, random goals).
struct DrivableArea {
  double x_min = 0.0;  ///< [m]
  double y_min = 0.0;  ///< [m]
  double x_max = 0.0;  ///< [m]
  double y_max = 0.0;  ///< [m]

  bool contains(const Eigen::Vector2d& map_p) const {
    return map_p.x() >= x_min && map_p.x() <= x_max && map_p.y() >= y_min && map_p.y() <= y_max;
  }
};

struct World {
  /// Reflectors as they really stand: the map the localization uses, with the world
  /// file's map errors applied (moved and missing reflectors, unmapped ones added).
  ReflectorMap reflectors;
  /// Walls, obstacles and distractors flattened into segments.
  std::vector<WorldSegment> segments;
  std::vector<DrivableArea> drivable_areas;
  std::string map_file;  ///< resolved path of the map file the reflectors came from
  std::string description;

  /// True when map_p lies in one of the drivable areas (false when there are none).
  bool is_drivable(const Eigen::Vector2d& map_p) const;
};

/// Append the segments of a polyline (closed: also last -> first).
void add_polyline(World& world, const std::vector<Eigen::Vector2d>& map_points, bool closed,
                  SurfaceKind surface, double remission);

}  // namespace refloc::sim
