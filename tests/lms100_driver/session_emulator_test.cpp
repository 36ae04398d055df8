// Driver session against the emulator, in one process over real loopback TCP.
#include "lms100_driver/lms100_session.hpp"

#include <gtest/gtest.h>

#if __has_include("lms100_emulator/lms100_emulator.hpp")
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "common/clock.hpp"
#include "lms100_emulator/lms100_emulator.hpp"
#include "lms100_emulator/test_pattern_scan_source.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using namespace std::chrono_literals;

/// Remembers what the emulator sent for each scan counter, so received scans can be
/// compared value by value.
struct RecordingSource {
  std::mutex mutex;
  std::map<uint32_t, std::pair<std::vector<uint16_t>, std::vector<uint16_t>>> sent;
  ScanSource make() {
    return [this](const ScanRequest& r, std::vector<uint16_t>& dist, std::vector<uint16_t>& rssi) {
      make_test_pattern_scan_source()(r, dist, rssi);
      // Vary values with the scan so a stale or mixed-up scan cannot pass.
      for (size_t i = 0; i < dist.size(); ++i)
        dist[i] = static_cast<uint16_t>(dist[i] + (r.scan_counter % 7));
      std::lock_guard<std::mutex> lock(mutex);
      sent[r.scan_counter & 0xFFFFu] = {dist, rssi};
    };
  }
};

/// Collects scans delivered by the session (called on the session thread).
struct ScanSink {
  std::mutex mutex;
  std::condition_variable cv;
  std::vector<LaserScan> scans;
  void operator()(const LaserScan& s) {
    std::lock_guard<std::mutex> lock(mutex);
    scans.push_back(s);
    cv.notify_all();
  }
  size_t count() {
    std::lock_guard<std::mutex> lock(mutex);
    return scans.size();
  }
  /// Waits until at least n scans in total arrived; false on timeout.
  bool wait_for(size_t n, std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex);
    return cv.wait_for(lock, timeout, [&] { return scans.size() >= n; });
  }
};

class SessionEmulatorTest : public ::testing::Test {
 protected:
  void start_emulator(uint16_t port = 0) {
    Lms100EmulatorConfig config;
    config.port = port;
    config.cola_b = dialect_ == ColaDialect::kColaB;
    config.device.spin_up_s = 0.1;
    emulator_ = std::make_unique<Lms100Emulator>(config, source_.make());
    emulator_->start();
    port_ = emulator_->port();
  }
  void start_session(double scan_timeout_periods = 3.0) {
    Lms100SessionConfig config;
    config.host = "127.0.0.1";
    config.port = port_;
    config.dialect = dialect_;
    config.scan_timeout_periods = scan_timeout_periods;
    config.reply_timeout_s = 1.0;
    session_ = std::make_unique<Lms100Session>(config, [this](const LaserScan& s) { sink_(s); });
    session_->start_thread();
  }
  void TearDown() override {
    if (session_) session_->join();
    if (emulator_) emulator_->stop();
  }

  ColaDialect dialect_ = ColaDialect::kColaA;  ///< both ends speak it
  RecordingSource source_;
  ScanSink sink_;
  std::unique_ptr<Lms100Emulator> emulator_;
  std::unique_ptr<Lms100Session> session_;
  uint16_t port_ = 0;
};

/// The same session logic over either dialect: only the framing and the field encoding differ.
class SessionEmulatorDialectTest : public SessionEmulatorTest,
                                   public ::testing::WithParamInterface<ColaDialect> {
 protected:
  void SetUp() override { dialect_ = GetParam(); }
};

INSTANTIATE_TEST_SUITE_P(Dialects, SessionEmulatorDialectTest,
                         ::testing::Values(ColaDialect::kColaA, ColaDialect::kColaB),
                         [](const ::testing::TestParamInfo<ColaDialect>& info) {
                           return std::string(to_string(info.param));
                         });

