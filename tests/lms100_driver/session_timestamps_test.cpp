// Issue 12: every published scan's utime comes from the sensor clock, also for scans that
// arrive several to a read (right after a connect, after a stall); utimes strictly increase.
// A scripted sensor whose clock is the host clock knows each scan's true first-beam time.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "common/clock.hpp"
#include "fake_sensor.hpp"
#include "lms100_driver/lms100_session.hpp"
#include "telegram_fixtures.hpp"

#include "scan_sink.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using namespace std::chrono_literals;
using test::FakeSensor;

constexpr unsigned kStartToTransmitUs = 2429;  // make_scan_telegram's transmit − start

/// A healthy LMS100 that is ready at once and already scans at 50 Hz / 0.5 deg. Its clock
/// is the host clock minus clock_epoch_utime, so every scan's true first-beam host time is
/// known. After each "sEN LMDscandata 1" the first connect_burst scans are held back and
/// sent in one write; burst_next(n) does the same mid-stream; go_silent(n) sends nothing
/// for n periods (the driver's scan timeout then reconnects).
class BurstySensor {
 public:
  explicit BurstySensor(size_t connect_burst) : connect_burst_(connect_burst) {}

  std::vector<std::string> reply(const std::string& r) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (r.rfind("sMN SetAccessMode", 0) == 0) return {"sAN SetAccessMode 1"};
    if (r == "sRN LMPscancfg") return {"sRA LMPscancfg 1388 1 1388 FFF92230 225510"};
    if (r.rfind("sWN LMDscandatacfg", 0) == 0) return {"sWA LMDscandatacfg"};
    if (r == "sMN LMCstartmeas") return {"sAN LMCstartmeas 0"};
    if (r == "sMN LMCstopmeas") return {"sAN LMCstopmeas 0"};
    if (r == "sMN Run") return {"sAN Run 1"};
    if (r == "sRN STlms") return {"sRA STlms 7 0 8 00:17:28 A 01.01.1970 0 0 0"};
    if (r == "sEN LMDscandata 0") {
      streaming_ = false;
      held_.clear();
      return {"sEA LMDscandata 0"};
    }
    if (r == "sEN LMDscandata 1") {
      streaming_ = true;
      burst_size_ = connect_burst_;
      ++connects_;
      return {"sEA LMDscandata 1"};
    }
    return {};
  }

  /// Called every 20 ms by FakeSensor: makes this period's scan, sends it or holds it.
  std::vector<std::string> stream() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!streaming_) return {};
    if (silent_periods_ > 0) {
      --silent_periods_;
      return {};
    }
    const int64_t transmit_utime = now_utime();
    const auto transmit_us = static_cast<unsigned>(transmit_utime - clock_epoch_utime_);
    const unsigned counter = counter_++ & 0xFFFFu;
    true_first_beam_utime_[counter] = transmit_utime - kStartToTransmitUs;
    held_.push_back(test::make_scan_telegram({500, 600, 700}, {10, 20, 30}, 16, counter,
                                             transmit_us - kStartToTransmitUs));
    if (held_.size() < burst_size_) return {};
    burst_size_ = 1;
    std::vector<std::string> out;
    out.swap(held_);
    return out;
  }

  void burst_next(size_t n) {
    std::lock_guard<std::mutex> lock(mutex_);
    burst_size_ = n;
  }
  void go_silent(int periods) {
    std::lock_guard<std::mutex> lock(mutex_);
    silent_periods_ = periods;
  }
  int connects() {
    std::lock_guard<std::mutex> lock(mutex_);
    return connects_;
  }
  int64_t true_first_beam_utime(uint32_t scan_counter) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = true_first_beam_utime_.find(scan_counter & 0xFFFFu);
    return it == true_first_beam_utime_.end() ? 0 : it->second;
  }

 private:
  std::mutex mutex_;
  const size_t connect_burst_;
  const int64_t clock_epoch_utime_ = now_utime() - 1'000'000;
  bool streaming_ = false;
  size_t burst_size_ = 1;
  int silent_periods_ = 0;
  int connects_ = 0;
  unsigned counter_ = 1;
  std::vector<std::string> held_;
  std::map<uint32_t, int64_t> true_first_beam_utime_;
};

using StampedScans = testing::ScanSink;

/// How published stamps compare with the truth, over scans [begin, end).
struct StampReport {
  double worst_error_us = 0;  ///< |utime − true first-beam time|
  double worst_late_us = 0;   ///< utime − truth, positive = late
  size_t shared_utimes = 0;   ///< scans whose utime equals the previous scan's
  size_t not_increasing = 0;  ///< scans whose utime is not after the previous scan's
  size_t unknown = 0;         ///< scans the sensor never sent (must be 0)
};

StampReport compare(const std::vector<LaserScan>& scans, size_t begin, size_t end, BurstySensor& sensor) {
  StampReport r;
  for (size_t k = begin; k < end; ++k) {
    const int64_t truth = sensor.true_first_beam_utime(scans[k].scan_counter);
    if (truth == 0) {
      ++r.unknown;
      continue;
    }
    const double error = static_cast<double>(scans[k].utime - truth);
    r.worst_error_us = std::max(r.worst_error_us, std::fabs(error));
    r.worst_late_us = std::max(r.worst_late_us, error);
    if (k > 0 && scans[k].utime == scans[k - 1].utime) ++r.shared_utimes;
    if (k > 0 && scans[k].utime <= scans[k - 1].utime) ++r.not_increasing;
  }
  return r;
}

void print(const char* what, const StampReport& r) {
  std::printf("%s: worst |error| %.0f us, worst late %.0f us, shared utimes %zu, not increasing %zu\n", what,
              r.worst_error_us, r.worst_late_us, r.shared_utimes, r.not_increasing);
}

