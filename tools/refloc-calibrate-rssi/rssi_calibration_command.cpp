#include "rssi_calibration_command.hpp"

#include "common/json_config.hpp"
#include "common/lcm_bounded_decode.hpp"
#include "common/lcm_conversions.hpp"
#include "reflector_extractor/extractor.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "reflector_extractor/extractor_input_checks.hpp"
#include "reflector_extractor/rssi_scale.hpp"
#include "rssi_calibration.hpp"

#include <fmt/core.h>
#include <lcm/lcm-cpp.hpp>
#include <refloc/laser_scan_t.hpp>

#include <cmath>
#include <fstream>
#include <string>

namespace refloc {
namespace {

void print_distribution(const char* what, const RssiDistribution& d) {
  if (d.count == 0) {
    fmt::print("  {:<10} {:>8}\n", what, 0);
    return;
  }
  fmt::print("  {:<10} {:>8} {:>7.1f} {:>7.1f} {:>7.1f} {:>7.1f} {:>7.1f} {:>7.1f}\n", what, d.count, d.min,
             d.p1, d.p50, d.p99, d.p999, d.max);
}

}  // namespace

int run_rssi_calibration(const RssiCalibrationOptions& o) {
  ExtractorServiceConfig config = load_extractor_service_config(o.config_path);
  const double config_threshold = config.extractor.energy_threshold_8bit;
  if (o.label_threshold >= 0.0) config.extractor.energy_threshold_8bit = o.label_threshold;
  if (o.label_min_beams > 0) config.extractor.min_beams = o.label_min_beams;
  BeamLabelConfig labels;
  labels.radius = config.extractor.reflector_radius;
  labels.tolerance = o.tolerance;
  labels.core_fraction = o.core_fraction;
  lcm::LogFile log(o.log_path, "r");
  if (!log.good()) throw ConfigError(o.log_path + ": cannot open as an LCM log");

  ReflectorExtractor extractor(config.extractor);
  RssiScaleDetector scale(config.rssi_scale);
  BeamTable table;
  LaserScan scan;
  std::vector<NodeEvent> events;
  std::vector<RssiSample> samples;
  int scans = 0, rejected = 0, undecodable = 0, without_rssi = 0, detections = 0;
  size_t left_out = 0;
  for (const lcm::LogEvent* e = log.readNextEvent(); e != nullptr; e = log.readNextEvent()) {
    if (e->channel != o.channel) continue;
    laser_scan_t msg;
    if (!decode_lcm_bounded(e->data, static_cast<size_t>(e->datalen), msg).ok) {
      ++undecodable;
      continue;
    }
    copy_from_lcm(msg, scan);
    if (const InputFault fault = check_scan(scan)) {
      ++rejected;
      continue;
    }
    ++scans;
    scale.observe(scan, events);
    make_beam_table(scan, table, scale.scale());
    if (!table.has_rssi) ++without_rssi;
    const std::vector<ReflectorDetection>& found = extractor.extract(table);
    detections += static_cast<int>(found.size());
    left_out += label_beams(table, found, labels, samples);
  }
  fmt::print(
      "{}: {} scans on {} ({} rejected by the extractor's input checks, {} undecodable, {} without RSSI)\n",
      o.log_path, scans, o.channel, rejected, undecodable, without_rssi);
  for (const NodeEvent& e : events) fmt::print("  {}\n", e.log);
  if (scans == 0) throw ConfigError(o.log_path + ": no usable scan on " + o.channel);
  fmt::print(
      "RSSI read {}; labelling extraction: threshold {:.0f} (8-bit), min_beams {}, {} detections\n",
      scale.scale() == RssiScale::k8bitIn16bit ? "as 8-bit in the 16-bit channel" : "on the native scale",
      config.extractor.energy_threshold_8bit, config.extractor.min_beams, detections);
  fmt::print(
      "reflector beams: within {:.3f} m of a detected centre and {:.3f} m of its axis; {} edge or mixed "
      "beams in a reflector's silhouette left out; every other echo is 'other' (an undetected reflector "
      "too: see --label-min-beams, --label-threshold-8bit)\n",
      labels.radius + labels.tolerance, labels.core_fraction * labels.radius, left_out);

  const RssiCalibration c = calibrate_rssi(samples, o.band_edges);
  fmt::print("RSSI of echo beams (8-bit scale)\n  {:<10} {:>8} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7}\n",
             "beams", "n", "min", "p1", "p50", "p99", "p99.9", "max");
  for (const RssiBand& b : c.bands) {
    fmt::print("range {:.1f}..{} m\n", b.range_min,
               std::isinf(b.range_max) ? std::string("inf") : fmt::format("{:.1f}", b.range_max));
    print_distribution("reflector", b.reflector);
    print_distribution("other", b.other);
  }
  fmt::print("all ranges\n");
  print_distribution("reflector", c.reflector);
  print_distribution("other", c.other);

  const ThresholdRecommendation& r = c.recommendation;
  int exit_code = 0;
  if (!r.have_both) {
    fmt::print("no recommendation: {} reflector and {} other beams (try a lower --label-threshold-8bit)\n",
               c.reflector.count, c.other.count);
    exit_code = 1;
  } else if (r.separable) {
    fmt::print(
        "recommended energy threshold {:.0f} (8-bit): {:.1f} above the other beams' p99.9 {:.1f}, {:.1f} "
        "below the reflector beams' p1 {:.1f}\n",
        r.threshold, r.margin_below, r.other_p999, r.margin_above, r.reflector_p1);
    fmt::print("config (deploy/config/reflector_extractor.json): \"energy_threshold_8bit\": {:.0f}\n",
               r.threshold);
  } else {
    fmt::print(
        "NOT SEPARABLE: the other beams' p99.9 {:.1f} >= the reflector beams' p1 {:.1f}; a threshold of "
        "{:.0f} keeps 99 % of reflector beams and lets {:.1f} above it through\n",
        r.other_p999, r.reflector_p1, r.threshold, -r.margin_below);
    exit_code = 1;
  }
  const auto print_shares = [&](const char* what, double threshold) {
    const ThresholdShares s = shares_at(samples, threshold);
    fmt::print("at {} {:.0f}: {:.2f} % of reflector beams below it, {:.2f} % of other beams at or above it\n",
               what, threshold, 100.0 * s.reflector_below, 100.0 * s.other_at_or_above);
  };
  print_shares("the config's threshold", config_threshold);
  if (r.have_both) print_shares("the recommended threshold", r.threshold);
  if (!o.plot_path.empty()) {
    std::ofstream svg(o.plot_path);
    if (!svg) throw ConfigError(o.plot_path + ": cannot write the plot");
    svg << rssi_histogram_svg(samples, c);
    fmt::print("plot: {}\n", o.plot_path);
  }
  return exit_code;
}

}  // namespace refloc
