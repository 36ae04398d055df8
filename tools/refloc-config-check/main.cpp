// refloc-config-check: validate map and config files before deploying them.
// Exit 0 when every file is valid, 2 with one message naming the file, the JSON
// pointer and the expectation for the first error. Warnings (a colinear map) go to
// stderr and do not fail the check unless --strict.

#include "common/guarded_main.hpp"
#include "common/json_config.hpp"
#include "common/program_version.hpp"
#include "config_check.hpp"
#include "data_file_reference.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <cstdio>

namespace {

void report(const std::string& path, const refloc::FileCheck& check, bool strict) {
  for (const auto& w : check.warnings) {
    if (strict) throw refloc::ConfigError(w + " (--strict)");
    std::fprintf(stderr, "refloc-config-check: warning: %s\n", w.c_str());
  }
  fmt::print("{}: {}\n", path, check.summary);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Validate refloc map and config files; exit 2 naming file and key on the first error"};
  refloc::add_version_flag(app, "refloc-config-check");
  std::vector<std::string> map_files;
  std::vector<std::string> config_files;
  bool strict = false;
  app.add_option("--map", map_files, "reflector map file (JSON); may be repeated");
  app.add_option("--config", config_files,
                 "service config file, SERVICE=FILE or named after its service (reflector_extractor.json); "
                 "may be repeated");
  app.add_flag("--strict", strict, "warnings (colinear map) fail with exit 2");
  std::string reference_kind;
  app.add_option("--print-reference", reference_kind,
                 "print the key reference (Markdown) of a data file and exit")
      ->check(CLI::IsMember(refloc::data_file_kinds()));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  if (!reference_kind.empty()) {
    return refloc::guarded_main("refloc-config-check", [&] {
      fmt::print("{}", refloc::data_file_reference_markdown(reference_kind));
      return 0;
    });
  }
  if (map_files.empty() && config_files.empty()) {
    std::fprintf(stderr, "refloc-config-check: give at least one --map or --config\n%s", app.help().c_str());
    return refloc::kExitUsageError;
  }
  return refloc::guarded_main("refloc-config-check", [&] {
    for (const auto& path : map_files) report(path, refloc::check_map_file(path), strict);
    for (const auto& argument : config_files) {
      const auto [service, path] = refloc::split_config_argument(argument);
      report(path, refloc::check_config_file(service, path), strict);
    }
    return 0;
  });
}
