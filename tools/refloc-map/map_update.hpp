#pragma once
// refloc-map update: the next version of a map from the matcher's evidence, the last MAP_HEALTH
// (map_health_t) for that map id and version in an LCM log. Candidates become new reflectors,
// missing ones are removed, moved ones corrected; each change is printed, and nothing is
// written with --dry-run. The planning (plan_map_update) is LCM-free; reading the log is not.

#include "reflector_matcher/map_health_report.hpp"

#include "common/reflector_map.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace refloc {

struct UpdateCommandOptions {
  std::string map_path;
  std::string evidence_path;  ///< an LCM log
  std::string out_path;
  std::string channel = "MAP_HEALTH";
  std::string map_id;  ///< for a format-1 map, which has none: default the map file's name
  bool add_candidates = false;
  bool remove_missing = false;
  bool move_moved = false;
  bool dry_run = false;
  bool force = false;
};

CLI::App* add_update_command(CLI::App& app, UpdateCommandOptions& o);
int run_update_command(const UpdateCommandOptions& o);

/// Which kinds of change to make.
struct MapUpdateSelection {
  bool add_candidates = true;
  bool remove_missing = true;
  bool move_moved = true;
};

struct MapUpdatePlan {
  ReflectorMap next;               ///< the map with the changes (info: version + 1, source "updated")
  std::vector<std::string> lines;  ///< one a change made, and one a change left out
  int added = 0, removed = 0, moved = 0;
};

/// Refuses (ConfigError naming source) evidence about another map: another map id or version,
/// or a reflector id or position the map does not have.
void check_evidence_is_for(const ReflectorMap& map, const MapHealthReport& evidence,
                           const std::string& source);

/// The next version of map after the selected changes of evidence. New reflectors get ids after
/// the largest in the map; moved and added ones get the evidence's std devs as covariance.
/// created: the new header's time (ISO 8601 UTC).
MapUpdatePlan plan_map_update(const ReflectorMap& map, const MapHealthReport& evidence,
                              const MapUpdateSelection& selection, const std::string& created);

/// The last MAP_HEALTH on channel in the LCM log at path that is about map (same map id and
/// version). ConfigError when the log cannot be read, has no MAP_HEALTH, or only some for
/// another map (naming which).
MapHealthReport last_map_health(const std::string& path, const std::string& channel, const ReflectorMap& map);

}  // namespace refloc
