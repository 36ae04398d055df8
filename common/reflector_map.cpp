#include "common/reflector_map.hpp"

#include "common/json_config.hpp"
#include "common/reflector_map_spacing.hpp"
#include "common/reflector_map_v2_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace refloc {
std::string colinear_map_warning(const ReflectorMap& map, const std::string& source) {
  if (map.reflectors.size() < 2) return "";
  const Eigen::Vector2d origin = map.reflectors.front().map_p_center;
  Eigen::Vector2d far = origin;
  for (const MapReflector& r : map.reflectors) {
    if ((r.map_p_center - origin).norm() > (far - origin).norm()) far = r.map_p_center;
  }
  const Eigen::Vector2d along = far - origin;
  if (along.norm() <= 0.0) return fmt::format("{}: all reflectors at one spot", source);
  const Eigen::Vector2d normal = Eigen::Vector2d(-along.y(), along.x()) / along.norm();
  double off_line = 0.0;
  for (const MapReflector& r : map.reflectors)
    off_line = std::max(off_line, std::fabs(normal.dot(r.map_p_center - origin)));
  if (off_line >= kColinearTolerance_m) return "";
  return fmt::format(
      "{}: all {} reflectors lie within {:.3f} m of one line (fewer than 3 non-colinear); "
      "the pose is not observable from them alone",
      source, map.reflectors.size(), off_line);
}

int ReflectorMap::index_of(int id) const {
  for (size_t i = 0; i < reflectors.size(); ++i) {
    if (reflectors[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

ReflectorMap parse_reflector_map(const JsonConfig& config, const std::string& pointer) {
  ReflectorMap map;
  map.info = read_map_info(config, pointer);
  const double default_radius =
      config.number({pointer + "/default_radius_m", "m",
                     "cylinder radius of reflectors without their own radius_m (120 mm "
                     "diameter: 0.06); the matcher's occlusion check and the simulator use it"},
                    0.06, 1e-3, 5.0);
  const std::string list = pointer + "/reflectors";
  const size_t n = config.array_size(
      {list, "",
       "the reflectors [{id, x, y, radius_m, type, covariance_m2}]: at least 3, centres r1 + r2 + "
       "10 mm apart; all on one line only warns"});
  if (n < 3) config.fail(list, fmt::format("expected at least 3 reflectors, got {}", n));

  map.reflectors.reserve(n);
  SpacingCheck spacing(config, list);
  std::map<long long, size_t> first_index_of_id;
  for (size_t i = 0; i < n; ++i) {
    const std::string item = fmt::format("{}/{}", list, i);
    MapReflector r;
    const long long id = config.required_integer(
        {item + "/id", "", "unique reflector id; REFLECTOR_MATCHES and the logs name reflectors by it"}, 0,
        1000000000);
    const auto [it, inserted] = first_index_of_id.emplace(id, i);
    if (!inserted) {
      config.fail(item + "/id",
                  fmt::format("duplicate reflector id {} (also at {}/{})", id, list, it->second));
    }
    r.id = static_cast<int>(id);
    r.map_p_center.x() =
        config.required_number({item + "/x", "m", "centre x in the map frame (surveyed; metres, not mm)"},
                               -kMaxMapCoordinate_m, kMaxMapCoordinate_m);
    r.map_p_center.y() = config.required_number({item + "/y", "m", "centre y in the map frame"},
                                                -kMaxMapCoordinate_m, kMaxMapCoordinate_m);
    r.radius =
        config.number({item + "/radius_m", "m", "this reflector's cylinder radius, if not default_radius_m"},
                      default_radius, 1e-3, 5.0);
    read_reflector_v2_keys(config, item, map.info.format, r);
    map.reflectors.push_back(r);
    spacing.add(map.reflectors);
  }
  map.occluders = read_occluders(config, pointer, map.info.format);
  const std::string warning = colinear_map_warning(map, config.source());
  if (!warning.empty()) map.warnings.push_back(warning);
  return map;
}

ReflectorMap load_reflector_map(const std::string& path) {
  const JsonConfig config = JsonConfig::load_file(path);
  ReflectorMap map = parse_reflector_map(config);
  config.reject_unknown_keys();
  return map;
}

}  // namespace refloc
