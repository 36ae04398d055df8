#include "lms100_driver/scan_handoff.hpp"

namespace refloc {

void ScanHandoff::push(const LaserScan& scan) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (queued_.size() >= capacity_) {
    queued_.pop_front();
    ++dropped_;
  }
  queued_.push_back(scan);
}

void ScanHandoff::drain(const std::function<void(const LaserScan&)>& publish) {
  draining_.clear();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto& scan : queued_) draining_.push_back(std::move(scan));
    queued_.clear();
  }
  for (const LaserScan& scan : draining_) publish(scan);
}

uint64_t ScanHandoff::dropped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return dropped_;
}

}  // namespace refloc
