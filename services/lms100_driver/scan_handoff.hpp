#pragma once
// Scans from the session's thread to the thread that publishes them. The driver publishes
// through ServiceRuntime like every service, so HEARTBEAT's messages_out counts its scans, and
// ServiceRuntime is single-threaded: the session thread only queues, the runtime loop drains.
// Bounded: a publisher stalled for more than a second drops the oldest scans, counted.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <vector>

#include "common/laser_scan.hpp"

namespace refloc {

class ScanHandoff {
 public:
  /// capacity: scans kept while nobody drains (50 = 1 s at 50 Hz).
  explicit ScanHandoff(size_t capacity = 50) : capacity_(capacity) {}

  /// From the session thread. When full, the oldest queued scan is dropped and counted.
  void push(const LaserScan& scan);
  /// From the publishing thread: every queued scan, oldest first, with the queue unlocked.
  void drain(const std::function<void(const LaserScan&)>& publish);
  uint64_t dropped() const;

 private:
  size_t capacity_;
  mutable std::mutex mutex_;
  std::deque<LaserScan> queued_;
  std::vector<LaserScan> draining_;
  uint64_t dropped_ = 0;
};

}  // namespace refloc
