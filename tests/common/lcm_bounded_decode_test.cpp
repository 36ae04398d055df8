// The guarded decode where messages arrive: ServiceRuntime's subscriptions count a lying
// datagram as a decode error and go on; the recorded sample log passes the bounds check
// (the "// max N" comments did not change a fingerprint); a lie allocates nothing; a NaN,
// infinite or huge number anywhere in a message is named and, where a service consumes it, refused.

#include "common/lcm_bounded_decode.hpp"
#include "common/service_runtime.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <lcm/lcm-cpp.hpp>
#include <refloc_lcm_samples.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

template <class Message>
std::vector<uint8_t> encoded(const Message& m) {
  std::vector<uint8_t> bytes(static_cast<size_t>(m.getEncodedSize()));
  EXPECT_GE(m.encode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  return bytes;
}

/// reflector_detections_t with its nreflectors field (bytes 8 + 8 + 3 * 4) set to declared.
std::vector<uint8_t> detections_declaring(int32_t declared) {
  reflector_detections_t m{};
  fill_lcm_sample(m, 1);
  std::vector<uint8_t> bytes = encoded(m);
  const auto v = static_cast<uint32_t>(declared);
  for (size_t i = 0; i < 4; ++i) bytes[28 + i] = static_cast<uint8_t>(v >> (24 - 8 * i));
  return bytes;
}

long peak_rss_kb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

TEST(LcmBoundedDecode, LyingLengthNamesFieldAndBytesLeft) {
  reflector_detections_t m{};
  const LcmDecodeResult r =
      decode_lcm_bounded(detections_declaring(-1).data(), detections_declaring(-1).size(), m);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.reason, "nreflectors = -1 declared, 92 bytes left");
}

TEST(LcmBoundedDecode, LiesNeverReachTheDecoderSoNothingIsAllocated) {
  const long before_kb = peak_rss_kb();
  for (int32_t declared : {-1, INT32_MIN, INT32_MAX, 1 << 30, 50'000'000, 1025, 2}) {
    const std::vector<uint8_t> bytes = detections_declaring(declared);
    for (int i = 0; i < 100; ++i) {
      reflector_detections_t m{};
      EXPECT_FALSE(decode_lcm_bounded(bytes.data(), bytes.size(), m).ok) << declared;
      EXPECT_EQ(m.reflectors.capacity(), 0u) << declared;  // lcm-gen's resize() never ran
    }
  }
  // 50,000,000 reflectors decoded would be 4.4 GB; the refused lies leave the peak where it was.
  EXPECT_LT(peak_rss_kb() - before_kb, 16 * 1024);
}

TEST(LcmBoundedDecode, SampleLogPassesTheBoundsCheck) {
  const std::map<std::string, const LcmSchema*> type_of_channel = {
      {"LMS100_SCAN", &lcm_schema_of<laser_scan_t>()},
      {"REFLECTORS", &lcm_schema_of<reflector_detections_t>()},
      {"REFLECTOR_MATCHES", &lcm_schema_of<reflector_matches_t>()},
      {"LASER_POSE", &lcm_schema_of<pose2d_t>()},
      {"POSE", &lcm_schema_of<pose2d_t>()},
      {"GROUND_TRUTH", &lcm_schema_of<pose2d_t>()},
      {"ODOMETRY", &lcm_schema_of<odometry_t>()},
      {"WHEEL_ENCODERS", &lcm_schema_of<wheel_encoders_t>()},
      {"HEARTBEAT", &lcm_schema_of<heartbeat_t>()},
      {"NAV_GOAL", &lcm_schema_of<nav_goal_t>()},
      {"NAV_STATUS", &lcm_schema_of<nav_status_t>()},
      {"CMD_VEL", &lcm_schema_of<twist_t>()}};
  lcm::LogFile log(REFLOC_SOURCE_DIR "/logs/samples/replay_demo_4s.lcm", "r");
  ASSERT_TRUE(log.good());
  std::map<std::string, int> checked;
  while (const lcm::LogEvent* e = log.readNextEvent()) {
    const auto type = type_of_channel.find(e->channel);
    ASSERT_NE(type, type_of_channel.end()) << "unknown channel " << e->channel;
    EXPECT_EQ(check_lcm_datagram(*type->second, static_cast<const uint8_t*>(e->data),
                                 static_cast<size_t>(e->datalen)),
              "")
        << e->channel << " event " << e->eventnum;
    ++checked[e->channel];
  }
  EXPECT_GE(checked["LMS100_SCAN"], 100);
  EXPECT_GE(checked["REFLECTORS"], 100);
  EXPECT_GE(checked["REFLECTOR_MATCHES"], 100);
}

TEST(ServiceRuntimeBoundedDecode, LyingDatagramCountsADecodeErrorAndTheNextMessageArrives) {
  ServiceRuntime runtime("bounded_decode_test", "memq://");
  int delivered = 0;
  runtime.subscribe<reflector_detections_t>(
      "REFLECTORS", [&](const reflector_detections_t& m) { delivered += m.nreflectors; });
  for (int32_t declared : {-1, INT32_MAX, 1025, 2}) {
    const std::vector<uint8_t> lie = detections_declaring(declared);
    ASSERT_EQ(runtime.lcm().publish("REFLECTORS", lie.data(), static_cast<unsigned>(lie.size())), 0);
    EXPECT_NO_THROW(runtime.spin_once(100));
  }
  EXPECT_EQ(runtime.decode_errors(), 4);
  EXPECT_EQ(runtime.messages_in(), 0);
  EXPECT_EQ(delivered, 0);
  const std::vector<uint8_t> truth = detections_declaring(1);
  ASSERT_EQ(runtime.lcm().publish("REFLECTORS", truth.data(), static_cast<unsigned>(truth.size())), 0);
  runtime.spin_once(100);
  EXPECT_EQ(delivered, 1);
  EXPECT_EQ(runtime.messages_in(), 1);
  EXPECT_EQ(runtime.decode_errors(), 4);
}

