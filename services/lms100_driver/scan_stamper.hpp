#pragma once
// Gives each scan its host first-beam time from the sensor clock filter, and publishes a
// scan only when the filter can support that stamp.
//
// Why it exists (issue 12): telegrams that arrive in one read share one receive time, so
// only the latest of them says anything about the link delay; the earlier ones waited in
// the sensor, the network or the socket. Mapped one by one against a fresh filter, every
// telegram of such a burst became "receive time − (transmit − start)" of the same read: one
// shared, late utime (80 ms for the first of 5 after a connect). So every telegram of a read
// first updates the filter (add), and only then are they mapped (release), all against the
// envelope the latest one set. A fresh filter (after a connect or a clock restart) has seen
// only one read, and that read may itself have been late: its scans are held until
// settle_reads reads have shaped the envelope, then published in order with their stamps from
// it. A stamp not after the previous published one is never published.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/laser_scan.hpp"
#include "lms100_driver/sensor_clock_filter.hpp"

namespace refloc {

struct ScanStamperConfig {
  /// Reads carrying plausible scans the envelope needs after a (re)connect or a clock restart
  /// before any scan is published [reads]. 5 at 50 Hz costs about 80 ms once per connect.
  size_t settle_reads = 5;
  /// Scans held at most while settling; beyond it the oldest is dropped [scans] (1 s at 50 Hz).
  size_t max_held_scans = 50;
  SensorClockFilterConfig clock;
};

/// What the stamper did besides stamping; plain counts, since start.
struct ScanStamperCounts {
  uint64_t scans_in_bursts = 0;        ///< scans that shared their read with a later scan
  uint64_t held_scans = 0;             ///< scans published later than their read (settling)
  uint64_t held_scans_dropped = 0;     ///< held scans never published (overflow, lost link, clock restart)
  uint64_t utime_not_increasing = 0;   ///< scans dropped: stamp not after the previous published one
  int64_t held_scan_max_delay_us = 0;  ///< longest read-to-publish delay of a held scan [us]
};

class ScanStamper {
 public:
  explicit ScanStamper(const ScanStamperConfig& config = {});

  /// A new connection: forgets the clock fit; scans still held are dropped and counted. The
  /// last published utime is kept, so stamps keep increasing across reconnects.
  void reset();

  /// Adds one parsed scan: feeds its clock pair to the filter and holds a copy of it.
  /// start_us / transmit_us: raw sensor clock; receive_utime: host time of the read [us].
  void add(const LaserScan& scan, uint32_t start_us, uint32_t transmit_us, int64_t receive_utime);

  /// Call when every byte read so far has been added. Stamps the held scans, oldest first, and
  /// hands each to publish(scan) if the filter has settled; returns how many. now_utime: host time [us].
  template <class Publish>
  size_t release(int64_t now_utime, Publish&& publish) {
    size_t published = 0;
    if (!settled()) return 0;
    for (size_t i = 0; i < held_count_; ++i) {
      LaserScan& scan = held_[(held_head_ + i) % held_.size()];
      if (stamp(scan, now_utime)) {
        publish(static_cast<const LaserScan&>(scan));
        ++published;
      }
    }
    held_count_ = 0;
    return published;
  }

  bool settled() const { return reads_since_restart_ >= config_.settle_reads; }
  size_t held() const { return held_count_; }
  const ScanStamperCounts& counts() const { return counts_; }
  const SensorClockFilter& clock() const { return clock_; }

 private:
  /// Sets scan.utime from the current fit; false (counted) when it would not increase.
  bool stamp(LaserScan& scan, int64_t now_utime);
  void drop_held();

  ScanStamperConfig config_;
  SensorClockFilter clock_;
  std::vector<LaserScan> held_;  ///< ring; copies reuse their vectors' capacity
  size_t held_head_ = 0;
  size_t held_count_ = 0;
  size_t reads_since_restart_ = 0;
  int64_t last_read_utime_ = 0;
  uint64_t clock_restarts_seen_ = 0;
  bool has_published_ = false;
  int64_t last_published_utime_ = 0;
  ScanStamperCounts counts_;
};

}  // namespace refloc
