#include "common/guarded_main.hpp"

#include "common/json_config.hpp"

#include <cstdio>
#include <exception>
#include <string>

namespace refloc {
namespace {

// One line on stderr whatever the message carries (a file name or library text with a
// newline), so supervisors and tests see exactly one line per failure.
std::string one_line(const char* text) {
  std::string out;
  for (const char* p = text; *p != '\0'; ++p) out += (*p == '\n' || *p == '\r') ? ' ' : *p;
  return out;
}

}  // namespace

int guarded_main(const std::string& program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), one_line(e.what()).c_str());
    return kExitConfigError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: fatal: %s\n", program.c_str(), one_line(e.what()).c_str());
    return 1;
  }
}

}  // namespace refloc
