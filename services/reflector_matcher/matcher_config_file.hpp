#pragma once
// deploy/config/reflector_matcher.json: the matcher's settings, its map file and
// its channels. Every key is optional (defaults as in MatcherConfig).

#include "reflector_matcher/map_health_config.hpp"
#include "reflector_matcher/matcher_config.hpp"
#include "reflector_matcher/prior_selector.hpp"

#include <string>

namespace refloc {

class JsonConfig;

struct MatcherServiceConfig {
  MatcherConfig matcher;
  std::string map_file;  ///< resolved against the config file's folder when relative
  std::string input_channel = "REFLECTORS";
  std::string prior_channel = "POSE";
  std::string initial_pose_channel = "INITIAL_POSE";
  std::string output_channel = "REFLECTOR_MATCHES";
  PriorSelectionConfig prior;  ///< the file's top-level prior keys
  MapHealthConfig map_health;  ///< "map_health": evidence about the map, MAP_HEALTH
};

/// Read and validate; base_dir resolves a relative map_file (usually the config file's folder).
MatcherServiceConfig parse_matcher_service_config(const JsonConfig& config, const std::string& base_dir);

/// Load, parse and reject unknown keys of the file at path (its folder resolves map_file);
/// an empty path gives the defaults with map_file under deploy/config.
MatcherServiceConfig load_matcher_service_config(const std::string& path);

}  // namespace refloc
