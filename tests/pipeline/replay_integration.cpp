// Replay: logs/samples/replay_demo_4s.lcm was recorded live while the demo robot
// drove. Its inputs (LMS100_SCAN, ODOMETRY, POSE) are played with lcm-logplayer
// into freshly started reflector_extractor, reflector_matcher and pose_solver
// processes; the LASER_POSE they publish must reproduce the recorded LASER_POSE.
// Services take time from message utime, never from the clock, so this holds.

#include "tests/tools/child_process.hpp"

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>

#include <chrono>
#include <cmath>
#include <map>
#include <set>

namespace refloc {
namespace {

const std::string kUrl = "udpm://239.255.76.67:7667?ttl=0";
const std::string kSource = REFLOC_SOURCE_DIR;
const std::string kBin = std::string(REFLOC_BINARY_DIR) + "/bin/";
const std::string kLog = kSource + "/logs/samples/replay_demo_4s.lcm";

struct Recorded {
  std::map<int64_t, pose2d_t> laser_poses;
  double max_speed = 0.0;  ///< [m/s] from ODOMETRY: the sample must be of a moving robot
};

Recorded read_recorded(const std::string& path) {
  Recorded r;
  lcm::LogFile log(path, "r");
  EXPECT_TRUE(log.good()) << path;
  while (const lcm::LogEvent* e = log.readNextEvent()) {
    if (e->channel == "LASER_POSE") {
      pose2d_t p;
      if (p.decode(e->data, 0, e->datalen) >= 0) r.laser_poses[p.utime] = p;
    } else if (e->channel == "ODOMETRY") {
      odometry_t o;
      if (o.decode(e->data, 0, e->datalen) >= 0) r.max_speed = std::max(r.max_speed, std::hypot(o.vx, o.vy));
    }
  }
  return r;
}

struct Inbox {
  std::map<int64_t, pose2d_t> laser_poses;
  std::set<std::string> services;
  void on_pose(const lcm::ReceiveBuffer*, const std::string&, const pose2d_t* m) { laser_poses[m->utime] = *m; }
  void on_heartbeat(const lcm::ReceiveBuffer*, const std::string&, const heartbeat_t* m) { services.insert(m->service); }
};

TEST(Replay, LoggedScansThroughExtractorMatcherSolverReproduceTheRecordedLaserPose) {
  const Recorded recorded = read_recorded(kLog);
  ASSERT_GE(recorded.laser_poses.size(), 150u);
  ASSERT_GT(recorded.max_speed, 0.3) << "the sample should show a moving robot";

  lcm::LCM lcm(kUrl);
  ASSERT_TRUE(lcm.good()) << "run through tests/tools/run_in_netns.sh";
  Inbox inbox;
  lcm.subscribe("LASER_POSE", &Inbox::on_pose, &inbox);
  lcm.subscribe("HEARTBEAT", &Inbox::on_heartbeat, &inbox);

  const std::string config = kSource + "/deploy/config/";
  const std::string logs = ::testing::TempDir();
  const std::string url = "--lcm-url=" + kUrl;
  testing::ChildProcess extractor({kBin + "reflector_extractor", "--config", config + "reflector_extractor.json",
                                   "--robot", config + "robot.json", url}, logs + "replay_extractor.log");
  testing::ChildProcess matcher({kBin + "reflector_matcher", "--config", config + "reflector_matcher.json",
                                 "--robot", config + "robot.json", url}, logs + "replay_matcher.log");
  testing::ChildProcess solver({kBin + "pose_solver", "--config", config + "pose_solver.json", "--robot",
                                config + "robot.json", url}, logs + "replay_solver.log");
  // Services announce themselves with their first heartbeat once they are subscribed.
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (inbox.services.size() < 3 && std::chrono::steady_clock::now() < deadline) lcm.handleTimeout(100);
  ASSERT_EQ(inbox.services.size(), 3u);

  testing::ChildProcess player({"/usr/bin/lcm-logplayer", "--lcm-url=" + kUrl,
                                "--regexp=^(LMS100_SCAN|ODOMETRY|POSE)$", kLog}, logs + "replay_player.log");
  deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (player.running() && std::chrono::steady_clock::now() < deadline) lcm.handleTimeout(50);
  const auto drain = std::chrono::steady_clock::now() + std::chrono::milliseconds(1000);
  while (std::chrono::steady_clock::now() < drain) lcm.handleTimeout(50);

  size_t compared = 0, same_status = 0;
  double worst_xy = 0.0, worst_theta = 0.0;
  for (const auto& [utime, live] : recorded.laser_poses) {
    const auto it = inbox.laser_poses.find(utime);
    if (it == inbox.laser_poses.end()) continue;
    ++compared;
    const pose2d_t& replayed = it->second;
    if (replayed.status != live.status) continue;
    ++same_status;
    if (live.status != pose2d_t::STATUS_OK && live.status != pose2d_t::STATUS_DEGRADED) continue;
    worst_xy = std::max(worst_xy, std::hypot(replayed.x - live.x, replayed.y - live.y));
    worst_theta = std::max(worst_theta, std::abs(std::remainder(replayed.theta - live.theta, 2 * M_PI)));
  }
  std::printf("recorded %zu, replayed %zu, compared %zu, same status %zu, worst difference %.3f mm %.4f deg\n",
              recorded.laser_poses.size(), inbox.laser_poses.size(), compared, same_status, 1000 * worst_xy,
              worst_theta * 180 / M_PI);
  // The first scans after a cold start relocalize globally; everything after must agree.
  EXPECT_GE(compared, recorded.laser_poses.size() * 95 / 100);
  EXPECT_GE(same_status, compared * 98 / 100);
  EXPECT_LT(worst_xy, 0.001);
  EXPECT_LT(worst_theta, 0.05 * M_PI / 180.0);
}

}  // namespace
}  // namespace refloc
