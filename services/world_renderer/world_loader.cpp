#include "world_renderer/world_loader.hpp"

#include "common/json_config.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <map>

namespace refloc::sim {
namespace {

constexpr double kMaxCoordinate_m = 1e5;  // as common/reflector_map.cpp: catches mm-for-m mistakes

Eigen::Vector2d read_point(const JsonConfig& config, const std::string& pointer) {
  const size_t n = config.array_size({pointer, "m", "a point [x, y] in the map frame"});
  if (n != 2) config.fail(pointer, fmt::format("expected a point [x, y], got an array of {}", n));
  return {config.required_number({pointer + "/0", "m", "x, then y, of the point in the map frame"},
                                 -kMaxCoordinate_m, kMaxCoordinate_m),
          config.required_number(pointer + "/1", -kMaxCoordinate_m, kMaxCoordinate_m)};
}

// what names the list's things for the reference ("walls: ..."); every list is optional.
void read_polylines(const JsonConfig& config, const std::string& list, const std::string& what,
                    bool with_surface, double default_remission, World& world) {
  const size_t n = config.array_size({list, "", what}, false);
  std::vector<Eigen::Vector2d> points;
  for (size_t i = 0; i < n; ++i) {
    const std::string item = fmt::format("{}/{}", list, i);
    config.string({item + "/name", "", "a name for people reading the file; not used"}, "");
    SurfaceKind surface = SurfaceKind::kDiffuse;
    double remission_default = default_remission;
    if (with_surface) {
      const std::string kind =
          config.choice({item + "/surface", "",
                         "tape: reflective tape, as bright as a reflector head-on; metal: a specular glint"},
                        "", {"tape", "metal"});
      surface = kind == "tape" ? SurfaceKind::kReflectiveTape : SurfaceKind::kMetal;
      remission_default = surface == SurfaceKind::kReflectiveTape ? 0.8 : 0.05;
    }
    // Real surfaces lie between 2 % (black) and ~100 % (white paper); up to 2
    // allows glossy paint that beats white paper at normal incidence.
    const double remission = config.number({item + "/remission", "",
                                            "diffuse reflectivity (black 0.02, white paper 1): sets RSSI and "
                                            "detection range; default 0.5, tape 0.8, "
                                            "metal 0.05"},
                                           remission_default, 0.02, 2.0);
    const bool closed =
        config.boolean({item + "/closed", "", "true: the last point joins the first (a room, a box)"}, false);
    const std::string list_of_points = item + "/points";
    const size_t count =
        config.array_size({list_of_points, "m", "the polyline's corners [[x, y], ...], at least 2"});
    if (count < 2) config.fail(list_of_points, fmt::format("expected at least 2 points, got {}", count));
    if (closed && count < 3) config.fail(item + "/closed", "a closed polyline needs at least 3 points");
    points.clear();
    for (size_t k = 0; k < count; ++k) {
      const std::string point = fmt::format("{}/{}", list_of_points, k);
      points.push_back(read_point(config, point));
      if (k > 0 && (points[k] - points[k - 1]).norm() < 1e-6) {
        config.fail(point, "repeats the previous point (a zero-length segment)");
      }
    }
    add_polyline(world, points, closed, surface, remission);
  }
}

void read_unmapped_reflectors(const JsonConfig& config, const std::string& list, World& world) {
  const size_t n = config.array_size(
      {list, "", "reflectors in the world but not in the map (a robustness test): [{id, x, y, radius_m}]"},
      false);
  for (size_t i = 0; i < n; ++i) {
    const std::string item = fmt::format("{}/{}", list, i);
    MapReflector r;
    r.id = static_cast<int>(config.required_integer(
        {item + "/id", "", "id of a reflector that stands in the world but not in the map; unique in both"},
        0, 1000000000));
    const int clash = world.reflectors.index_of(r.id);
    if (clash >= 0) {
      config.fail(item + "/id",
                  fmt::format("duplicate reflector id {} (already in the map file, index {})", r.id, clash));
    }
    r.map_p_center.x() = config.required_number({item + "/x", "m", "centre x of the unmapped reflector"},
                                                -kMaxCoordinate_m, kMaxCoordinate_m);
    r.map_p_center.y() = config.required_number({item + "/y", "m", "centre y of the unmapped reflector"},
                                                -kMaxCoordinate_m, kMaxCoordinate_m);
    r.radius = config.number({item + "/radius_m", "m", "cylinder radius of the unmapped reflector"}, 0.06,
                             1e-3, 5.0);
    world.reflectors.reflectors.push_back(r);
  }
}

void read_map_errors(const JsonConfig& config, const std::string& pointer, World& world) {
  auto& reflectors = world.reflectors.reflectors;
  const std::string moved = pointer + "/moved_reflectors";
  const size_t num_moved = config.array_size(
      {moved, "", "map error for robustness tests: mapped reflectors that stand elsewhere in the world"},
      false);
  for (size_t i = 0; i < num_moved; ++i) {
    const std::string item = fmt::format("{}/{}", moved, i);
    const long long id =
        config.required_integer({item + "/id", "", "id of the map reflector that was moved"}, 0, 1000000000);
    const int index = world.reflectors.index_of(static_cast<int>(id));
    if (index < 0) config.fail(item + "/id", fmt::format("no reflector with id {} in the map", id));
    reflectors[index].map_p_center.x() =
        config.required_number({item + "/x", "m", "where the moved reflector really stands, x"},
                               -kMaxCoordinate_m, kMaxCoordinate_m);
    reflectors[index].map_p_center.y() =
        config.required_number({item + "/y", "m", "where the moved reflector really stands, y"},
                               -kMaxCoordinate_m, kMaxCoordinate_m);
  }
  const std::string missing = pointer + "/missing_reflector_ids";
  const size_t num_missing = config.array_size(
      {missing, "", "map error for robustness tests: ids of mapped reflectors absent from the world"}, false);
  for (size_t i = 0; i < num_missing; ++i) {
    const std::string item = fmt::format("{}/{}", missing, i);
    const long long id =
        config.required_integer({item, "", "id of a map reflector the world lacks"}, 0, 1000000000);
    const int index = world.reflectors.index_of(static_cast<int>(id));
    if (index < 0) config.fail(item, fmt::format("no reflector with id {} in the map (or listed twice)", id));
    reflectors.erase(reflectors.begin() + index);
  }
}

void read_drivable_areas(const JsonConfig& config, const std::string& list, World& world) {
  const size_t n = config.array_size({list, "",
                                      "rectangles where refloc-eval random draws test poses (each 0.4 m from "
                                      "any surface); it needs at least one"},
                                     false);
  for (size_t i = 0; i < n; ++i) {
    const std::string item = fmt::format("{}/{}", list, i);
    DrivableArea a;
    a.x_min = config.required_number({item + "/x_min", "m", "lower x edge of the drivable rectangle"},
                                     -kMaxCoordinate_m, kMaxCoordinate_m);
    a.y_min = config.required_number({item + "/y_min", "m", "lower y edge of the drivable rectangle"},
                                     -kMaxCoordinate_m, kMaxCoordinate_m);
    a.x_max =
        config.required_number({item + "/x_max", "m", "upper x edge, >= x_min"}, a.x_min, kMaxCoordinate_m);
    a.y_max =
        config.required_number({item + "/y_max", "m", "upper y edge, >= y_min"}, a.y_min, kMaxCoordinate_m);
    world.drivable_areas.push_back(a);
  }
}

}  // namespace

World parse_world(const JsonConfig& config, const std::string& pointer, const std::string& base_dir) {
  World world;
  world.description =
      config.string({pointer + "/description", "", "what this world is, for people; not used"}, "");
  const std::string map_key = pointer + "/map_file";
  if (!config.has(map_key)) config.fail(map_key, "missing; expected the path of a reflector map file");
  const std::string map_name = config.string(
      {map_key, "",
       "the reflector map (required), relative to this file: the reflectors rendered are the mapped ones"},
      "");
  if (map_name.empty()) config.fail(map_key, "expected a non-empty path");
  std::filesystem::path map_path(map_name);
  if (map_path.is_relative() && !base_dir.empty()) map_path = std::filesystem::path(base_dir) / map_path;
  world.map_file = map_path.lexically_normal().string();
  try {
    world.reflectors = load_reflector_map(world.map_file);
  } catch (const ConfigError& e) {
    // Name both: where the reference is and what is wrong in the referenced file.
    config.fail(map_key, fmt::format("cannot use the map: {}", e.what()));
  }

  read_polylines(config, pointer + "/walls", "walls: diffuse polylines [{name, points, closed, remission}]",
                 false, 0.5, world);
  read_polylines(config, pointer + "/obstacles", "racks, pillars, machines: diffuse polylines like walls",
                 false, 0.5, world);
  read_polylines(config, pointer + "/distractors",
                 "bright non-reflectors (tape, metal) the extractor must not take for reflectors", true, 0.05,
                 world);
  read_map_errors(config, pointer, world);
  read_unmapped_reflectors(config, pointer + "/unmapped_reflectors", world);
  read_drivable_areas(config, pointer + "/drivable_areas", world);
  return world;
}

World load_world(const std::string& path) {
  const JsonConfig config = JsonConfig::load_file(path);
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  World world = parse_world(config, "", base_dir);
  config.reject_unknown_keys();
  return world;
}

}  // namespace refloc::sim
