// The lms100_emulator executable as a real process (run inside a private network
// namespace, so port 2111 and the LCM group are ours): it serves a rendered world
// on TCP 2111, publishes its HEARTBEAT, rejects a bad config with exit 2, ends
// cleanly on SIGTERM, and the real lms100_driver turns its stream into
// LMS100_SCAN at 50 Hz.

#include "emulator_test_client.hpp"
#include "lms100_driver/lmd_scandata_parser.hpp"
#include "tests/tools/child_process.hpp"

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/laser_scan_t.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <thread>

namespace refloc {
namespace {

const char* kUrl = "udpm://239.255.76.67:7667?ttl=0";
const std::string kBin = std::string(REFLOC_BINARY_DIR) + "/bin/";
const std::string kWorld = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/world_demo.json";

std::unique_ptr<test::EmulatorTestClient> connect_with_retry(uint16_t port) {
  for (int i = 0; i < 200; ++i) {
    auto client = std::make_unique<test::EmulatorTestClient>(port);
    if (client->connected()) return client;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return nullptr;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Collector {
  std::vector<heartbeat_t> heartbeats;
  std::vector<laser_scan_t> scans;
  std::vector<int64_t> scan_receive_us;
  void on_heartbeat(const lcm::ReceiveBuffer*, const std::string&, const heartbeat_t* m) {
    heartbeats.push_back(*m);
  }
  void on_scan(const lcm::ReceiveBuffer* rbuf, const std::string&, const laser_scan_t* m) {
    scans.push_back(*m);
    scan_receive_us.push_back(rbuf->recv_utime);
  }
};

void spin_for(lcm::LCM& lcm, std::chrono::milliseconds duration) {
  const auto end = std::chrono::steady_clock::now() + duration;
  while (std::chrono::steady_clock::now() < end) lcm.handleTimeout(20);
}

TEST(Lms100EmulatorProcess, ServesARenderedWorldAndPublishesItsHeartbeat) {
  lcm::LCM lcm(kUrl);
  ASSERT_TRUE(lcm.good());
  Collector collector;
  lcm.subscribe("HEARTBEAT", &Collector::on_heartbeat, &collector);
  testing::ChildProcess emulator({kBin + "lms100_emulator", "--world", kWorld, "--pose", "10,3,1.5708",
                                  "--spin-up-s", "0.1", "--lcm-url", kUrl},
                                 std::string(REFLOC_BINARY_DIR) + "/lms100_emulator_process_test.log");
  auto client = connect_with_retry(2111);
  ASSERT_TRUE(client);
  ASSERT_EQ(client->request("sMN SetAccessMode 03 F4724744"), "sAN SetAccessMode 1");
  std::this_thread::sleep_for(std::chrono::milliseconds(150));
  ASSERT_EQ(client->request("sRN STlms").substr(0, 12), "sRA STlms 7 ");
  ASSERT_EQ(client->request("sEN LMDscandata 1"), "sEA LMDscandata 1");
  test::ReceivedFrame frame;
  ASSERT_TRUE(client->next_scan(frame, 1000));
  LmdScanData scan;
  ASSERT_TRUE(parse_lmd_scandata(frame.payload, scan).ok());
  ASSERT_EQ(scan.channels16.size(), 2u);
  const std::vector<uint16_t>& dist = scan.channels16[0].values;
  ASSERT_EQ(dist.size(), 541u);
  // Inside a 20 m x 12 m hall every beam sees something within 25 m.
  int echoes = 0;
  for (uint16_t d : dist) echoes += (d >= 16 && d < 25000) ? 1 : 0;
  EXPECT_GT(echoes, 500);

  spin_for(lcm, std::chrono::milliseconds(1300));
  bool seen = false;
  for (const heartbeat_t& h : collector.heartbeats) {
    if (h.service != "lms100_emulator") continue;
    seen = true;
    EXPECT_EQ(h.state, heartbeat_t::STATE_OK);
  }
  EXPECT_TRUE(seen);
  EXPECT_EQ(emulator.stop(), 0);
}

TEST(Lms100EmulatorProcess, BadConfigExitsWithCodeTwoNamingFileAndKey) {
  const std::string config = std::string(REFLOC_BINARY_DIR) + "/lms100_emulator_bad_config.json";
  std::ofstream(config) << R"({"scan_frequency_hz": 30})";
  const std::string log = std::string(REFLOC_BINARY_DIR) + "/lms100_emulator_bad_config.log";
  std::ofstream(log, std::ios::trunc).close();
  testing::ChildProcess emulator({kBin + "lms100_emulator", "--config", config, "--no-lcm"}, log);
  for (int i = 0; i < 200 && emulator.running(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(emulator.stop(), 2);
  const std::string text = read_file(log);
  EXPECT_NE(text.find("lms100_emulator_bad_config.json: /scan_frequency_hz"), std::string::npos) << text;
}

TEST(Lms100EmulatorProcess, TheRealDriverStreamsItAsLms100ScanAtFiftyHertz) {
  lcm::LCM lcm(kUrl);
  ASSERT_TRUE(lcm.good());
  Collector collector;
  lcm.subscribe("LMS100_SCAN", &Collector::on_scan, &collector);
  const std::string log = std::string(REFLOC_BINARY_DIR) + "/lms100_emulator_driver_e2e.log";
  testing::ChildProcess emulator({kBin + "lms100_emulator", "--world", kWorld, "--pose", "10,3,1.5708",
                                  "--spin-up-s", "0.5", "--no-lcm"},
                                 log);
  testing::ChildProcess driver(
      {kBin + "lms100_driver", "--host", "127.0.0.1", "--port", "2111", "--lcm-url", kUrl}, log);
  for (int i = 0; i < 150 && collector.scans.size() < 60; ++i) lcm.handleTimeout(20);
  collector.scans.clear();
  collector.scan_receive_us.clear();
  spin_for(lcm, std::chrono::milliseconds(1000));
  driver.stop();
  EXPECT_EQ(emulator.stop(), 0);
  ASSERT_GE(collector.scans.size(), 45u) << read_file(log);
  EXPECT_LE(collector.scans.size(), 52u);
  for (size_t i = 1; i < collector.scans.size(); ++i) {
    const laser_scan_t& a = collector.scans[i - 1];
    const laser_scan_t& b = collector.scans[i];
    EXPECT_EQ(b.scan_counter, (a.scan_counter + 1) & 0xFFFF);
    EXPECT_EQ(b.sensor_start_us - a.sensor_start_us, 20000);
  }
  const laser_scan_t& s = collector.scans.front();
  EXPECT_EQ(s.nranges, 541);
  EXPECT_EQ(s.nrssi, 541);
  EXPECT_EQ(s.rssi_bits, 16);
  EXPECT_NEAR(s.start_angle, -135.0 * M_PI / 180.0, 1e-6);
  EXPECT_NEAR(s.time_increment, 1.0 / 36000.0, 1e-9);
}

}  // namespace
}  // namespace refloc
