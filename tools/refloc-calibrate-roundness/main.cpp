// refloc-calibrate-roundness: reproduce the paper's §3.3-3.4 roundness calibration.
//   simulate (default): 276 placements (0.25..3 m every 0.25 m x -110..110 deg every 10 deg),
//     d-bar of each from paper-mode extraction, line fitted over 0.75..3 m, raised 30 mm;
//   --log FILE: the same fit over the REFLECTORS detections of an LCM log (range, roundness_m).
// Prints the table, the fitted and the raised line, and the config keys to paste.

#include "calibration_command.hpp"
#include "common/guarded_main.hpp"
#include "common/program_version.hpp"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"refloc-calibrate-roundness: fit the paper's roundness line (d-bar against distance, §3.4)"};
  refloc::add_version_flag(app, "refloc-calibrate-roundness");
  refloc::CalibrationOptions o;
  app.add_option("--log", o.log_path, "LCM log with REFLECTORS messages (default: simulate)");
  app.add_option("--channel", o.channel, "channel of the detections in the log")->capture_default_str();
  app.add_option("--renderer", o.renderer, "simulation: emulator (LMS100 model) or synthetic")
      ->check(CLI::IsMember({"emulator", "synthetic"}))
      ->capture_default_str();
  app.add_option("--drop-points", o.drop_points, "first and last n points left out of d-bar")
      ->check(CLI::Range(0, 20))
      ->capture_default_str();
  app.add_option("--scans", o.scans, "scans per placement")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_option("--raise-mm", o.raise_mm, "how far the fitted line is raised [mm]")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  app.add_option("--fit-min-m", o.fit_min, "fit only distances from [m]")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  app.add_option("--fit-max-m", o.fit_max, "fit only distances up to [m]")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  app.add_option("--distance-max-m", o.distance_max, "farthest placement [m]")
      ->check(CLI::Range(0.25, 20.0))
      ->capture_default_str();
  app.add_option("--range-sigma-m", o.range_sigma, "range noise of the synthetic renderer [m]")
      ->check(CLI::Range(0.0, 0.2))
      ->capture_default_str();
  app.add_option("--seed", o.seed, "random seed")->capture_default_str();
  app.add_option("--csv", o.csv_path, "also write the samples to this CSV file");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  return refloc::guarded_main("refloc-calibrate-roundness", [&] { return refloc::run_calibration(o); });
}
