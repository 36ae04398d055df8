#pragma once
// The map of retro-reflectors: id and centre in the map frame.

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace refloc {

struct MapReflector {
  int id = 0;
  Eigen::Vector2d map_p_center = Eigen::Vector2d::Zero();  ///< centre in the map frame [m]
  double radius = 0.06;                                    ///< cylinder radius [m]
  /// Free-form reflector type from the file (e.g. "cylinder_120"); "" when not given.
  std::string type;
  /// Covariance of map_p_center from the survey [m^2]; absent for typed or imported
  /// positions whose accuracy nobody stated.
  std::optional<Eigen::Matrix2d> map_cov_center;
};

/// Something the laser cannot see through (a wall, a rack): a polyline in the map frame.
/// The matcher does not expect a reflector behind one.
struct MapOccluder {
  std::string name;
  std::vector<Eigen::Vector2d> map_points;  ///< at least 2 [m]
  bool closed = false;                      ///< also the segment last -> first
};

/// Where a map came from (format v2's header); a v1 file loads with format 1 and the rest empty.
struct MapInfo {
  int format = 1;       ///< 1: reflectors only; 2: this header, covariances, occluders
  std::string map_id;   ///< names the hall/layout; stays the same across versions
  int version = 0;      ///< increases with every written revision (refloc-map update)
  std::string created;  ///< ISO 8601 UTC time the file was written
  std::string source;   ///< "typed", "imported", "surveyed", "updated"
};

/// Two reflectors closer than r1 + r2 + this [m] are refused: they would touch (or overlap),
/// and the extractor could not tell them apart anyway.
inline constexpr double kMinReflectorGap_m = 0.01;
/// A map whose reflectors all lie within this distance [m] of one straight line gets a
/// warning: the pose is not observable from colinear reflectors alone.
inline constexpr double kColinearTolerance_m = 0.05;

struct ReflectorMap {
  MapInfo info;
  std::vector<MapReflector> reflectors;
  std::vector<MapOccluder> occluders;
  /// Accepted but doubtful geometry (colinear reflectors), one line each, for the caller to log.
  std::vector<std::string> warnings;

  /// Index into reflectors of the reflector with this id, or -1.
  int index_of(int id) const;
};

/// Load and validate a map file (docs/map-format.md). Format 1: {"default_radius_m": 0.06,
/// "reflectors": [{"id", "x", "y", "radius_m"?}, ...]}. Format 2 ("format": 2) adds the header
/// (map_id, version, created, source), a reflector's "type" and "covariance_m2" [xx, xy, yy]
/// (positive definite) and "occluders" [{"name", "points": [[x, y], ...], "closed"?}]; a format-1
/// file holding any of these is refused. Ids unique, coordinates finite within 100 km, radius in
/// [1 mm, 5 m], at least 3 reflectors, no two closer than r1 + r2 + kMinReflectorGap_m (checked
/// on a grid: 100,000 reflectors at one spot are refused at the second one). Colinear maps load
/// with a warning in ReflectorMap::warnings.
/// Throws ConfigError naming the file and the JSON pointer of the offending value.
ReflectorMap load_reflector_map(const std::string& path);

class JsonConfig;
/// Same validation on a document already loaded (the map may live inside another file);
/// pointer is where the map object sits in that document ("" for the root).
ReflectorMap parse_reflector_map(const JsonConfig& config, const std::string& pointer = "");

/// The warning for a map whose reflectors all lie within kColinearTolerance_m of one line,
/// or "" when the geometry is fine. source names the map in the text.
std::string colinear_map_warning(const ReflectorMap& map, const std::string& source);

/// The map as the JSON text of a format-2 file (docs/map-format.md): info header, reflectors in
/// order with their covariance where known, occluders. Loading the text gives the map back (the
/// same doubles: numbers are written as their shortest round-trip text). map.info.format is
/// ignored (always 2); an empty map.info.created is written as the current time.
std::string reflector_map_v2_text(const ReflectorMap& map);
/// Writes reflector_map_v2_text to path through a temporary file and a rename, so a reader
/// never sees half a map. A map the reader would refuse (no map_id, fewer than 3 reflectors...)
/// is not written: ConfigError naming the path and the key. Throws std::runtime_error naming the
/// path when the file cannot be written.
void write_reflector_map(const ReflectorMap& map, const std::string& path);

/// The current time as the map header's "created" holds it: "2026-12-03T06:30:58Z".
std::string iso8601_utc_now();
/// Whether text is a time as "created" holds it: ISO 8601 UTC, YYYY-MM-DDTHH:MM:SS[.fraction]Z,
/// each field in its calendar range.
bool is_iso8601_utc(const std::string& text);

}  // namespace refloc
