#include "config_check.hpp"

#include "common/json_config.hpp"
#include "common/reflector_map.hpp"
#include "common/robot_config.hpp"
#include "lms100_driver/driver_config_file.hpp"
#include "mecanum_odometry/odometry_config_file.hpp"
#include "navigator/navigator_config_file.hpp"
#include "pose_fusion/fusion_config_file.hpp"
#include "pose_solver/solver_config_file.hpp"
#include "quick_layout_check.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "reflector_matcher/matcher_config_file.hpp"
#include "robot_sim/sim_setup.hpp"
#include "world_renderer/world_loader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>

namespace refloc {
namespace {

using Checker = std::function<FileCheck(const std::string&)>;

FileCheck loaded(const std::string& what) { return FileCheck{"ok, " + what, {}}; }

const std::map<std::string, Checker>& checkers() {
  static const std::map<std::string, Checker> table = {
      {"lms100_driver",
       [](const std::string& p) { return load_driver_config_file(p), loaded("lms100_driver config"); }},
      {"mecanum_odometry",
       [](const std::string& p) {
         return load_odometry_service_config(p), loaded("mecanum_odometry config");
       }},
      {"navigator",
       [](const std::string& p) { return load_navigator_service_config(p), loaded("navigator config"); }},
      {"pose_fusion",
       [](const std::string& p) { return load_fusion_service_config(p), loaded("pose_fusion config"); }},
      {"pose_solver",
       [](const std::string& p) { return load_solver_service_config(p), loaded("pose_solver config"); }},
      {"reflector_extractor",
       [](const std::string& p) {
         return load_extractor_service_config(p), loaded("reflector_extractor config");
       }},
      {"reflector_matcher",
       [](const std::string& p) {
         const MatcherServiceConfig config = load_matcher_service_config(p);
         FileCheck map = check_map_file(config.map_file);
         map.summary = fmt::format("ok, reflector_matcher config, map {} {}", config.map_file, map.summary);
         return map;
       }},
      {"robot", [](const std::string& p) { return load_robot_config(p), loaded("robot config"); }},
      {"robot_sim",
       [](const std::string& p) {
         const SimSetup setup = load_sim_setup(p, SimOverrides{});
         if (!setup.world_path.empty()) sim::load_world(setup.world_path);
         return loaded(setup.world_path.empty() ? "robot_sim config"
                                                : "robot_sim config, world " + setup.world_path);
       }},
  };
  return table;
}

}  // namespace

const std::vector<std::string>& checkable_services() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& [name, checker] : checkers()) out.push_back(name);
    return out;
  }();
  return names;
}

std::pair<std::string, std::string> split_config_argument(const std::string& argument) {
  const size_t equals = argument.find('=');
  std::string service = equals == std::string::npos ? std::filesystem::path(argument).stem().string()
                                                    : argument.substr(0, equals);
  const std::string path = equals == std::string::npos ? argument : argument.substr(equals + 1);
  if (checkers().count(service) == 0) {
    std::string known;
    for (const auto& name : checkable_services()) known += (known.empty() ? "" : ", ") + name;
    throw ConfigError(fmt::format(
        "{}: cannot tell which service reads it; name it as SERVICE=FILE, SERVICE one of {}", path, known));
  }
  return {service, path};
}

FileCheck check_map_file(const std::string& path) {
  const ReflectorMap map = load_reflector_map(path);
  std::vector<std::string> warnings = map.warnings;
  // refloc-plan's quick version: a layout that localizes nowhere or is ambiguous somewhere
  // (not repeated for a colinear map, whose warning already says the pose is not observable).
  if (warnings.empty()) {
    const QuickLayoutCheck layout = quick_layout_check(map, path);
    if (!layout.warning.empty()) warnings.push_back(layout.warning);
  }
  if (map.info.format == 1) {
    return FileCheck{fmt::format("ok, {} reflectors, format 1", map.reflectors.size()), warnings};
  }
  const long with_covariance =
      std::count_if(map.reflectors.begin(), map.reflectors.end(),
                    [](const MapReflector& r) { return r.map_cov_center.has_value(); });
  return FileCheck{
      fmt::format("ok, {} reflectors ({} with covariance, {} without), {} occluders, format 2, "
                  "map {} version {}, {}, created {}",
                  map.reflectors.size(), with_covariance,
                  static_cast<long>(map.reflectors.size()) - with_covariance, map.occluders.size(),
                  map.info.map_id, map.info.version, map.info.source, map.info.created),
      warnings};
}

FileCheck check_config_file(const std::string& service, const std::string& path) {
  const auto found = checkers().find(service);
  if (found == checkers().end()) throw ConfigError(fmt::format("{}: unknown service {}", path, service));
  return found->second(path);
}

}  // namespace refloc
