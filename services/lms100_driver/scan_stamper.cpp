#include "lms100_driver/scan_stamper.hpp"

#include <algorithm>

namespace refloc {

ScanStamper::ScanStamper(const ScanStamperConfig& config)
    : config_(config), clock_(config.clock), held_(std::max<size_t>(config.max_held_scans, 1)) {
  config_.settle_reads = std::max<size_t>(config_.settle_reads, 1);
}

void ScanStamper::drop_held() {
  counts_.held_scans_dropped += held_count_;
  held_count_ = 0;
}

void ScanStamper::reset() {
  drop_held();
  clock_.reset();
  clock_restarts_seen_ = clock_.resets();
  reads_since_restart_ = 0;
  last_read_utime_ = 0;
}

void ScanStamper::add(const LaserScan& scan, uint32_t start_us, uint32_t transmit_us, int64_t receive_utime) {
  const bool same_read = reads_since_restart_ > 0 && receive_utime == last_read_utime_;
  if (same_read) ++counts_.scans_in_bursts;  // the scan before this one shared its read
  const SensorTimeMapping mapping = clock_.update(start_us, transmit_us, receive_utime);
  if (clock_.resets() != clock_restarts_seen_) {
    // Host clock step or sensor reboot: held scans were measured against the old fit, and
    // the host clock may have gone back, so the increase guard starts over with the fit.
    clock_restarts_seen_ = clock_.resets();
    drop_held();
    reads_since_restart_ = 0;
    has_published_ = false;
  }
  if (!same_read || reads_since_restart_ == 0) ++reads_since_restart_;
  last_read_utime_ = receive_utime;

  if (held_count_ == held_.size()) {  // settling for longer than the buffer: give up the oldest
    held_head_ = (held_head_ + 1) % held_.size();
    --held_count_;
    ++counts_.held_scans_dropped;
  }
  LaserScan& slot = held_[(held_head_ + held_count_) % held_.size()];
  slot = scan;
  slot.receive_utime = receive_utime;
  slot.sensor_start_us = mapping.sensor_start_us;
  slot.sensor_transmit_us = mapping.sensor_transmit_us;
  ++held_count_;
}

bool ScanStamper::stamp(LaserScan& scan, int64_t now_utime) {
  // The first beam cannot be after the telegram was complete, whatever the fit says.
  scan.utime = std::min(clock_.to_host_utime(scan.sensor_start_us), scan.receive_utime);
  if (has_published_ && scan.utime <= last_published_utime_) {
    ++counts_.utime_not_increasing;
    return false;
  }
  has_published_ = true;
  last_published_utime_ = scan.utime;
  if (scan.receive_utime != last_read_utime_) {
    ++counts_.held_scans;
    counts_.held_scan_max_delay_us = std::max(counts_.held_scan_max_delay_us, now_utime - scan.receive_utime);
  }
  return true;
}

}  // namespace refloc
