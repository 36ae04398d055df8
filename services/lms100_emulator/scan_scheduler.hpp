#pragma once
// When an emulated LMS100 is ready and when each of its scans is measured.
//
// The motor spin-up after LMCstartmeas (or after a change of frequency or
// resolution) takes seconds on a real unit (docs/lms100-protocol.md §4.3-4.4): STlms goes
// 3 (idle) -> 4 (rotated) -> 5 (in preparation) -> 7 (ready for measurement).
// Once ready, scans follow one another every period on a fixed grid (no drift):
// scan k starts at origin + k * period on the device clock. The scan counter
// counts every scan the device makes, sent or not, so scans lost inside the
// device show up as counter gaps, as the SICK manual describes.

#include <cstdint>

namespace refloc {

/// One scan on the device clock [us since power-up, unwrapped].
struct ScanSlot {
  uint64_t start_us = 0;     ///< beam 0
  uint64_t complete_us = 0;  ///< when the telegram is ready to go out
  uint16_t scan_counter = 0;
};

class ScanScheduler {
 public:
  /// spin_up_us: time from start of measurement to STlms 7; period_us: scan period.
  ScanScheduler(uint64_t spin_up_us, uint64_t period_us, uint16_t first_scan_counter);

  /// Starts the motor (no effect if already measuring).
  void start(uint64_t now_us);
  /// Stops measuring; STlms goes back to 3.
  void stop();
  /// A new frequency or resolution: the motor spins up again from now.
  void respin(uint64_t now_us, uint64_t period_us);
  /// While set, the device never reaches STlms 7 (fault injection); clearing it
  /// lets a finished spin-up become ready at once.
  void set_refuse_readiness(bool refuse) { refuse_readiness_ = refuse; }

  bool measuring() const { return measuring_; }
  /// STlms status code at now_us (3, 4, 5 or 7).
  int status_code(uint64_t now_us) const;
  bool ready(uint64_t now_us) const { return status_code(now_us) == 7; }
  uint64_t period_us() const { return period_us_; }

  /// Pops the next scan whose telegram is complete by now_us; complete_delay_us is
  /// the time from beam 0 until the telegram is ready (sweep plus processing).
  /// If the caller fell more than max_backlog periods behind, the missed scans are
  /// counted (scan counter gap) but skipped, as a device with a full buffer does.
  bool pop_due_scan(uint64_t now_us, uint64_t complete_delay_us, ScanSlot& slot);
  /// Earliest device time at which pop_due_scan may return a scan or the status
  /// changes; UINT64_MAX when nothing is scheduled.
  uint64_t next_event_us(uint64_t now_us, uint64_t complete_delay_us) const;

  /// The most recent scan popped; false when there has been none since measuring started.
  bool last_scan(ScanSlot& slot) const;
  /// The scan counter the next scan will carry.
  uint16_t next_scan_counter() const { return next_counter_; }

  static constexpr uint64_t kMaxBacklogPeriods = 10;

 private:
  uint64_t spin_up_us_;
  uint64_t period_us_;
  bool measuring_ = false;
  bool refuse_readiness_ = false;
  uint64_t spin_start_us_ = 0;
  bool grid_valid_ = false;  ///< next_start_us_ is on the current grid
  uint64_t next_start_us_ = 0;
  uint16_t next_counter_;
  bool has_last_ = false;
  ScanSlot last_;
};

}  // namespace refloc