TEST_P(SessionEmulatorDialectTest, HundredConsecutiveScansEqualWhatTheEmulatorSentValueByValue) {
  start_emulator();
  start_session();
  ASSERT_TRUE(sink_.wait_for(100, 10s)) << "got " << sink_.count();
  session_->join();
  std::lock_guard<std::mutex> lock_sink(sink_.mutex);
  std::lock_guard<std::mutex> lock_src(source_.mutex);
  for (size_t k = 0; k < 100; ++k) {
    const LaserScan& s = sink_.scans[k];
    if (k > 0) {
      ASSERT_EQ(s.scan_counter, (sink_.scans[k - 1].scan_counter + 1) & 0xFFFFu) << "scan lost before " << k;
    }
    const auto it = source_.sent.find(s.scan_counter);
    ASSERT_NE(it, source_.sent.end());
    const auto& [dist, rssi] = it->second;
    ASSERT_EQ(s.ranges.size(), 541u);
    ASSERT_EQ(s.rssi.size(), 541u);
    EXPECT_EQ(s.rssi_bits, 16);
    for (size_t i = 0; i < 541; ++i) {
      ASSERT_FLOAT_EQ(s.ranges[i], static_cast<float>(dist[i] * 1e-3)) << "scan " << k << " beam " << i;
      ASSERT_EQ(s.rssi[i], rssi[i]) << "scan " << k << " beam " << i;
    }
    EXPECT_NEAR(s.start_angle, -135.0 * M_PI / 180.0, 1e-9);
    EXPECT_NEAR(s.angle_increment, 0.5 * M_PI / 180.0, 1e-9);
    EXPECT_NEAR(s.time_increment, 1.0 / 36000.0, 1e-12);
    EXPECT_NEAR(s.scan_period, 0.02, 1e-12);
    EXPECT_LE(s.utime, s.receive_utime);
  }
  EXPECT_EQ(session_->counters().lost_scans.load(), 0u);
  EXPECT_EQ(session_->counters().parse_errors.load(), 0u);
  EXPECT_EQ(session_->counters().connects.load(), 1u);
  EXPECT_EQ(session_->counters().garbage_bytes.load(), 0u);
  EXPECT_EQ(session_->counters().unexpected_frames.load(), 0u);
}

TEST_P(SessionEmulatorDialectTest, MultiLayerTelegramsAreRefusedCountedAndNeverPublished) {
  start_emulator();
  std::vector<std::string> refusals;
  std::mutex refusals_mutex;
  Lms100SessionConfig config;
  config.host = "127.0.0.1";
  config.port = port_;
  config.dialect = dialect_;
  config.scan_timeout_periods = 50.0;  // a reconnect on a loaded host is not what this test is about
  session_ = std::make_unique<Lms100Session>(config, [this](const LaserScan& s) { sink_(s); });
  session_->set_reject_callback([&](const ScanPlausibility& p) {
    std::lock_guard<std::mutex> lock(refusals_mutex);
    refusals.push_back(p.detail);
  });
  session_->start_thread();
  ASSERT_TRUE(sink_.wait_for(5, 5s));
  FaultSettings layered = emulator_->faults().settings();
  layered.layer_angle_1e4deg = 0xFF06;  // -250 x 1e-4 deg, an MRS1000's lower layer
  emulator_->faults().set_settings(layered);
  std::this_thread::sleep_for(300ms);
  const size_t published_while_layered = sink_.count();
  std::this_thread::sleep_for(200ms);
  EXPECT_EQ(sink_.count(), published_while_layered) << "a multi-layer scan was published";
  EXPECT_GE(session_->counters().multi_layer_scans.load(), 5u);
  EXPECT_EQ(session_->counters().multi_layer_scans.load(), session_->counters().implausible_scans.load());
  EXPECT_EQ(session_->counters().parse_errors.load(), 0u);
  {
    std::lock_guard<std::mutex> lock(refusals_mutex);
    ASSERT_FALSE(refusals.empty());
    EXPECT_NE(refusals.front().find("multi-layer scanner"), std::string::npos) << refusals.front();
  }
  layered.layer_angle_1e4deg = 0;
  emulator_->faults().set_settings(layered);
  ASSERT_TRUE(sink_.wait_for(published_while_layered + 5, 3s));
}

TEST_F(SessionEmulatorTest, FirstBeamTimeIsWithinTwoMillisecondsOfTheEmulatorsBeamTime) {
  start_emulator();
  start_session();
  ASSERT_TRUE(sink_.wait_for(150, 10s));
  session_->join();
  // The emulator's device clock started at power_up_utime(); beam 0 of each scan is
  // at power_up + sensor_start (no drift in the emulator).
  std::lock_guard<std::mutex> lock(sink_.mutex);
  double worst_us = 0;
  for (size_t k = 50; k < sink_.scans.size(); ++k) {
    const LaserScan& s = sink_.scans[k];
    const int64_t truth = emulator_->power_up_utime() + s.sensor_start_us;
    worst_us = std::max(worst_us, std::fabs(static_cast<double>(s.utime - truth)));
  }
  std::printf("worst first-beam time error over %zu scans: %.0f us\n", sink_.scans.size() - 50, worst_us);
  EXPECT_LT(worst_us, 2000.0);
}

