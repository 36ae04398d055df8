// Each fault knob of the emulator does what it says, seen from a real TCP client.

#include "emulator_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <thread>

namespace refloc::test {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::vector<LmdScanData> collect(EmulatorTestClient& client, int count,
                                 std::vector<int64_t>* times = nullptr) {
  std::vector<LmdScanData> scans;
  ReceivedFrame frame;
  while (static_cast<int>(scans.size()) < count && client.next_scan(frame, 800)) {
    scans.push_back(parse_or_fail(frame.payload));
    if (times) times->push_back(frame.receive_mono_us);
  }
  return scans;
}

size_t count_etx(const std::string& bytes) {
  return static_cast<size_t>(std::count(bytes.begin(), bytes.end(), '\x03'));
}

TEST(Lms100EmulatorFaults, BoundarySplitSendsStxAloneAndEveryScanStillParses) {
  Lms100EmulatorConfig config = make_test_emulator_config();
  config.faults.split_mode = WriteSplitMode::boundaries;
  auto emulator = start_emulator(config);
  EmulatorTestClient client(emulator->port());
  ASSERT_TRUE(subscribe_to_stream(client));
  ASSERT_EQ(collect(client, 10).size(), 10u);
  const auto& reads = client.raw_reads();
  const auto lone_stx = std::count(reads.begin(), reads.end(), std::string("\x02"));
  const auto lone_etx = std::count(reads.begin(), reads.end(), std::string("\x03"));
  EXPECT_GE(lone_stx, 10);  // replies and scans: each frame's STX arrived on its own
  EXPECT_GE(lone_etx, 10);
}

TEST(Lms100EmulatorFaults, RandomSplitCutsScansIntoSeveralReads) {
  Lms100EmulatorConfig config = make_test_emulator_config();
  config.faults.split_mode = WriteSplitMode::random;
  config.faults.split_pieces = 4;
  auto emulator = start_emulator(config);
  EmulatorTestClient client(emulator->port());
  ASSERT_TRUE(subscribe_to_stream(client));
  const size_t reads_before = client.raw_reads().size();
  const std::vector<LmdScanData> scans = collect(client, 10);
  ASSERT_EQ(scans.size(), 10u);
  EXPECT_GE(client.raw_reads().size() - reads_before, 25u);  // ~4 reads a scan
  for (size_t i = 1; i < scans.size(); ++i)
    EXPECT_EQ(scans[i].scan_counter, (scans[i - 1].scan_counter + 1) & 0xFFFF);
}

TEST(Lms100EmulatorFaults, MergeSendsSeveralScansInOneWrite) {
  auto emulator = start_emulator(make_test_emulator_config());
  EmulatorTestClient client(emulator->port());
  ASSERT_TRUE(subscribe_to_stream(client));
  FaultSettings settings;
  settings.merge_scan_telegrams = 3;
  emulator->faults().set_settings(settings);
  std::vector<int64_t> times;
  const std::vector<LmdScanData> scans = collect(client, 12, &times);
  ASSERT_EQ(scans.size(), 12u);
  size_t multi_frame_reads = 0;
  for (const std::string& read : client.raw_reads()) multi_frame_reads += count_etx(read) >= 3 ? 1 : 0;
  EXPECT_GE(multi_frame_reads, 2u);
  // Scans still come in order and complete, three at a time about 60 ms apart.
  for (size_t i = 1; i < scans.size(); ++i)
    EXPECT_EQ(scans[i].scan_counter, (scans[i - 1].scan_counter + 1) & 0xFFFF);
  const int64_t max_gap = [&] {
    int64_t gap = 0;
    for (size_t i = 1; i < times.size(); ++i) gap = std::max(gap, times[i] - times[i - 1]);
    return gap;
  }();
  EXPECT_GT(max_gap, 45000);
}

TEST(Lms100EmulatorFaults, JunkBetweenTelegramsIsSkippedByTheSplitter) {
  Lms100EmulatorConfig config = make_test_emulator_config();
  config.faults.junk_bytes_between_telegrams = 17;
  auto emulator = start_emulator(config);
  EmulatorTestClient client(emulator->port());
  ASSERT_TRUE(subscribe_to_stream(client));
  ASSERT_EQ(collect(client, 10).size(), 10u);
  // At least 17 bytes before each of the 10 scans and 4+ replies (stray ETX bytes count as garbage too).
  EXPECT_GE(client.splitter().garbage_bytes(), 14u * 17u);
}

TEST(Lms100EmulatorFaults, DuplicateRepliesAnswerTwice) {
  Lms100EmulatorConfig config = make_test_emulator_config();
  config.faults.duplicate_replies = true;
  auto emulator = start_emulator(config);
  EmulatorTestClient client(emulator->port());
  EXPECT_EQ(client.request("sRN LMPscancfg"), "sRA LMPscancfg 1388 1 1388 FFF92230 225510");
  EXPECT_EQ(client.next_reply(500), "sRA LMPscancfg 1388 1 1388 FFF92230 225510");
}

TEST(Lms100EmulatorFaults, StallHoldsTheStreamThenDeliversTheBacklogInABurst) {
  auto emulator = start_emulator(make_test_emulator_config());
  EmulatorTestClient client(emulator->port());
  ASSERT_TRUE(subscribe_to_stream(client));
  ASSERT_EQ(collect(client, 2).size(), 2u);
  const int64_t stall_start = monotonic_us();
  emulator->faults().stall_for_ms(300);
  std::vector<int64_t> times;
  const std::vector<LmdScanData> scans = collect(client, 20, &times);
  ASSERT_EQ(scans.size(), 20u);
  EXPECT_GT(times[0] - stall_start, 280000);
  // Nothing was lost: counters are continuous through the stall.
  for (size_t i = 1; i < scans.size(); ++i)
    EXPECT_EQ(scans[i].scan_counter, (scans[i - 1].scan_counter + 1) & 0xFFFF);
  // The backlog (~14 scans made during the stall) arrived together right after it.
  EXPECT_LT(times[10] - times[0], 10000);
}

TEST(Lms100EmulatorFaults, DroppedScansLeaveAScanCounterGapButNoTelegramCounterGap) {
  auto emulator = start_emulator(make_test_emulator_config());
  EmulatorTestClient client(emulator->port());
  ASSERT_TRUE(subscribe_to_stream(client));
  ASSERT_EQ(collect(client, 2).size(), 2u);
  emulator->faults().drop_next_scans(3);
  const std::vector<LmdScanData> scans = collect(client, 6);
  ASSERT_EQ(scans.size(), 6u);
  int gaps = 0;
  for (size_t i = 1; i < scans.size(); ++i) {
    const uint32_t step = (scans[i].scan_counter - scans[i - 1].scan_counter) & 0xFFFF;
    EXPECT_EQ(scans[i].telegram_counter, (scans[i - 1].telegram_counter + 1) & 0xFFFF);
    if (step != 1) {
      EXPECT_EQ(step, 4u);
      ++gaps;
    }
  }
  // The drop may have hit before the first collected scan; then the gap is not visible here.
  EXPECT_LE(gaps, 1);
  EXPECT_EQ(emulator->stats().scans_dropped, 3u);
}

TEST(Lms100EmulatorFaults, CloseNowDropsTheClientAndTheNextOneIsServed) {
  auto emulator = start_emulator(make_test_emulator_config());
  EmulatorTestClient client(emulator->port());
  ASSERT_TRUE(subscribe_to_stream(client));
  emulator->faults().close_connection_now();
  EXPECT_TRUE(client.wait_for_close(200));
  EmulatorTestClient next(emulator->port());
  ASSERT_TRUE(subscribe_to_stream(next));
  EXPECT_EQ(collect(next, 2).size(), 2u);
}

TEST(Lms100EmulatorFaults, ResetMidTelegramSendsHalfAScanThenCloses) {
  auto emulator = start_emulator(make_test_emulator_config());
  EmulatorTestClient client(emulator->port());
  ASSERT_TRUE(subscribe_to_stream(client));
  ASSERT_EQ(collect(client, 1).size(), 1u);
  emulator->faults().reset_mid_telegram();
  ReceivedFrame frame;
  while (client.next_frame(frame, 500)) {
  }
  EXPECT_TRUE(client.closed_by_peer());
  std::string all;
  for (const std::string& read : client.raw_reads()) all += read;
  const size_t last_stx = all.rfind('\x02');
  ASSERT_NE(last_stx, std::string::npos);
  EXPECT_EQ(all.find('\x03', last_stx), std::string::npos);  // the last frame never ended
  EXPECT_EQ(all.compare(last_stx + 1, 15, "sSN LMDscandata"), 0);
  EXPECT_GT(all.size() - last_stx, 1000u);
}

TEST(Lms100EmulatorFaults, RefusedReadinessKeepsStlmsBelowSevenAndNoScansFlow) {
  Lms100EmulatorConfig config = make_test_emulator_config();
  config.faults.refuse_readiness = true;
  auto emulator = start_emulator(config);
  EmulatorTestClient client(emulator->port());
  std::this_thread::sleep_for(std::chrono::milliseconds(150));  // three spin-up times
  EXPECT_EQ(client.request("sRN STlms").substr(0, 12), "sRA STlms 4 ");
  EXPECT_EQ(client.request("sRN SCdevicestate"), "sRA SCdevicestate 0");
  EXPECT_EQ(client.request("sEN LMDscandata 1"), "sEA LMDscandata 1");
  ReceivedFrame frame;
  EXPECT_FALSE(client.next_scan(frame, 150));
  FaultSettings settings;
  emulator->faults().set_settings(settings);
  EXPECT_EQ(client.request("sRN STlms").substr(0, 12), "sRA STlms 7 ");
  EXPECT_TRUE(client.next_scan(frame, 200));
}

TEST(Lms100EmulatorFaults, FirstWriteAfterPowerUpIsRefusedWithSfa4) {
  Lms100EmulatorConfig config = make_test_emulator_config();
  config.refuse_first_write_after_power_up = true;
  auto emulator = start_emulator(config);
  EmulatorTestClient client(emulator->port());
  ASSERT_EQ(client.request("sMN SetAccessMode 03 F4724744"), "sAN SetAccessMode 1");
  EXPECT_EQ(client.request("sWN LMPoutputRange 1 1388 FFF92230 225510"), "sFA 4");
  EXPECT_EQ(client.request("sWN LMPoutputRange 1 1388 FFF92230 225510"), "sWA LMPoutputRange");
  emulator->faults().refuse_next_write();
  EXPECT_EQ(client.request("sWN LMDscandatacfg 01 00 1 1 0 00 00 0 0 0 1 +1"), "sFA 4");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc::test
