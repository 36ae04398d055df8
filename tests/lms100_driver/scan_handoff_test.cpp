// ScanHandoff: scans queued by the session thread reach the publishing thread in order, none
// twice; a publisher that does not drain loses the oldest, counted.
#include "lms100_driver/scan_handoff.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

LaserScan scan_number(uint32_t n) {
  LaserScan s;
  s.scan_counter = n;
  return s;
}

TEST(ScanHandoff, ScansFromAnotherThreadArriveInOrderExactlyOnce) {
  ScanHandoff handoff;
  std::atomic<bool> done{false};
  std::thread session([&] {
    for (uint32_t n = 0; n < 2000; ++n) {
      handoff.push(scan_number(n));
      if (n % 40 == 0) std::this_thread::yield();
    }
    done = true;
  });
  std::vector<uint32_t> published;
  while (!done.load() || published.size() + handoff.dropped() < 2000) {
    handoff.drain([&](const LaserScan& s) { published.push_back(s.scan_counter); });
  }
  session.join();
  EXPECT_EQ(published.size() + handoff.dropped(), 2000u);
  for (size_t k = 1; k < published.size(); ++k) ASSERT_GT(published[k], published[k - 1]);
}

TEST(ScanHandoff, WhenNobodyDrainsTheOldestAreDroppedAndCounted) {
  ScanHandoff handoff(3);
  for (uint32_t n = 0; n < 5; ++n) handoff.push(scan_number(n));
  std::vector<uint32_t> published;
  handoff.drain([&](const LaserScan& s) { published.push_back(s.scan_counter); });
  EXPECT_EQ(published, (std::vector<uint32_t>{2, 3, 4}));
  EXPECT_EQ(handoff.dropped(), 2u);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
