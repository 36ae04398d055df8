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

/// Two reflectors closer than r1 + r2 + this [m] are refused: they would touch (or overlap),
/// and the extractor could not tell them apart anyway.
inline constexpr double kMinReflectorGap_m = 0.01;
/// A map whose reflectors all lie within this distance [m] of one straight line gets a
/// warning: the pose is not observable from colinear reflectors alone.
inline constexpr double kColinearTolerance_m = 0.05;

struct ReflectorMap {
  std::vector<MapReflector> reflectors;
  /// Accepted but doubtful geometry (colinear reflectors), one line each, for the caller to log.
  std::vector<std::string> warnings;

  /// Index into reflectors of the reflector with this id, or -1.
  int index_of(int id) const;
};

/// Load and validate a map file: {"default_radius_m": 0.06, "reflectors": [{"id", "x", "y",
/// "radius_m"?}, ...]}. Ids unique, coordinates finite within 100 km, radius in [1 mm, 5 m],
/// at least 3 reflectors, no two closer than r1 + r2 + kMinReflectorGap_m (checked on a grid:
/// 100,000 reflectors at one spot are refused at the second one). Colinear maps load with a
/// warning in ReflectorMap::warnings.
/// Throws ConfigError naming the file and the JSON pointer of the offending value.
ReflectorMap load_reflector_map(const std::string& path);

class JsonConfig;
/// Same validation on a document already loaded (the map may live inside another file);
/// pointer is where the map object sits in that document ("" for the root).
ReflectorMap parse_reflector_map(const JsonConfig& config, const std::string& pointer = "");

/// The warning for a map whose reflectors all lie within kColinearTolerance_m of one line,
/// or "" when the geometry is fine. source names the map in the text.
std::string colinear_map_warning(const ReflectorMap& map, const std::string& source);

}  // namespace refloc
