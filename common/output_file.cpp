#include "common/output_file.hpp"

#include "common/json_config.hpp"

#include <filesystem>

namespace refloc {

void refuse_to_replace(const std::string& path, bool force, const std::string& hint) {
  if (force || !std::filesystem::exists(path)) return;
  throw ConfigError(path + ": exists; give --force to replace it" + (hint.empty() ? "" : " (" + hint + ")"));
}

}  // namespace refloc
