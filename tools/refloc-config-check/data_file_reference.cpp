#include "data_file_reference.hpp"

#include "common/config_reference.hpp"
#include "common/json_config.hpp"
#include "common/program_version.hpp"
#include "common/reflector_map.hpp"
#include "mission_file.hpp"
#include "world_renderer/world_loader.hpp"

#include <filesystem>

namespace refloc {
namespace {

// Every key at least once: keys inside array elements are only recorded when an element exists.
constexpr const char* kMapExample = R"({"format": 2, "map_id": "example_hall", "version": 1,
  "created": "2026-12-03T06:30:58Z", "source": "surveyed", "default_radius_m": 0.06, "reflectors": [
  {"id": 1, "x": 0.0, "y": 0.0, "covariance_m2": [4e-6, 0, 4e-6]},
  {"id": 2, "x": 5.0, "y": 0.0, "radius_m": 0.05, "type": "cylinder_100"}, {"id": 3, "x": 0.0, "y": 4.0}],
  "occluders": [{"name": "hall", "points": [[-0.1, -0.1], [6, -0.1], [6, 5]], "closed": true}]})";

constexpr const char* kWorldExample = R"({"description": "example", "map_file": "map_demo.json",
  "walls": [{"name": "hall", "points": [[0, 0], [20, 0], [20, 12], [0, 12]], "closed": true, "remission": 0.6}],
  "obstacles": [{"name": "rack", "points": [[5, 5], [9, 5], [9, 7], [5, 7]], "closed": true, "remission": 0.3}],
  "distractors": [{"name": "tape", "surface": "tape", "points": [[6.5, 4.98], [6.6, 4.98]], "remission": 0.8}],
  "moved_reflectors": [{"id": 1, "x": 0.55, "y": 0.35}],
  "missing_reflector_ids": [2],
  "unmapped_reflectors": [{"id": 900, "x": 10.0, "y": 8.0, "radius_m": 0.06}],
  "drivable_areas": [{"x_min": 1, "y_min": 1, "x_max": 19, "y_max": 4}]})";

constexpr const char* kMissionExample = R"({"waypoints": [{"x_m": 8.0, "y_m": 2.0, "theta_deg": 90}],
  "xy_tolerance_m": 0.01, "heading_tolerance_deg": 0.5, "max_speed_m_s": 1.0, "timeout_s": 240,
  "localization_timeout_s": 60})";

}  // namespace

const std::vector<std::string>& data_file_kinds() {
  static const std::vector<std::string> kinds{"map", "world", "mission"};
  return kinds;
}

std::string data_file_reference_markdown(const std::string& kind) {
  if (kind == "map") {
    const JsonConfig config = JsonConfig::parse_text(kMapExample, "built-in map example");
    parse_reflector_map(config);
    return config_reference_markdown(config.key_records());
  }
  if (kind == "world") {
    const JsonConfig config = JsonConfig::parse_text(kWorldExample, "built-in world example");
    const std::string map_dir =
        std::filesystem::path(shipped_path("deploy/config/map_demo.json")).parent_path().string();
    sim::parse_world(config, "", map_dir);
    return config_reference_markdown(config.key_records());
  }
  if (kind == "mission") {
    const JsonConfig config = JsonConfig::parse_text(kMissionExample, "built-in mission example");
    parse_mission(config);
    return config_reference_markdown(config.key_records());
  }
  throw ConfigError("--print-reference: unknown kind \"" + kind + "\" (map, world or mission)");
}

}  // namespace refloc
