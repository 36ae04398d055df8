#pragma once
// Maps the LMS100's free-running uint32 microsecond clock to host time.
//
// The sensor stamps each scan with "time since start-up" (first beam) and "time
// of transmission"; the host only knows when the telegram arrived, which is
// transmission + network/stack delay (>= a minimum, with one-sided jitter).
// Like sick_scan_xd's software PLL we fit host_receive ≈ offset + (1 + drift) ·
// sensor_transmit, but over the lower envelope of the delays: the smallest
// (host − sensor) per time bin, fitted by least squares over a sliding window.
// Late telegrams (bursts, scheduling) then do not pull the mapping later, and
// the drift between the two crystals (tens of ppm) is followed.

#include <array>
#include <cstddef>
#include <cstdint>

namespace refloc {

struct SensorClockFilterConfig {
  double bin_s = 1.0;              ///< one lower-envelope sample per bin [s]
  size_t window_bins = 60;         ///< fit window = window_bins · bin_s (at most kMaxBins)
  size_t min_bins_for_drift = 5;   ///< fewer closed bins: drift assumed 0
  double step_backward_s = 0.05;   ///< a telegram this much earlier than the envelope = host clock step [s]
  double step_forward_s = 1.0;     ///< consistently this much later = host clock step [s]
  size_t step_forward_count = 25;  ///< how many late telegrams in a row make a step
};

/// Sensor times after unwrapping and their host equivalents.
struct SensorTimeMapping {
  int64_t sensor_start_us = 0;     ///< unwrapped sensor clock at the first beam
  int64_t sensor_transmit_us = 0;  ///< unwrapped sensor clock at transmission
  int64_t host_start_utime = 0;    ///< host time of the first beam [us]
};

class SensorClockFilter {
 public:
  static constexpr size_t kMaxBins = 256;

  explicit SensorClockFilter(const SensorClockFilterConfig& config = {});

  /// Adds one scan's clock pair and returns the mapping of its first beam.
  /// start_us/transmit_us: raw sensor clock; host_receive_utime: when the telegram was complete.
  SensorTimeMapping update(uint32_t start_us, uint32_t transmit_us, int64_t host_receive_utime);

  /// Host time of an unwrapped sensor time with the current fit [us].
  int64_t to_host_utime(int64_t sensor_us) const;

  /// Forgets everything (new sensor connection, sensor reboot).
  void reset();

  double drift_ppm() const { return drift_ * 1e6; }  ///< host rate minus sensor rate [ppm]
  uint64_t resets() const { return resets_; }        ///< clock steps and wraps backwards seen
  bool has_drift_estimate() const { return closed_bins_ >= config_.min_bins_for_drift; }

 private:
  struct Bin {
    double sensor_us = 0;  ///< relative to origin
    double offset_us = 0;  ///< min over the bin of host − sensor
  };
  void close_bin();
  void fit();
  void restart_after_step();

  SensorClockFilterConfig config_;
  bool initialized_ = false;
  uint32_t last_transmit_raw_ = 0;
  int64_t transmit_unwrapped_ = 0;
  int64_t origin_sensor_us_ = 0;  ///< sensor time of the first sample (keeps doubles small)
  int64_t origin_host_us_ = 0;

  std::array<Bin, kMaxBins> bins_{};
  size_t bin_head_ = 0;  ///< ring buffer of closed bins
  size_t closed_bins_ = 0;
  bool bin_open_ = false;
  Bin open_bin_;
  double open_bin_start_us_ = 0;

  // host − origin_host = x + intercept + drift · x, with x = sensor − origin_sensor [us]
  double intercept_us_ = 0;
  double drift_ = 0;
  bool has_estimate_ = false;
  bool fitted_ = false;
  size_t late_in_a_row_ = 0;
  uint64_t resets_ = 0;
};

}  // namespace refloc
