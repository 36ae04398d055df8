#include "lms100_driver/sensor_clock_filter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

/// A simulated sensor at 50 Hz whose crystal runs drift_ppm faster than the host's, with
/// one-sided network delay: min_delay + exponential jitter + occasional 30 ms stalls.
struct SimulatedLink {
  double drift_ppm = 80.0;
  int64_t host_epoch_utime = 1'700'000'000'000'000;
  uint32_t sensor_clock_at_epoch = 0;
  double min_delay_us = 150.0;
  double mean_jitter_us = 400.0;
  double period_us = 20'000.0;
  double start_to_transmit_us = 3100.0;
  std::mt19937 rng{42};

  struct Sample {
    uint32_t start_us;
    uint32_t transmit_us;
    int64_t receive_utime;
    int64_t true_start_utime;
  };

  Sample scan(int k) {
    const double host_start = static_cast<double>(k) * period_us;  // host time since epoch [us]
    const double sensor_start = host_start * (1.0 + drift_ppm * 1e-6);
    const double sensor_tx = sensor_start + start_to_transmit_us;
    const double host_tx = sensor_tx / (1.0 + drift_ppm * 1e-6);
    std::exponential_distribution<double> jitter(1.0 / mean_jitter_us);
    std::uniform_real_distribution<double> u(0, 1);
    double delay = min_delay_us + jitter(rng);
    if (u(rng) < 0.02) delay += 30'000.0;
    Sample s;
    s.start_us = sensor_clock_at_epoch + static_cast<uint32_t>(std::llround(sensor_start));
    s.transmit_us = sensor_clock_at_epoch + static_cast<uint32_t>(std::llround(sensor_tx));
    s.receive_utime = host_epoch_utime + std::llround(host_tx + delay);
    s.true_start_utime = host_epoch_utime + std::llround(host_start);
    return s;
  }
};

TEST(SensorClockFilter, TracksDriftAndMapsFirstBeamWithinHalfAMillisecond) {
  SimulatedLink link;
  SensorClockFilter filter;
  double worst_after_converged_us = 0;
  double sum_abs_us = 0;
  int counted = 0;
  for (int k = 0; k < 50 * 120; ++k) {
    const auto s = link.scan(k);
    const SensorTimeMapping m = filter.update(s.start_us, s.transmit_us, s.receive_utime);
    if (k >= 50 * 30) {
      const double err = static_cast<double>(m.host_start_utime - s.true_start_utime);
      worst_after_converged_us = std::max(worst_after_converged_us, std::fabs(err));
      sum_abs_us += std::fabs(err);
      ++counted;
    }
  }
  std::printf("first-beam time error after 30 s: mean %.0f us, worst %.0f us; drift %.2f ppm\n",
              sum_abs_us / counted, worst_after_converged_us, filter.drift_ppm());
  EXPECT_NEAR(filter.drift_ppm(), -80.0, 5.0);  // host runs slower than this sensor
  // The envelope includes the unobservable minimum delay (150 us), nothing else.
  EXPECT_LT(worst_after_converged_us, 500.0);
  EXPECT_LT(sum_abs_us / counted, 300.0);
  EXPECT_EQ(filter.resets(), 0u);
}

TEST(SensorClockFilter, NaiveReceiveStampWouldBeMillisecondsLate) {
  // The reason the filter exists: receive time minus first-beam time averages > 3.5 ms here.
  SimulatedLink link;
  double sum_us = 0;
  for (int k = 0; k < 1000; ++k) {
    const auto s = link.scan(k);
    sum_us += static_cast<double>(s.receive_utime - s.true_start_utime);
  }
  EXPECT_GT(sum_us / 1000.0, 3500.0);
}

TEST(SensorClockFilter, UnwrapsTheSensorClockAcrossTwoToThe32Microseconds) {
  SimulatedLink link;
  link.sensor_clock_at_epoch = 0xFFFFFFFFu - 10'000'000u;  // wraps after 10 s
  SensorClockFilter filter;
  int64_t last_transmit = 0;
  double worst_us = 0;
  for (int k = 0; k < 50 * 40; ++k) {
    const auto s = link.scan(k);
    const SensorTimeMapping m = filter.update(s.start_us, s.transmit_us, s.receive_utime);
    if (k > 0) {
      EXPECT_GT(m.sensor_transmit_us, last_transmit);
    }
    last_transmit = m.sensor_transmit_us;
    if (k > 50 * 15)
      worst_us = std::max(worst_us, std::fabs(static_cast<double>(m.host_start_utime - s.true_start_utime)));
  }
  EXPECT_GT(last_transmit, int64_t{0xFFFFFFFF});
  EXPECT_LT(worst_us, 500.0);
  EXPECT_EQ(filter.resets(), 0u);
}

TEST(SensorClockFilter, FirstBeamIsNeverAfterReception) {
  SensorClockFilter filter;
  const SensorTimeMapping m = filter.update(1000, 4000, 5'000'000);
  EXPECT_EQ(m.sensor_start_us, 1000);
  EXPECT_EQ(m.sensor_transmit_us, 4000);
  EXPECT_EQ(m.host_start_utime, 5'000'000 - 3000);
}

TEST(SensorClockFilter, HostClockStepBackwardsRestartsTheFit) {
  SimulatedLink link;
  SensorClockFilter filter;
  for (int k = 0; k < 500; ++k) {
    const auto s = link.scan(k);
    filter.update(s.start_us, s.transmit_us, s.receive_utime);
  }
  double worst_us = 0;
  for (int k = 500; k < 1500; ++k) {
    auto s = link.scan(k);
    s.receive_utime -= 2'000'000;  // NTP stepped the host clock back by 2 s
    const SensorTimeMapping m = filter.update(s.start_us, s.transmit_us, s.receive_utime);
    if (k > 600) {
      worst_us = std::max(
          worst_us, std::fabs(static_cast<double>(m.host_start_utime - (s.true_start_utime - 2'000'000))));
    }
  }
  EXPECT_EQ(filter.resets(), 1u);
  EXPECT_LT(worst_us, 1000.0);
}

TEST(SensorClockFilter, SensorRebootRestartsTheFit) {
  SensorClockFilter filter;
  filter.update(5'000'000, 5'003'000, 1'000'000'000);
  filter.update(5'020'000, 5'023'000, 1'000'020'500);
  const SensorTimeMapping m = filter.update(100, 3100, 1'000'040'500);  // clock went back
  EXPECT_EQ(filter.resets(), 1u);
  EXPECT_EQ(m.sensor_transmit_us, 3100);
  EXPECT_EQ(m.host_start_utime, 1'000'040'500 - 3000);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
