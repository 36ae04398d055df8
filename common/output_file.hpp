#pragma once
// The tools' rule for files they write (maps, logs, CSV): never replace one silently.

#include <string>

namespace refloc {

/// Throws ConfigError "PATH: exists; give --force to replace it" when path exists and force is
/// false; hint, when not empty, is appended in parentheses ("or another --out").
void refuse_to_replace(const std::string& path, bool force, const std::string& hint = "");

}  // namespace refloc
