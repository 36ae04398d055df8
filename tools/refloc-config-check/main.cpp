// refloc-config-check: validate map and config files before deploying them.
// Exit 0 when every file is valid, 2 with one message naming the file, the JSON
// pointer and the expectation for the first error.

#include "common/guarded_main.hpp"
#include "common/json_config.hpp"
#include "common/reflector_map.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"Validate refloc map files; exit 2 naming file and key on the first error"};
  std::vector<std::string> map_files;
  app.add_option("--map", map_files, "reflector map file (JSON); may be repeated")->required();
  CLI11_PARSE(app, argc, argv);
  return refloc::guarded_main("refloc-config-check", [&] {
    for (const auto& path : map_files) {
      const refloc::ReflectorMap map = refloc::load_reflector_map(path);
      fmt::print("{}: ok, {} reflectors\n", path, map.reflectors.size());
    }
    return 0;
  });
}
