// refloc-map: map files in and out of refloc (docs/map-format.md). Subcommands:
//   import   a format-2 map from a CSV (a total-station survey)
//   export   a map's reflectors as CSV
//   info     what a map holds
//   update   the next version from the matcher's MAP_HEALTH evidence in an LCM log
//   merge    one map from several surveys in the same frame
// Each is an add_*_command / run_*_command pair in the library.
// Exit 0 done, 2 bad input file (named with file and key or line), 64 usage error.

#include "common/guarded_main.hpp"
#include "common/program_version.hpp"
#include "map_commands.hpp"
#include "map_merge.hpp"
#include "map_update.hpp"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{
      "refloc-map: reflector map files: import from CSV, export to CSV, info, update from MAP_HEALTH, merge "
      "surveys"};
  refloc::add_version_flag(app, "refloc-map");
  app.require_subcommand(1);
  refloc::ImportCommandOptions import_options;
  CLI::App* import_command = refloc::add_import_command(app, import_options);
  refloc::ExportCommandOptions export_options;
  CLI::App* export_command = refloc::add_export_command(app, export_options);
  refloc::InfoCommandOptions info_options;
  CLI::App* info_command = refloc::add_info_command(app, info_options);
  refloc::UpdateCommandOptions update_options;
  CLI::App* update_command = refloc::add_update_command(app, update_options);
  refloc::MergeCommandOptions merge_options;
  CLI::App* merge_command = refloc::add_merge_command(app, merge_options);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  return refloc::guarded_main("refloc-map", [&] {
    if (import_command->parsed()) return refloc::run_import_command(import_options);
    if (export_command->parsed()) return refloc::run_export_command(export_options);
    if (info_command->parsed()) return refloc::run_info_command(info_options);
    if (update_command->parsed()) return refloc::run_update_command(update_options);
    if (merge_command->parsed()) return refloc::run_merge_command(merge_options);
    return refloc::kExitUsageError;
  });
}
