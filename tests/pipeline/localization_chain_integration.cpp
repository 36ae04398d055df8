// The localization chain as real processes over real TCP and LCM, in a private
// network namespace: lms100_emulator (rendering the paper's test cell from a
// known pose) -> lms100_driver (CoLa-A over TCP) -> reflector_extractor ->
// reflector_matcher -> pose_solver. Every LASER_POSE with status OK must lie
// within 10 mm (and 0.5 deg) of the pose the emulator rendered.

#include "common/robot_config.hpp"
#include "common/se2.hpp"
#include "tests/tools/child_process.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <refloc/pose2d_t.hpp>

#include <chrono>
#include <cmath>

namespace refloc {
namespace {

const std::string kUrl = "udpm://239.255.76.67:7667?ttl=0";
const std::string kSource = REFLOC_SOURCE_DIR;
const std::string kBin = std::string(REFLOC_BINARY_DIR) + "/bin/";

struct Collector {
  std::vector<pose2d_t> fixes;
  void on_pose(const lcm::ReceiveBuffer*, const std::string&, const pose2d_t* m) { fixes.push_back(*m); }
};

TEST(LocalizationChain, EmulatorToSolverGivesThePoseWithin10mm) {
  lcm::LCM lcm(kUrl);
  ASSERT_TRUE(lcm.good()) << "run through tests/tools/run_in_netns.sh";
  Collector collector;
  lcm.subscribe("LASER_POSE", &Collector::on_pose, &collector);

  const std::string config = kSource + "/deploy/config/";
  const RobotConfig robot = load_robot_config(config + "robot.json");
  const Pose2 map_T_robot{1.5, 2.0, 0.3};
  const Pose2 map_T_laser = map_T_robot * robot.robot_T_laser;
  const std::string log_dir = ::testing::TempDir();
  const std::string lcm_arg = "--lcm-url=" + kUrl;

  testing::ChildProcess emulator(
      {kBin + "lms100_emulator", "--bind", "127.0.0.1", "--port", "2111", "--world",
       config + "paper_cell.json", "--pose",
       fmt::format("{},{},{}", map_T_laser.x, map_T_laser.y, map_T_laser.theta), lcm_arg},
      log_dir + "chain_emulator.log");
  testing::ChildProcess driver({kBin + "lms100_driver", "--host", "127.0.0.1", "--port", "2111", "--config",
                                config + "lms100_driver.json", lcm_arg},
                               log_dir + "chain_driver.log");
  testing::ChildProcess extractor(
      {kBin + "reflector_extractor", "--config", config + "reflector_extractor.json", "--robot",
       config + "robot.json", lcm_arg},
      log_dir + "chain_extractor.log");
  testing::ChildProcess matcher(
      {kBin + "reflector_matcher", "--config", config + "reflector_matcher.json", "--map",
       config + "map_paper_cell.json", "--robot", config + "robot.json", lcm_arg},
      log_dir + "chain_matcher.log");
  testing::ChildProcess solver({kBin + "pose_solver", "--config", config + "pose_solver.json", "--robot",
                                config + "robot.json", lcm_arg},
                               log_dir + "chain_solver.log");

  // 50 OK fixes at 50 Hz after start-up; generous time for a loaded CI machine.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(40);
  auto ok_count = [&] {
    return std::count_if(collector.fixes.begin(), collector.fixes.end(),
                         [](const pose2d_t& p) { return p.status == pose2d_t::STATUS_OK; });
  };
  while (ok_count() < 50 && std::chrono::steady_clock::now() < deadline) lcm.handleTimeout(100);

  for (auto* p : {&emulator, &driver, &extractor, &matcher, &solver}) {
    EXPECT_TRUE(p->running()) << "a service died; logs in " << log_dir;
  }
  ASSERT_GE(ok_count(), 50) << collector.fixes.size() << " LASER_POSE messages, logs in " << log_dir;
  double sum_sq = 0.0, worst = 0.0;
  int n = 0;
  for (const auto& p : collector.fixes) {
    if (p.status != pose2d_t::STATUS_OK) continue;
    const double err = std::hypot(p.x - map_T_robot.x, p.y - map_T_robot.y);
    EXPECT_LT(err, 0.010) << "fix at " << p.utime << ": (" << p.x << ", " << p.y << ")";
    EXPECT_LT(std::abs(angle_diff(p.theta, map_T_robot.theta)), 0.5 * M_PI / 180.0);
    EXPECT_EQ(p.reflectors_used >= 3, true);
    sum_sq += err * err;
    worst = std::max(worst, err);
    ++n;
  }
  std::printf("%d OK fixes: RMS error %.2f mm, worst %.2f mm\n", n, 1000 * std::sqrt(sum_sq / n),
              1000 * worst);
}

}  // namespace
}  // namespace refloc