TEST_F(SessionEmulatorTest, EmulatorRestartedScansResumeWithinTwoSeconds) {
  start_emulator();
  start_session();
  ASSERT_TRUE(sink_.wait_for(10, 5s));
  const uint16_t port = port_;
  emulator_->stop();
  emulator_.reset();
  std::this_thread::sleep_for(300ms);
  const size_t before = sink_.count();
  start_emulator(port);
  const int64_t restarted = monotonic_us();
  ASSERT_TRUE(sink_.wait_for(before + 1, 2s));
  std::printf("scans resumed %.0f ms after the restart\n", (monotonic_us() - restarted) * 1e-3);
  EXPECT_GE(session_->counters().reconnects.load(), 1u);
  EXPECT_GE(session_->counters().connects.load(), 2u);
}

TEST_F(SessionEmulatorTest, StalledStreamCausesReconnectAndScansResume) {
  start_emulator();
  start_session();
  ASSERT_TRUE(sink_.wait_for(10, 5s));
  emulator_->faults().stall_for_ms(500);
  std::this_thread::sleep_for(700ms);
  const size_t before = sink_.count();
  ASSERT_TRUE(sink_.wait_for(before + 10, 3s));
  EXPECT_GE(session_->counters().timeouts.load(), 1u);
  EXPECT_GE(session_->counters().reconnects.load(), 1u);
}

TEST_F(SessionEmulatorTest, JunkBetweenTelegramsIsSkippedAndNoScanIsLost) {
  start_emulator();
  FaultSettings f;
  f.junk_bytes_between_telegrams = 17;
  f.split_mode = WriteSplitMode::random;
  f.split_pieces = 4;
  f.split_gap_ms = 1;
  emulator_->faults().set_settings(f);
  // A 1 s scan timeout: on a loaded 2-core CI host a 60 ms pause of this process is
  // ordinary, and the reconnect it causes is not what this test is about (CI saw one).
  start_session(50.0);
  ASSERT_TRUE(sink_.wait_for(60, 10s));
  session_->join();
  EXPECT_GT(session_->counters().garbage_bytes.load(), 17u * 50u);
  EXPECT_EQ(session_->counters().parse_errors.load(), 0u);
  EXPECT_EQ(session_->counters().lost_scans.load(), 0u);
  EXPECT_EQ(session_->counters().reconnects.load(), 0u);
}

TEST_F(SessionEmulatorTest, DroppedScansAreCountedAsCounterGaps) {
  start_emulator();
  start_session();
  ASSERT_TRUE(sink_.wait_for(10, 5s));
  emulator_->faults().drop_next_scans(2);  // 40 ms without scans: under the 60 ms timeout
  const size_t before = sink_.count();
  ASSERT_TRUE(sink_.wait_for(before + 10, 3s));
  EXPECT_EQ(session_->counters().scan_counter_gaps.load(), 1u)
      << "reconnects " << session_->counters().reconnects.load() << ", timeouts "
      << session_->counters().timeouts.load() << ", held " << session_->counters().held_scans.load()
      << ", dropped while held " << session_->counters().held_scans_dropped.load();
  EXPECT_EQ(session_->counters().lost_scans.load(), 2u);
}

TEST_F(SessionEmulatorTest, ResetInsideATelegramReconnectsWithoutParseErrorStreak) {
  start_emulator();
  start_session();
  ASSERT_TRUE(sink_.wait_for(10, 5s));
  emulator_->faults().reset_mid_telegram();
  std::this_thread::sleep_for(200ms);
  const size_t before = sink_.count();
  ASSERT_TRUE(sink_.wait_for(before + 10, 3s));
  EXPECT_GE(session_->counters().reconnects.load(), 1u);
}

TEST_F(SessionEmulatorTest, RefusedWriteIsAnSfaErrorAndTheNextAttemptSucceeds) {
  start_emulator();
  emulator_->faults().refuse_next_write();
  start_session();
  ASSERT_TRUE(sink_.wait_for(5, 5s));
  EXPECT_EQ(session_->counters().sfa_errors.load(), 1u);
  EXPECT_EQ(session_->counters().reconnects.load(), 1u);
}

TEST_F(SessionEmulatorTest, StopWhileStreamingReturnsWithinOneAndAHalfSeconds) {
  start_emulator();
  start_session();
  ASSERT_TRUE(sink_.wait_for(5, 5s));
  const int64_t t0 = monotonic_us();
  session_->join();
  EXPECT_LT(monotonic_us() - t0, 1'500'000);
  EXPECT_EQ(session_->state(), SessionState::kStopped);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc

#else
TEST(SessionEmulator, SkippedWithoutEmulator) { GTEST_SKIP() << "services/lms100_emulator not present"; }
#endif
