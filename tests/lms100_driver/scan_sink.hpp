#pragma once
// Scans a session publishes from its own thread, collected for a test to wait on.

#include "common/laser_scan.hpp"

#include <chrono>
#include <cstddef>
#include <mutex>
#include <thread>
#include <vector>

namespace refloc::testing {

struct ScanSink {
  std::mutex mutex;
  std::vector<LaserScan> scans;
  void add(const LaserScan& s) {
    std::lock_guard<std::mutex> lock(mutex);
    scans.push_back(s);
  }
  size_t count() {
    std::lock_guard<std::mutex> lock(mutex);
    return scans.size();
  }
  /// Polls every 2 ms until n scans arrived; false after timeout.
  bool wait_for(size_t n, std::chrono::milliseconds timeout) {
    const auto until = std::chrono::steady_clock::now() + timeout;
    while (count() < n) {
      if (std::chrono::steady_clock::now() > until) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return true;
  }
};

}  // namespace refloc::testing
