#pragma once
// "Never silently idle": scans arrive and are accepted, yet no reflector comes out of them
// for longer than a timeout. The matcher downstream only says LOST; this says why, from
// what the scans held since the last reflector: no RSSI at all, nothing reaching the
// energy threshold (with the brightest echo's RSSI), or bright clusters the shape tests
// rejected (by reason).

#include "common/node_event.hpp"
#include "reflector_extractor/beam_table.hpp"
#include "reflector_extractor/extractor.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace refloc {

class NoReflectorWatch {
 public:
  /// timeout_s: how long accepted scans may bring no reflector before the watch fires [s];
  /// threshold_8bit: the extractor's energy threshold (for the reason).
  NoReflectorWatch(double timeout_s, double threshold_8bit);

  /// One accepted scan at host_utime [us], read into table, with its extraction's stats and
  /// number of detections. Firing appends an event (counter no_reflector_timeouts, warning)
  /// once; the first reflector afterwards appends an info line.
  void observe(const BeamTable& table, const ExtractionStats& stats, size_t detections, int64_t host_utime,
               std::vector<NodeEvent>& events);

  /// true while the last accepted scan came over timeout_s after the last reflector.
  bool firing() const { return firing_; }
  /// Why, for state_detail: "no reflector for 2.0 s: max RSSI 142 (8-bit) < threshold 180".
  std::string detail() const;

 private:
  void restart(int64_t host_utime);

  int64_t timeout_us_;
  double threshold_8bit_;
  bool started_ = false;
  bool firing_ = false;
  int64_t since_host_utime_ = 0;  ///< the last reflector, or the first accepted scan [us]
  int64_t last_host_utime_ = 0;   ///< the last accepted scan [us]
  // What the scans since since_host_utime_ held.
  bool any_rssi_ = false;
  bool any_echo_ = false;
  double max_rssi_8bit_ = 0.0;
  ExtractionStats clusters_;  ///< summed
};

}  // namespace refloc
