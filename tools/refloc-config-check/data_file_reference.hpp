#pragma once
// The key reference of the data files users edit (map, world, mission): each file's own reader
// run on a small built-in example that uses every key, its records printed as Markdown
// (refloc-config-check --print-reference KIND; docs/generate-parameters.sh appends them).

#include <string>
#include <vector>

namespace refloc {

/// "map", "world", "mission".
const std::vector<std::string>& data_file_kinds();

/// The Markdown table of the kind's keys; throws ConfigError for an unknown kind. The world
/// example names the shipped deploy/config/map_demo.json (found through shipped_path).
std::string data_file_reference_markdown(const std::string& kind);

}  // namespace refloc
