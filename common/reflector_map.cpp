#include "common/reflector_map.hpp"

#include "common/json_config.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>

namespace refloc {
namespace {

// Refuses the first reflector that stands closer than r1 + r2 + gap to an earlier one, as
// the map is read, so a pile at one spot fails at its second reflector. Grid cells are at
// least as wide as the largest pair distance that can fail, so only the 3x3 cells around a
// reflector can hold one too close; a larger radius regrids with doubled cells (at most
// log2(5 m / 1 mm) times).
class SpacingCheck {
 public:
  SpacingCheck(const JsonConfig& config, std::string list) : config_(config), list_(std::move(list)) {}

  void add(const std::vector<MapReflector>& reflectors) {
    const size_t i = reflectors.size() - 1;
    const MapReflector& a = reflectors[i];
    max_radius_ = std::max(max_radius_, a.radius);
    if (2.0 * max_radius_ + kMinReflectorGap_m > cell_)
      regrid(reflectors, 2.0 * (2.0 * max_radius_ + kMinReflectorGap_m));
    const int64_t cx = cell_of(a.map_p_center.x());
    const int64_t cy = cell_of(a.map_p_center.y());
    for (int64_t dx = -1; dx <= 1; ++dx) {
      for (int64_t dy = -1; dy <= 1; ++dy) {
        const auto found = grid_.find(key(cx + dx, cy + dy));
        if (found == grid_.end()) continue;
        for (const size_t j : found->second) check_pair(reflectors, i, j);
      }
    }
    grid_[key(cx, cy)].push_back(i);
  }

 private:
  int64_t cell_of(double v) const { return static_cast<int64_t>(std::floor(v / cell_)); }
  static uint64_t key(int64_t cx, int64_t cy) {
    return (static_cast<uint64_t>(cx) << 32) ^ (static_cast<uint64_t>(cy) & 0xffffffffU);
  }
  void regrid(const std::vector<MapReflector>& reflectors, double cell) {
    cell_ = cell;
    grid_.clear();
    for (size_t j = 0; j + 1 < reflectors.size(); ++j) {
      const Eigen::Vector2d& p = reflectors[j].map_p_center;
      grid_[key(cell_of(p.x()), cell_of(p.y()))].push_back(j);
    }
  }
  void check_pair(const std::vector<MapReflector>& reflectors, size_t i, size_t j) const {
    const MapReflector& a = reflectors[i];
    const MapReflector& b = reflectors[j];
    const double distance = (a.map_p_center - b.map_p_center).norm();
    const double needed = a.radius + b.radius + kMinReflectorGap_m;
    if (distance >= needed) return;
    config_.fail(
        fmt::format("{}/{}", list_, i),
        fmt::format("reflector id {} is {:.3f} m from id {} at {}/{}; centres must be at least {:.3f} m "
                    "apart (radii {} + {} m + {} m gap)",
                    a.id, distance, b.id, list_, j, needed, a.radius, b.radius, kMinReflectorGap_m));
  }

  const JsonConfig& config_;
  std::string list_;
  double max_radius_ = 0.0;
  double cell_ = 0.0;
  std::unordered_map<uint64_t, std::vector<size_t>> grid_;
};

}  // namespace

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
  constexpr double kMaxCoordinate_m = 1e5;  // 100 km: beyond any factory, catches unit mistakes
  const double default_radius =
      config.number({pointer + "/default_radius_m", "m",
                     "cylinder radius of reflectors without their own radius_m (120 mm "
                     "diameter: 0.06); the matcher's occlusion check and the simulator use it"},
                    0.06, 1e-3, 5.0);
  const std::string list = pointer + "/reflectors";
  const size_t n = config.array_size({list, "",
                                      "the reflectors [{id, x, y, radius_m}]: at least 3, centres r1 + r2 + "
                                      "10 mm apart; all on one line only warns"});
  if (n < 3) config.fail(list, fmt::format("expected at least 3 reflectors, got {}", n));

  ReflectorMap map;
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
                               -kMaxCoordinate_m, kMaxCoordinate_m);
    r.map_p_center.y() = config.required_number({item + "/y", "m", "centre y in the map frame"},
                                                -kMaxCoordinate_m, kMaxCoordinate_m);
    r.radius =
        config.number({item + "/radius_m", "m", "this reflector's cylinder radius, if not default_radius_m"},
                      default_radius, 1e-3, 5.0);
    map.reflectors.push_back(r);
    spacing.add(map.reflectors);
  }
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
