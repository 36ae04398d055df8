#pragma once
// refloc-calibrate-rssi's work: LMS100_SCAN from an LCM log through the extractor library
// (input checks, RSSI scale verdict, extraction), beams labelled, distributions and the
// recommended threshold printed, optionally an SVG.

#include <string>
#include <vector>

namespace refloc {

/// The command line of refloc-calibrate-rssi.
struct RssiCalibrationOptions {
  std::string log_path;
  std::string channel = "LMS100_SCAN";
  std::string config_path;      ///< extractor config; empty: the code defaults
  double label_threshold = -1;  ///< energy threshold for the labelling extraction; < 0: the config's
  double tolerance = 0.02;      ///< a beam within reflector radius + this of a detection is its [m]
  double core_fraction = 0.6;   ///< reflector beams pass within this fraction of the radius of the centre
  int label_min_beams = 0;      ///< min_beams of the labelling extraction; 0: the config's
  std::vector<double> band_edges = {1.0, 2.0, 4.0, 8.0};  ///< [m]
  std::string plot_path;                                  ///< SVG; empty: none
};

/// Returns the exit code (ConfigError on a bad log or config).
int run_rssi_calibration(const RssiCalibrationOptions& o);

}  // namespace refloc
