#pragma once
// refloc-calibrate-roundness's work: samples from simulated placements or an LCM log, the
// paper's line fitted and raised, the table and the config keys printed.

#include <cstdint>
#include <string>

namespace refloc {

/// The command line of refloc-calibrate-roundness.
struct CalibrationOptions {
  std::string log_path;
  std::string channel = "REFLECTORS";
  std::string renderer = "emulator";
  std::string csv_path;
  int drop_points = 1;
  int scans = 1;
  double raise_mm = 30.0;
  double fit_min = 0.75;
  double fit_max = 3.0;
  double distance_max = 3.0;
  double range_sigma = 0.012;
  uint64_t seed = 1;
};

/// Returns the exit code.
int run_calibration(const CalibrationOptions& o);

}  // namespace refloc
