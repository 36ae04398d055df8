#pragma once
// The parts of the map reader that format 2 adds (docs/map-format.md): the header, a
// reflector's type and covariance, the occluders. A format-1 file carrying any of them is
// refused with a message that says to add "format": 2, instead of "unknown key".

#include "common/reflector_map.hpp"

#include <string>
#include <vector>

namespace refloc {

class JsonConfig;

/// Largest coordinate accepted [m]: 100 km, beyond any factory; catches mm-for-m mistakes.
inline constexpr double kMaxMapCoordinate_m = 1e5;

/// "format" (absent: 1) and, for format 2, map_id, version, created and source.
MapInfo read_map_info(const JsonConfig& config, const std::string& pointer);
/// type and covariance_m2 of the reflector object at item (format 2 only).
void read_reflector_v2_keys(const JsonConfig& config, const std::string& item, int format, MapReflector& r);
/// The occluder list at pointer + "/occluders" (format 2 only; absent: none).
std::vector<MapOccluder> read_occluders(const JsonConfig& config, const std::string& pointer, int format);

}  // namespace refloc
