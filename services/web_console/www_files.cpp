#include "web_console/www_files.hpp"

#include "common/json_config.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace refloc {

std::map<std::string, WwwFile> load_www_files(const std::string& dir) {
  namespace fs = std::filesystem;
  const std::map<std::string, std::string> types = {{".html", "text/html; charset=utf-8"},
                                                    {".js", "text/javascript; charset=utf-8"},
                                                    {".css", "text/css; charset=utf-8"}};
  std::map<std::string, WwwFile> files;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    const auto type = types.find(entry.path().extension().string());
    if (type == types.end() || !entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream body;
    body << in.rdbuf();
    if (!in) throw ConfigError(entry.path().string() + ": cannot be read");
    files["/" + entry.path().filename().string()] = {type->second, body.str()};
  }
  if (ec) throw ConfigError(dir + ": the page's folder cannot be read: " + ec.message());
  const auto index = files.find("/index.html");
  if (index == files.end()) throw ConfigError(dir + ": no index.html (www_dir)");
  files["/"] = index->second;
  return files;
}

}  // namespace refloc
