#include "counter_kind.hpp"

#include <array>
#include <string_view>

namespace refloc {
namespace {

// Counters of normal operation and gauges (values, not counts), by the services that send
// them. Listed, not guessed from the name: "lost_scans" and "scans" differ by one word.
constexpr std::array<std::string_view, 41> kNormalCounters = {
    // lms100_driver: link and stamping
    "connects", "scans", "scans_in_bursts", "held_scans", "held_scan_max_delay_us",
    // lms100_emulator and robot_sim's emulated sensor
    "clients_accepted", "requests", "scan_telegrams_sent", "laser_clients_accepted", "laser_scans_sent",
    // reflector_extractor: motion compensation, and bright clusters it classified as not a
    // reflector (tape, metal, cut by an occluder): its filter at work, thousands a minute
    "rssi_scale_8bit", "scans_compensated_odometry", "scans_compensated_fixes", "rejected_shape",
    "rejected_too_few_beams", "rejected_occluded",
    // reflector_matcher
    "global_relocalizations", "startup_scans_without_prior", "initial_poses_received",
    "initial_poses_confirmed",
    // pose_solver: the range bias gauges, and fixes where b was held (said in the OK detail)
    "range_bias_um", "range_bias_sigma_um", "range_bias_unestimable_fixes",
    // pose_fusion: the fixes and scans it used, and its gauges (range bias, shared name with the
    // solver's; odometry calibration; mean squared Mahalanobis distance of accepted detections)
    "fixes_accepted", "initialisations", "fixes_deferred", "scans_accepted", "fixes_left_to_detections",
    "detection_nis_milli", "odometry_error_xx_ppm", "odometry_error_yy_ppm", "odometry_error_turn_ppm",
    "odometry_error_turn_per_x_ppm", "noise_inflation_milli", "scan_time_offset_us",
    "scan_time_offset_sigma_us",
    // web_console: its clients (a gauge), frames sent, scans decimated away, commands accepted
    "clients", "frames_sent", "scans_skipped", "requests_accepted", "http_requests"};

}  // namespace

bool is_error_counter(const std::string& name) {
  for (const auto normal : kNormalCounters) {
    if (name == normal) return false;
  }
  return true;
}

SplitCounters split_counters(const NamedCounters& counters) {
  SplitCounters split;
  for (const auto& [name, value] : counters) {
    if (value == 0) continue;
    (is_error_counter(name) ? split.errors : split.normal).emplace_back(name, value);
  }
  return split;
}

int error_kinds(int64_t decode_errors, const NamedCounters& counters) {
  int kinds = decode_errors != 0 ? 1 : 0;
  for (const auto& [name, value] : counters) {
    if (value != 0 && is_error_counter(name)) ++kinds;
  }
  return kinds;
}

}  // namespace refloc
