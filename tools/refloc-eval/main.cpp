// refloc-eval: accuracy studies of the localization pipeline in simulation.
//   refloc-eval paper-table   the paper's Table 1 protocol, both modes side by side
//   refloc-eval random --n N  random poses of a world; also wrong matches, recall, false detections
//   refloc-eval drive         a robot driving a loop: motion compensation by odometry, fixes, none

#include "common/guarded_main.hpp"
#include "common/program_version.hpp"
#include "drive_command.hpp"
#include "drive_options.hpp"
#include "eval_command.hpp"
#include "eval_options.hpp"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"Accuracy studies of refloc's localization in simulation (LMS100 error model)"};
  refloc::add_version_flag(app, "refloc-eval");
  app.require_subcommand(1);
  refloc::EvalOptions o;
  // Shipped files from the refloc root, so refloc-eval runs from any working directory.
  for (std::string* file : {&o.robot_file, &o.extractor_file, &o.matcher_file, &o.solver_file})
    *file = refloc::shipped_path(*file);
  CLI::App* table =
      app.add_subcommand("paper-table", "the paper's Table 1: 10 static positions, 3 scans each");
  refloc::add_eval_options(table, o);
  table->add_option("--repeats", o.repeats, "scans per position")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  CLI::App* random = app.add_subcommand("random", "random poses in a world: accuracy, wrong matches, recall");
  refloc::add_eval_options(random, o);
  random->add_option("--n", o.n, "number of poses")->capture_default_str()->check(CLI::Range(1, 10000000));
  refloc::DriveOptions d;
  for (std::string* file : {&d.world_file, &d.robot_file, &d.extractor_file, &d.matcher_file, &d.solver_file})
    *file = refloc::shipped_path(*file);
  CLI::App* drive = app.add_subcommand(
      "drive", "a moving robot's consecutive scans: motion compensation with odometry, from fixes, none");
  refloc::add_drive_options(drive, d);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  if (drive->parsed())
    return refloc::guarded_main("refloc-eval", [&] { return refloc::run_drive_command(d); });
  const std::string command = table->parsed() ? "paper-table" : "random";
  return refloc::guarded_main("refloc-eval", [&] { return refloc::run_eval(command, o); });
}
