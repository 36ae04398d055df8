#include "lms100_emulator/scan_scheduler.hpp"

#include <algorithm>
#include <limits>

namespace refloc {

ScanScheduler::ScanScheduler(uint64_t spin_up_us, uint64_t period_us, uint16_t first_scan_counter)
    : spin_up_us_(spin_up_us), period_us_(period_us), next_counter_(first_scan_counter) {}

void ScanScheduler::start(uint64_t now_us) {
  if (measuring_) return;
  measuring_ = true;
  spin_start_us_ = now_us;
  grid_valid_ = false;
  has_last_ = false;
}

void ScanScheduler::stop() {
  measuring_ = false;
  grid_valid_ = false;
}

void ScanScheduler::respin(uint64_t now_us, uint64_t period_us) {
  period_us_ = period_us;
  if (!measuring_) return;
  spin_start_us_ = now_us;
  grid_valid_ = false;
  has_last_ = false;
}

int ScanScheduler::status_code(uint64_t now_us) const {
  if (!measuring_) return 3;
  const uint64_t elapsed = now_us > spin_start_us_ ? now_us - spin_start_us_ : 0;
  // The split of the spin-up into phases is ours; only the order 3, 4, 5, 7 is documented.
  if (elapsed * 10 < spin_up_us_ * 3) return 3;
  if (elapsed * 10 < spin_up_us_ * 8 || refuse_readiness_) return 4;
  if (elapsed < spin_up_us_) return 5;
  return 7;
}

bool ScanScheduler::pop_due_scan(uint64_t now_us, uint64_t complete_delay_us, ScanSlot& slot) {
  if (!ready(now_us)) {
    grid_valid_ = false;
    return false;
  }
  if (!grid_valid_) {
    // The first scan starts when readiness is observed; the grid runs from there.
    next_start_us_ = std::max(now_us, spin_start_us_ + spin_up_us_);
    grid_valid_ = true;
  }
  if (next_start_us_ + complete_delay_us > now_us) return false;
  const uint64_t behind = (now_us - next_start_us_ - complete_delay_us) / period_us_;
  if (behind > kMaxBacklogPeriods) {
    next_start_us_ += behind * period_us_;
    next_counter_ = static_cast<uint16_t>(next_counter_ + behind);
  }
  slot.start_us = next_start_us_;
  slot.complete_us = next_start_us_ + complete_delay_us;
  slot.scan_counter = next_counter_;
  next_counter_ = static_cast<uint16_t>(next_counter_ + 1);
  next_start_us_ += period_us_;
  last_ = slot;
  has_last_ = true;
  return true;
}

uint64_t ScanScheduler::next_event_us(uint64_t now_us, uint64_t complete_delay_us) const {
  constexpr uint64_t kNever = std::numeric_limits<uint64_t>::max();
  if (!measuring_) return kNever;
  const int status = status_code(now_us);
  if (status == 3) return spin_start_us_ + spin_up_us_ * 3 / 10;
  if (status == 4) return refuse_readiness_ ? kNever : spin_start_us_ + spin_up_us_ * 8 / 10;
  if (status == 5) return spin_start_us_ + spin_up_us_;
  if (!grid_valid_) return now_us;
  return next_start_us_ + complete_delay_us;
}

bool ScanScheduler::last_scan(ScanSlot& slot) const {
  if (!has_last_) return false;
  slot = last_;
  return true;
}

}  // namespace refloc
