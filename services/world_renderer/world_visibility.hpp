#pragma once
// Which reflectors of a World a sensor can see: used to check that a world's
// reflector layout supports localization (>= 4 in view everywhere it drives)
// and by tests that need the expected detections of a pose.

#include "common/se2.hpp"
#include "world_renderer/world.hpp"

#include <vector>

namespace refloc::sim {

/// Ids of the reflectors whose centre lies within max_range [m] of map_T_laser, inside
/// the field of view |bearing| <= half_fov [rad] (pi: all around), with a free line of
/// sight from the sensor to the reflector's near side (no segment or other reflector
/// in between).
std::vector<int> visible_reflector_ids(const World& world, const Pose2& map_T_laser, double max_range,
                                       double half_fov);

/// Distance from map_p to the nearest segment or reflector surface of the world [m].
double clearance(const World& world, const Eigen::Vector2d& map_p);

}  // namespace refloc::sim
