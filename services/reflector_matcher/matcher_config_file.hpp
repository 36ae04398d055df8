#pragma once
// deploy/config/reflector_matcher.json: the matcher's settings, its map file and
// its channels. Every key is optional (defaults as in MatcherConfig).

#include "reflector_matcher/matcher_config.hpp"

#include <string>

namespace refloc {

class JsonConfig;

struct MatcherServiceConfig {
  MatcherConfig matcher;
  std::string map_file;  ///< resolved against the config file's folder when relative
  std::string input_channel = "REFLECTORS";
  std::string prior_channel = "POSE";
  std::string output_channel = "REFLECTOR_MATCHES";
  double prior_max_age = 0.5;         ///< [s] a POSE older than this (vs the scan) is not used
  bool use_own_pose_as_prior = true;  ///< track from the last OK match when no POSE is fresh
  double own_prior_sigma_xy = 0.3;    ///< [m] std dev assumed for the own previous pose
  double own_prior_sigma_theta = 5.0 * M_PI / 180.0;  ///< [rad]
  /// After start, ignore priors until a global relocalization is OK, for at most
  /// this long (StartupRelocalization); 0 = track from POSE at once [s].
  double relocalize_on_start = 2.0;
};

/// Read and validate; base_dir resolves a relative map_file (usually the config file's folder).
MatcherServiceConfig parse_matcher_service_config(const JsonConfig& config, const std::string& base_dir);

}  // namespace refloc
