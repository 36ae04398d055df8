#include "common/guarded_main.hpp"

#include "common/json_config.hpp"

#include <cstdio>
#include <exception>

namespace refloc {

int guarded_main(const std::string& program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
    return kExitConfigError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: fatal: %s\n", program.c_str(), e.what());
    return 1;
  }
}

}  // namespace refloc
