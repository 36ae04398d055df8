#include "common/reflector_map.hpp"

#include "common/json_config.hpp"

#include <fmt/format.h>

#include <map>

namespace refloc {

int ReflectorMap::index_of(int id) const {
  for (size_t i = 0; i < reflectors.size(); ++i) {
    if (reflectors[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

ReflectorMap parse_reflector_map(const JsonConfig& config, const std::string& pointer) {
  constexpr double kMaxCoordinate_m = 1e5;  // 100 km: beyond any factory, catches unit mistakes
  const double default_radius = config.number(pointer + "/default_radius_m", 0.06, 1e-3, 5.0);
  const std::string list = pointer + "/reflectors";
  const size_t n = config.array_size(list);
  if (n < 3) config.fail(list, fmt::format("expected at least 3 reflectors, got {}", n));

  ReflectorMap map;
  std::map<long long, size_t> first_index_of_id;
  for (size_t i = 0; i < n; ++i) {
    const std::string item = fmt::format("{}/{}", list, i);
    MapReflector r;
    const long long id = config.required_integer(item + "/id", 0, 1000000000);
    const auto [it, inserted] = first_index_of_id.emplace(id, i);
    if (!inserted) {
      config.fail(item + "/id",
                  fmt::format("duplicate reflector id {} (also at {}/{})", id, list, it->second));
    }
    r.id = static_cast<int>(id);
    r.map_p_center.x() = config.required_number(item + "/x", -kMaxCoordinate_m, kMaxCoordinate_m);
    r.map_p_center.y() = config.required_number(item + "/y", -kMaxCoordinate_m, kMaxCoordinate_m);
    r.radius = config.number(item + "/radius_m", default_radius, 1e-3, 5.0);
    map.reflectors.push_back(r);
  }
  return map;
}

ReflectorMap load_reflector_map(const std::string& path) {
  const JsonConfig config = JsonConfig::load_file(path);
  ReflectorMap map = parse_reflector_map(config);
  config.reject_unknown_keys();
  return map;
}

}  // namespace refloc
