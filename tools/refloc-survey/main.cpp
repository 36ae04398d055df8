// refloc-survey: maps the robot makes itself (issue 14). Subcommands:
//   drive    a map from an LCM log of the robot driven through the hall (drive_command.hpp)
//   compare  a map against the true one, after a rigid alignment of frames
//   static   a map of the reflectors around the robot standing still, N scans (static_command.hpp)

#include "common/guarded_main.hpp"
#include "common/program_version.hpp"
#include "drive_command.hpp"
#include "static_command.hpp"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"refloc-survey: reflector maps surveyed by the robot itself"};
  refloc::add_version_flag(app, "refloc-survey");
  app.require_subcommand(1);
  refloc::DriveCommandOptions drive;
  CLI::App* drive_command = refloc::add_drive_command(app, drive);
  refloc::CompareCommandOptions compare;
  CLI::App* compare_command = refloc::add_compare_command(app, compare);
  refloc::StaticCommandOptions static_options;
  CLI::App* static_command = refloc::add_static_command(app, static_options);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  return refloc::guarded_main("refloc-survey", [&] {
    if (drive_command->parsed()) return refloc::run_drive_command(drive);
    if (compare_command->parsed()) return refloc::run_compare_command(compare);
    if (static_command->parsed()) return refloc::run_static_command(static_options);
    return refloc::kExitUsageError;
  });
}
