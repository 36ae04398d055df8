#pragma once
// What refloc-config-check checks: a map, or a service's config file read by the service's
// own loader (so the tool and the service can never disagree about a file), plus the files
// that config names (the matcher's map, robot_sim's world).

#include <string>
#include <utility>
#include <vector>

namespace refloc {

struct FileCheck {
  std::string summary;                ///< "ok, ..." for the report line
  std::vector<std::string> warnings;  ///< accepted but doubtful (a colinear map)
};

/// The services whose config files the tool reads, by the name of their program.
const std::vector<std::string>& checkable_services();

/// "NAME=FILE", or FILE named after its service (deploy/config/reflector_matcher.json).
/// Throws ConfigError when no service can be told.
std::pair<std::string, std::string> split_config_argument(const std::string& argument);

FileCheck check_map_file(const std::string& path);
/// Throws ConfigError naming file and key, exactly as the service would at start.
FileCheck check_config_file(const std::string& service, const std::string& path);

}  // namespace refloc
