// refloc-calibrate-rssi: the extractor's energy threshold from a log. LMS100_SCAN goes
// through the extractor library as the service runs it (input checks, RSSI scale verdict,
// extraction with the config's or a lower labelling threshold); the echo beams within a
// reflector radius of a detection are "reflector", all others "other"; both RSSI
// distributions are printed by range band and a threshold is recommended midway between
// the other beams' 99.9th and the reflector beams' 1st percentile, with both margins.
// Exit 0 with a recommendation, 1 without one (not separable, no reflector), 2 bad input.

#include "common/guarded_main.hpp"
#include "common/program_version.hpp"
#include "rssi_calibration_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>

int main(int argc, char** argv) {
  CLI::App app{"refloc-calibrate-rssi: RSSI of reflector and other beams in a log, and an energy threshold"};
  refloc::add_version_flag(app, "refloc-calibrate-rssi");
  refloc::RssiCalibrationOptions o;
  app.add_option("--log", o.log_path, "LCM log with laser scans")->required()->check(CLI::ExistingFile);
  app.add_option("--channel", o.channel, "channel of the scans")->capture_default_str();
  app.add_option("--config", o.config_path, "extractor config (default: the code defaults)")
      ->check(CLI::ExistingFile);
  app.add_option("--label-threshold-8bit", o.label_threshold,
                 "energy threshold of the labelling extraction (default: the config's)")
      ->check(CLI::Range(0.0, 255.0));
  app.add_option("--tolerance-m", o.tolerance,
                 "beams within reflector radius + this of a detection are its [m]")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  app.add_option("--core-fraction", o.core_fraction,
                 "reflector beams pass within this fraction of the radius of a detected centre")
      ->check(CLI::Range(0.05, 1.0))
      ->capture_default_str();
  app.add_option(
         "--label-min-beams", o.label_min_beams,
         "min_beams of the labelling extraction (1 labels far one-beam reflectors; default: the config's)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--band-edges-m", o.band_edges, "range band limits [m], increasing, comma-separated")
      ->delimiter(',')
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--plot", o.plot_path, "write both RSSI histograms with the threshold as SVG");
  try {
    app.parse(argc, argv);
    if (!std::is_sorted(o.band_edges.begin(), o.band_edges.end()))
      throw CLI::ValidationError("--band-edges-m", "must be increasing");
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  return refloc::guarded_main("refloc-calibrate-rssi", [&] { return refloc::run_rssi_calibration(o); });
}