Lms100SessionConfig local_config(uint16_t port) {
  Lms100SessionConfig c;
  c.host = "127.0.0.1";
  c.port = port;
  c.reply_timeout_s = 0.5;
  c.status_poll_period_s = 0.05;
  c.backoff_initial_s = 0.1;
  return c;
}

constexpr size_t kConnectBurst = 5;       // 4 scans wait 20..80 ms in the sensor, then all in one write
constexpr double kStampBoundUs = 2000.0;  // every stamp within 2 ms of the true first beam

TEST(SessionTimestamps, BurstAfterConnectGetsDistinctSensorTimesNoneLate) {
  BurstySensor bursty(kConnectBurst);
  FakeSensor sensor([&](const std::string& r) { return bursty.reply(r); });
  sensor.set_stream([&] { return bursty.stream(); });
  StampedScans sink;
  Lms100Session session(local_config(sensor.port()), [&](const LaserScan& s) { sink.add(s); });
  session.start_thread();
  ASSERT_TRUE(sink.wait_for(30, 5s)) << "got " << sink.count();
  session.join();
  std::lock_guard<std::mutex> lock(sink.mutex);
  const StampReport first = compare(sink.scans, 0, kConnectBurst, bursty);
  const StampReport all = compare(sink.scans, 0, sink.scans.size(), bursty);
  print("first burst after connect", first);
  print("all scans", all);
  const double first_late_us =
      static_cast<double>(sink.scans[0].utime - bursty.true_first_beam_utime(sink.scans[0].scan_counter));
  std::printf("first scan after connect: %.0f us late\n", first_late_us);
  const Lms100SessionCounters& c = session.counters();
  std::printf("scans_in_bursts %llu, held_scans %llu, held_scan_max_delay_us %lld\n",
              static_cast<unsigned long long>(c.scans_in_bursts.load()),
              static_cast<unsigned long long>(c.held_scans.load()),
              static_cast<long long>(c.held_scan_max_delay_us.load()));
  // The burst's 4 earlier scans shared their read; the first 5 reads' scans (at least the
  // burst's 5 and 3 more) waited for the envelope, the oldest for the 4 reads after it.
  EXPECT_GE(c.scans_in_bursts.load(), kConnectBurst - 1);
  EXPECT_GE(c.held_scans.load(), kConnectBurst + 3);
  EXPECT_GT(c.held_scan_max_delay_us.load(), 40'000);
  EXPECT_LT(c.held_scan_max_delay_us.load(), 200'000);
  EXPECT_EQ(c.held_scans_dropped.load(), 0u);
  EXPECT_EQ(c.utime_not_increasing.load(), 0u);
  EXPECT_EQ(all.unknown, 0u);
  EXPECT_LT(std::fabs(first_late_us), kStampBoundUs);
  EXPECT_LT(first.worst_error_us, kStampBoundUs);
  EXPECT_LT(all.worst_error_us, kStampBoundUs);
  EXPECT_EQ(all.shared_utimes, 0u);
  EXPECT_EQ(all.not_increasing, 0u);
}

TEST(SessionTimestamps, MidStreamBurstAndReconnectKeepStampsWithinBound) {
  BurstySensor bursty(kConnectBurst);
  FakeSensor sensor([&](const std::string& r) { return bursty.reply(r); });
  sensor.set_stream([&] { return bursty.stream(); });
  StampedScans sink;
  Lms100Session session(local_config(sensor.port()), [&](const LaserScan& s) {
    sink.add(s);
    // The driver's host stalls 100 ms: 5 telegrams pile up in the socket and come in one read.
    if (sink.count() == 12) std::this_thread::sleep_for(100ms);
  });
  session.start_thread();
  ASSERT_TRUE(sink.wait_for(20, 5s));
  bursty.burst_next(6);  // 120 ms held in the sensor: under the 200 ms scan timeout
  ASSERT_TRUE(sink.wait_for(40, 5s));
  bursty.go_silent(20);  // 400 ms: the driver reconnects, then the connect burst again
  const size_t before_reconnect = sink.count();
  const int64_t deadline = monotonic_us() + 5'000'000;
  while (bursty.connects() < 2 && monotonic_us() < deadline) std::this_thread::sleep_for(5ms);
  ASSERT_EQ(bursty.connects(), 2);
  ASSERT_TRUE(sink.wait_for(before_reconnect + 20, 5s));
  session.join();
  std::lock_guard<std::mutex> lock(sink.mutex);
  const StampReport after_reconnect =
      compare(sink.scans, before_reconnect, before_reconnect + kConnectBurst, bursty);
  const StampReport all = compare(sink.scans, 0, sink.scans.size(), bursty);
  print("first burst after the reconnect", after_reconnect);
  print("all scans (connect, 100 ms host stall, sensor burst of 6, reconnect)", all);
  std::printf("scans_in_bursts %llu\n",
              static_cast<unsigned long long>(session.counters().scans_in_bursts.load()));
  // The connect bursts (2 x 4), the sensor's burst (5) and the host stall's (3-4 of its 5 telegrams
  // share a read; the kernel may hand the first over alone).
  EXPECT_GE(session.counters().scans_in_bursts.load(), 14u);
  EXPECT_EQ(session.counters().reconnects.load(), 1u);
  EXPECT_EQ(session.counters().utime_not_increasing.load(), 0u);
  EXPECT_EQ(all.unknown, 0u);
  EXPECT_LT(after_reconnect.worst_error_us, kStampBoundUs);
  EXPECT_LT(all.worst_error_us, kStampBoundUs);
  EXPECT_EQ(all.shared_utimes, 0u);
  EXPECT_EQ(all.not_increasing, 0u);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
