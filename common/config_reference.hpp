#pragma once
// The parameter reference from the readers themselves: what JsonConfig recorded while a
// service read its file (or read {} for its built-in defaults) printed as a commented config
// file that is itself valid input (--print-config), or as the Markdown of docs/parameters.md.

#include "common/json_config.hpp"

#include <string>
#include <vector>

namespace refloc {

/// The keys as a JSON-with-comments config file: each key's effective value under a comment
/// with its meaning, unit, type, range and default. heading becomes the first comment lines.
std::string annotated_config_text(const std::vector<ConfigKeyRecord>& keys, const std::string& heading);

/// The keys as a Markdown table (key, type, unit, default, range, meaning), values as defaults.
std::string config_reference_markdown(const std::vector<ConfigKeyRecord>& keys);

/// Pointers of the keys that have no meaning: a reader call that documents nothing.
std::vector<std::string> undocumented_keys(const std::vector<ConfigKeyRecord>& keys);

}  // namespace refloc
