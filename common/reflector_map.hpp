#pragma once
// The map of retro-reflectors: id and centre in the map frame.

#include <Eigen/Core>

#include <string>
#include <vector>

namespace refloc {

struct MapReflector {
  int id = 0;
  Eigen::Vector2d map_p_center = Eigen::Vector2d::Zero();  ///< centre in the map frame [m]
  double radius = 0.06;                                    ///< cylinder radius [m]
};

struct ReflectorMap {
  std::vector<MapReflector> reflectors;

  /// Index into reflectors of the reflector with this id, or -1.
  int index_of(int id) const;
};

/// Load and validate a map file: {"default_radius_m": 0.06, "reflectors": [{"id", "x", "y",
/// "radius_m"?}, ...]}. Ids unique, coordinates finite, radius > 0, at least 3 reflectors.
/// Throws ConfigError naming the file and the JSON pointer of the offending value.
ReflectorMap load_reflector_map(const std::string& path);

class JsonConfig;
/// Same validation on a document already loaded (the map may live inside another file);
/// pointer is where the map object sits in that document ("" for the root).
ReflectorMap parse_reflector_map(const JsonConfig& config, const std::string& pointer = "");

}  // namespace refloc
