#pragma once
// refloc-map merge: one map from several surveys of the same hall in the same frame (static
// surveys from several standing poses, or a drive survey and a static one). The first map is the
// reference; an entry of a later map within --gate-m of a merged entry is the same reflector and
// their positions are averaged, weighted by 1 / trace(covariance) (equal weights when a map has
// none); an entry that matches nothing is added with the next free id. LCM-free.

#include "common/reflector_map.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace refloc {

struct MergeCommandOptions {
  std::vector<std::string> map_paths;
  std::string out_path;
  std::string map_id;    ///< default: the first map's
  double gate_m = 0.10;  ///< entries closer than this are one reflector [m]
  bool force = false;
};

CLI::App* add_merge_command(CLI::App& app, MergeCommandOptions& o);
int run_merge_command(const MergeCommandOptions& o);

struct MapMergePlan {
  ReflectorMap merged;
  std::vector<std::string> lines;  ///< one a merged or added entry
  int averaged = 0, added = 0;
};

/// Merges maps (names: their files, for the lines) into one format-2 map: the first map's header
/// (version + 1, source "merged", created), occluders of every map, reflectors as said above.
/// Throws ConfigError when two entries of one later map fall on the same merged reflector (the
/// gate is wider than the layout's spacing), naming both.
MapMergePlan plan_map_merge(const std::vector<ReflectorMap>& maps, const std::vector<std::string>& names,
                            double gate_m, const std::string& created);

}  // namespace refloc