TEST(DecodeErrorLogLimiter, LogsTheFirstErrorThenOneLineAnIntervalCoveringTheSilentOnes) {
  DecodeErrorLogLimiter limiter;
  constexpr int64_t kT0 = 1'000'000'000;
  EXPECT_EQ(limiter.on_error(kT0), 1);
  int64_t lines = 0;
  for (int i = 1; i < 250; ++i)  // 50 Hz for 5 s minus one message
    lines += limiter.on_error(kT0 + i * 20'000) > 0 ? 1 : 0;
  EXPECT_EQ(lines, 0);
  EXPECT_EQ(limiter.on_error(kT0 + DecodeErrorLogLimiter::kIntervalUs), 250);
  EXPECT_EQ(limiter.on_error(kT0 + DecodeErrorLogLimiter::kIntervalUs + 1), 0);
}

TEST(DecodeErrorLogLimiter, ClockGoingBackwardsDoesNotSilenceTheLog) {
  DecodeErrorLogLimiter limiter;
  EXPECT_EQ(limiter.on_error(10'000'000), 1);
  EXPECT_EQ(limiter.on_error(1'000), 1);
}

TEST(LcmPlausibleNumbers, TheFirstNonFiniteOrHugeNumberIsNamedWithItsPath) {
  pose2d_t pose{};
  fill_lcm_sample(pose, 1);
  std::vector<uint8_t> bytes = encoded(pose);
  EXPECT_EQ(find_implausible_lcm_number(lcm_schema_of<pose2d_t>(), bytes.data(), bytes.size()), "");
  pose.covariance[3] = std::numeric_limits<double>::quiet_NaN();
  bytes = encoded(pose);
  EXPECT_EQ(find_implausible_lcm_number(lcm_schema_of<pose2d_t>(), bytes.data(), bytes.size()),
            "covariance[3] is nan");
  pose.covariance[3] = 0.0;
  pose.theta = -HUGE_VAL;
  bytes = encoded(pose);
  EXPECT_EQ(find_implausible_lcm_number(lcm_schema_of<pose2d_t>(), bytes.data(), bytes.size()),
            "theta is -inf");

  reflector_detections_t detections{};
  fill_lcm_sample(detections, 3);
  ASSERT_EQ(detections.nreflectors, 3);
  detections.reflectors[1].mean_rssi = std::numeric_limits<float>::infinity();
  bytes = encoded(detections);
  EXPECT_EQ(find_implausible_lcm_number(lcm_schema_of<reflector_detections_t>(), bytes.data(), bytes.size()),
            "reflectors[1].mean_rssi is inf");
  // Huge finite values are lies too (an uninitialised or corrupted number); 1e15 is not.
  detections.reflectors[1].mean_rssi = std::numeric_limits<float>::max();
  bytes = encoded(detections);
  EXPECT_EQ(find_implausible_lcm_number(lcm_schema_of<reflector_detections_t>(), bytes.data(), bytes.size()),
            "reflectors[1].mean_rssi is 3.40282e+38, beyond +-1e+15");
  detections.reflectors[1].mean_rssi = 1e15F;
  detections.reflectors[2].range = -kMaxPlausibleLcmMagnitude;
  bytes = encoded(detections);
  EXPECT_EQ(find_implausible_lcm_number(lcm_schema_of<reflector_detections_t>(), bytes.data(), bytes.size()),
            "");
}

TEST(LcmPlausibleNumbers, PlausibleOnlyRefusesWhatAsSentDecodes) {
  pose2d_t pose{};
  fill_lcm_sample(pose, 1);
  pose.x = std::numeric_limits<double>::quiet_NaN();
  const std::vector<uint8_t> bytes = encoded(pose);
  pose2d_t decoded{};
  const LcmDecodeResult as_sent = decode_lcm_bounded(bytes.data(), bytes.size(), decoded);
  EXPECT_TRUE(as_sent.ok) << as_sent.reason;
  EXPECT_TRUE(std::isnan(decoded.x));
  const LcmDecodeResult finite =
      decode_lcm_bounded(bytes.data(), bytes.size(), decoded, LcmNumbers::kPlausibleOnly);
  EXPECT_FALSE(finite.ok);
  EXPECT_TRUE(finite.implausible_number);
  EXPECT_EQ(finite.reason, "x is nan");
}

TEST(ServiceRuntimeBoundedDecode, ImplausibleNumberIsCountedPerChannelAndNeverHandled) {
  ServiceRuntime runtime("bounded_decode_test", "memq://");
  int delivered = 0;
  runtime.subscribe<pose2d_t>("LASER_POSE", [&](const pose2d_t&) { ++delivered; });
  pose2d_t pose{};
  fill_lcm_sample(pose, 1);
  EXPECT_EQ(runtime.counter("implausible_numbers_laser_pose"), 0)
      << "the counter is there before the first lie";
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), HUGE_VAL, -HUGE_VAL, 1e300}) {
    pose.residual = bad;
    ASSERT_EQ(runtime.lcm().publish("LASER_POSE", &pose), 0);
    runtime.spin_once(100);
  }
  EXPECT_EQ(delivered, 0);
  EXPECT_EQ(runtime.counter("implausible_numbers_laser_pose"), 4);
  EXPECT_EQ(runtime.decode_errors(), 0) << "a well-formed message is not a decode error";
  pose.residual = 1e14;
  ASSERT_EQ(runtime.lcm().publish("LASER_POSE", &pose), 0);
  runtime.spin_once(100);
  EXPECT_EQ(delivered, 1);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
