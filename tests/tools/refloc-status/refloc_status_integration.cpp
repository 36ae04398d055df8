// refloc-status --once against a real process publishing HEARTBEAT over udpm
// (lcm_echo_peer). Runs inside tests/tools/run_in_netns.sh.

#include "tests/tools/child_process.hpp"
#include "tests/tools/run_command.hpp"

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <nlohmann/json.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/pose2d_t.hpp>

#include <atomic>
#include <string>
#include <thread>

namespace refloc {
namespace {

const std::string kBin = std::string(REFLOC_BINARY_DIR) + "/bin/";
const std::string kUrl = "udpm://239.255.76.67:7667?ttl=0";

class RefLocStatusWithPeer : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(peer_.start({kBin + "lcm_echo_peer", "--lcm-url", kUrl}, "/dev/null"));
  }
  testing::ChildProcess peer_;
};

std::string status_command(const std::string& args) {
  return kBin + "refloc-status --once --wait 2 --lcm-url '" + kUrl + "' " + args;
}

TEST_F(RefLocStatusWithPeer, ExpectedPeerPresentExitsZero) {
  const auto r = testing::run_command(status_command("--expect lcm_echo_peer"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("lcm_echo_peer"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("all 1 expected services alive"), std::string::npos) << r.output;
}

TEST_F(RefLocStatusWithPeer, MissingServiceExitsOne) {
  const auto r = testing::run_command(status_command("--expect lcm_echo_peer,missing_service"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("MISSING or stale: missing_service"), std::string::npos) << r.output;
}

TEST_F(RefLocStatusWithPeer, JsonReportsPeerPidStateAndRates) {
  const auto r = testing::run_command(status_command("--expect lcm_echo_peer --json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto doc = nlohmann::json::parse(r.output);
  ASSERT_EQ(doc["services"].size(), 1u);
  const auto& peer = doc["services"][0];
  EXPECT_EQ(peer["service"], "lcm_echo_peer");
  EXPECT_EQ(peer["pid"].get<int>(), peer_.pid());
  EXPECT_EQ(peer["state"], "OK");
  EXPECT_LT(peer["age_s"].get<double>(), 1.0);              // the peer beats every 0.2 s
  EXPECT_DOUBLE_EQ(peer["rate_in_hz"].get<double>(), 0.0);  // nobody sends it data
}

TEST(RefLocStatus, StoppedServiceTurnsStaleAndExitsOne) {
  testing::ChildProcess peer({kBin + "lcm_echo_peer", "--lcm-url", kUrl}, "/dev/null");
  // Listen 5 s; the peer dies after 1 s, so its last heartbeat is > 3 s old at the end.
  const std::string cmd =
      kBin + "refloc-status --once --wait 5 --json --expect lcm_echo_peer --lcm-url '" + kUrl + "'";
  FILE* pipe = popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::this_thread::sleep_for(std::chrono::seconds(1));
  peer.stop();
  std::string output;
  char buffer[4096];
  size_t n = 0;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) output.append(buffer, n);
  const int status = pclose(pipe);
  EXPECT_EQ(WEXITSTATUS(status), 1) << output;
  const auto doc = nlohmann::json::parse(output);
  EXPECT_EQ(doc["missing"], nlohmann::json::array({"lcm_echo_peer"}));
  EXPECT_TRUE(doc["services"][0]["stale"].get<bool>());
  EXPECT_EQ(doc["services"][0]["state"], "STOPPING");  // its last word before exiting
}

TEST(RefLocStatus, NothingOnTheBusMeansEveryExpectedServiceMissing) {
  const auto r = testing::run_command(kBin + "refloc-status --once --wait 0.5 --lcm-url '" + kUrl + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("lms100_driver"), std::string::npos);
  EXPECT_NE(r.output.find("robot_sim"), std::string::npos);
}

/// Publishes, every 50 ms until destroyed, the HEARTBEAT of a service `fake_driver` in the given
/// state, a POSE and an OK LASER_POSE: what refloc-status watches, without a whole stack.
class FakeStack {
 public:
  explicit FakeStack(int8_t state) : thread_([this, state] { publish_until_stopped(state); }) {}
  ~FakeStack() {
    stop_ = true;
    thread_.join();
  }

 private:
  void publish_until_stopped(int8_t state) {
    lcm::LCM lcm(kUrl);
    heartbeat_t hb{};
    hb.service = "fake_driver";
    hb.pid = 77;
    hb.state = state;
    hb.state_detail = "sensor unreachable";
    pose2d_t pose{};
    pose.x = 1.25;
    pose.y = -0.5;
    pose.covariance[0] = pose.covariance[4] = 4e-6;  // 2 mm
    pose.covariance[8] = 1e-6;
    pose.status = pose2d_t::STATUS_OK;
    for (int i = 0; !stop_; ++i) {
      hb.utime = pose.utime = 1'000'000 + i * 50'000;
      hb.uptime_us = hb.utime;
      hb.messages_out = i;
      lcm.publish("HEARTBEAT", &hb);
      lcm.publish("POSE", &pose);
      lcm.publish("LASER_POSE", &pose);
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

TEST(RefLocStatus, AServiceInErrorExitsOneAndThePoseLineShowsPOSE) {
  FakeStack stack(heartbeat_t::STATE_ERROR);
  const auto r = testing::run_command(
      kBin + "refloc-status --once --wait 1.5 --expect fake_driver --lcm-url '" + kUrl + "'");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("IN ERROR: fake_driver"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("POSE OK x 1.250 y -0.500 m, theta 0.00 deg, sigma 2.0 mm 0.06 deg, fixes "),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(" 20.0 "), std::string::npos) << "20 messages out a second: " << r.output;
}

TEST(RefLocStatus, DegradedPassesAndWideIsWiderThanOneHundredColumns) {
  FakeStack stack(heartbeat_t::STATE_DEGRADED);
  const auto r = testing::run_command(kBin +
                                      "refloc-status --once --wide --wait 1.5 --expect fake_driver "
                                      "--lcm-url '" +
                                      kUrl + "'");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("P50[us]"), std::string::npos) << r.output;
}

TEST(RefLocStatus, UsageErrorsExit64AndVersionExits0) {
  EXPECT_EQ(testing::run_command(kBin + "refloc-status --no-such-option").exit_code, 64);
  EXPECT_EQ(testing::run_command(kBin + "refloc-status --wait -1").exit_code, 64);
  const auto v = testing::run_command(kBin + "refloc-status --version");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_EQ(v.output.rfind("refloc-status from refloc ", 0), 0u) << v.output;
}

}  // namespace
}  // namespace refloc
