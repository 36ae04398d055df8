#pragma once
// The page's files, read once at start: the server answers from memory, so a request can name
// nothing outside them (no path is ever opened from a URL).

#include <map>
#include <string>

namespace refloc {

struct WwwFile {
  std::string content_type;
  std::string body;
};

/// Every *.html, *.js and *.css directly in dir, by URL path ("/index.html", "/app.js"; "/" is
/// index.html). Throws ConfigError naming dir when it holds no index.html or a file cannot be read.
std::map<std::string, WwwFile> load_www_files(const std::string& dir);

}  // namespace refloc
