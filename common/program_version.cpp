#include "common/program_version.hpp"

#include "common/refloc_version.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace refloc {

std::string refloc_version() {
  std::string version = std::string("refloc ") + kReflocVersion;
  if (kReflocGitCommit[0] != '\0') version += std::string(" (git ") + kReflocGitCommit + ")";
  return version;
}

void add_version_flag(CLI::App& app, const std::string& program) {
  app.set_version_flag("--version", program + " from " + refloc_version(), "print the version and exit");
}

std::string refloc_root() {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (const char* env = std::getenv("REFLOC_ROOT"); env != nullptr && env[0] != '\0') return env;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  for (fs::path dir = exe.parent_path(); !dir.empty(); dir = dir.parent_path()) {
    if (fs::is_directory(dir / "deploy" / "config", ec)) return dir.string();
    if (dir == dir.root_path()) break;
  }
  return "";
}

std::string shipped_path(const std::string& relative_to_root) {
  if (relative_to_root.empty() || relative_to_root.front() == '/') return relative_to_root;
  const std::string root = refloc_root();
  return root.empty() ? relative_to_root : root + "/" + relative_to_root;
}

}  // namespace refloc
