// reflector_matcher and pose_solver as real processes over UDP multicast (run in a
// private network namespace): synthetic REFLECTORS in, REFLECTOR_MATCHES and
// LASER_POSE out. Checks global relocalization at start, tracking from the
// matcher's own last pose, global relocalization again after a matcher restart,
// and that an ambiguous (symmetric) layout reaches LASER_POSE as AMBIGUOUS.

#include "common/reflector_map.hpp"
#include "common/robot_config.hpp"
#include "tests/tools/child_process.hpp"

#include "synthetic_detections.hpp"

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_matches_t.hpp>

#include <algorithm>
#include <chrono>
#include <optional>

namespace refloc {
namespace {

const char* kUrl = "udpm://239.255.76.67:7667?ttl=0";
const std::string kSource = REFLOC_SOURCE_DIR;
const std::string kBin = std::string(REFLOC_BINARY_DIR) + "/bin/";

class MatcherSolverIntegration : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(lcm_.good());
    lcm_.subscribe("REFLECTOR_MATCHES", &MatcherSolverIntegration::on_matches, this);
    lcm_.subscribe("LASER_POSE", &MatcherSolverIntegration::on_pose, this);
    robot_T_laser_ = load_robot_config(kSource + "/deploy/config/robot.json").robot_T_laser;
    ASSERT_TRUE(solver_.start({kBin + "pose_solver", std::string("--lcm-url=") + kUrl, "--config",
                               kSource + "/deploy/config/pose_solver.json", "--robot",
                               kSource + "/deploy/config/robot.json"}));
    // The solver must listen before the first scan: a resent scan is tracked, not relocalized,
    // by a matcher that answered the first one while a late-started solver missed it.
    ASSERT_TRUE(wait_for_heartbeat("pose_solver"));
  }

  bool wait_for_heartbeat(const std::string& service) {
    awaited_service_ = service;
    heard_awaited_ = false;
    // LCM 1.3.1 takes no lambdas: a member handler.
    lcm::Subscription* sub = lcm_.subscribe("HEARTBEAT", &MatcherSolverIntegration::on_heartbeat, this);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
    while (!heard_awaited_ && std::chrono::steady_clock::now() < deadline) lcm_.handleTimeout(50);
    lcm_.unsubscribe(sub);
    return heard_awaited_;
  }
  void on_heartbeat(const lcm::ReceiveBuffer*, const std::string&, const heartbeat_t* msg) {
    heard_awaited_ = heard_awaited_ || msg->service == awaited_service_;
  }

  bool start_matcher(const std::string& map_file) {
    return matcher_.start({kBin + "reflector_matcher", std::string("--lcm-url=") + kUrl, "--config",
                           kSource + "/deploy/config/reflector_matcher.json", "--robot",
                           kSource + "/deploy/config/robot.json", "--map", map_file});
  }

  void on_matches(const lcm::ReceiveBuffer*, const std::string&, const reflector_matches_t* msg) {
    matches_.push_back(*msg);
  }
  void on_pose(const lcm::ReceiveBuffer*, const std::string&, const pose2d_t* msg) { poses_.push_back(*msg); }

  reflector_detections_t scan_message(const ReflectorMap& map, const Pose2& map_T_robot, int64_t utime) {
    const auto scan =
        testing::render_detections(map, map_T_robot * robot_T_laser_, testing::SyntheticSensor{}, rng_);
    reflector_detections_t msg{};
    msg.utime = utime;
    msg.scan_counter = static_cast<int32_t>(utime / 1000);
    for (const ReflectorDetection& d : scan.detections) {
      reflector_t r{};
      r.x = d.laser_p_center.x();
      r.y = d.laser_p_center.y();
      for (int i = 0; i < 4; ++i) r.covariance[i] = d.covariance(i / 2, i % 2);
      r.range = d.range;
      r.bearing = d.bearing;
      r.utime = utime;
      r.fitted_radius_m = 0.06f;
      msg.reflectors.push_back(r);
    }
    msg.nreflectors = static_cast<int32_t>(msg.reflectors.size());
    return msg;
  }

  /// Publish msg (again every 200 ms: the services may still be starting) until the
  /// LASER_POSE for its utime is back; returns the matches and the pose.
  /// Publishes msg until its LASER_POSE comes back. A resend is the same scan 100 us later:
  /// the matcher refuses a repeated stamp (not increasing), and a solver that subscribed after
  /// the first answer (a loaded host starts it late) would otherwise never see one.
  std::optional<std::pair<reflector_matches_t, pose2d_t>> exchange(reflector_detections_t msg) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
    auto next_publish = std::chrono::steady_clock::now();
    std::vector<int64_t> sent;
    while (std::chrono::steady_clock::now() < deadline) {
      if (std::chrono::steady_clock::now() >= next_publish) {
        if (!sent.empty()) msg.utime += 100;
        lcm_.publish("REFLECTORS", &msg);
        sent.push_back(msg.utime);
        next_publish += std::chrono::milliseconds(200);
      }
      lcm_.handleTimeout(20);
      for (const pose2d_t& p : poses_) {
        if (std::find(sent.begin(), sent.end(), p.utime) == sent.end()) continue;
        for (const reflector_matches_t& m : matches_) {
          if (m.utime == p.utime) return std::make_pair(m, p);
        }
      }
    }
    return std::nullopt;
  }

  lcm::LCM lcm_{kUrl};
  std::mt19937 rng_{60};
  Pose2 robot_T_laser_;
  std::string awaited_service_;
  bool heard_awaited_ = false;
  std::vector<reflector_matches_t> matches_;
  std::vector<pose2d_t> poses_;
  testing::ChildProcess solver_, matcher_;
};

TEST_F(MatcherSolverIntegration, RelocalizesTracksAndRelocalizesAfterRestart) {
  const std::string map_file = kSource + "/deploy/config/map_demo.json";
  const ReflectorMap map = load_reflector_map(map_file);
  ASSERT_TRUE(start_matcher(map_file));

  const Pose2 first{8.0, 6.0, 0.3};
  const auto a = exchange(scan_message(map, first, 1'000'000'000));
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->first.status, reflector_matches_t::STATUS_OK);
  EXPECT_EQ(a->first.mode, reflector_matches_t::MODE_GLOBAL);
  EXPECT_EQ(a->first.nmatches, a->first.ndetections);
  EXPECT_EQ(a->second.status, pose2d_t::STATUS_OK);
  EXPECT_NEAR(a->second.x, first.x, 0.03);
  EXPECT_NEAR(a->second.y, first.y, 0.03);
  EXPECT_NEAR(angle_diff(a->second.theta, first.theta), 0.0, 0.005);
  EXPECT_EQ(a->second.reflectors_used, a->first.nmatches);
  EXPECT_GT(a->second.covariance[0], 0.0);

  // 40 ms later, 2 cm on: tracked from the matcher's own last pose (no POSE is published).
  const Pose2 second{8.02, 6.0, 0.31};
  const auto b = exchange(scan_message(map, second, 1'000'040'000));
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(b->first.status, reflector_matches_t::STATUS_OK);
  EXPECT_EQ(b->first.mode, reflector_matches_t::MODE_TRACKING);
  EXPECT_NEAR(b->second.x, second.x, 0.03);
  EXPECT_NEAR(b->second.y, second.y, 0.03);

  // A restarted matcher has no prior: it relocalizes globally.
  EXPECT_EQ(matcher_.stop(), 0);
  ASSERT_TRUE(start_matcher(map_file));
  const Pose2 third{12.0, 4.0, -2.5};
  const auto c = exchange(scan_message(map, third, 1'000'080'000));
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->first.status, reflector_matches_t::STATUS_OK);
  EXPECT_EQ(c->first.mode, reflector_matches_t::MODE_GLOBAL);
  EXPECT_NEAR(c->second.x, third.x, 0.03);
  EXPECT_NEAR(c->second.y, third.y, 0.03);
}

TEST_F(MatcherSolverIntegration, SymmetricLayoutReachesLaserPoseAsAmbiguous) {
  const std::string map_file = kSource + "/deploy/config/map_symmetric.json";
  const ReflectorMap map = load_reflector_map(map_file);
  ASSERT_TRUE(start_matcher(map_file));
  // Inside the 180-deg-symmetric layout: the rotated pose sees the identical scan.
  const auto r = exchange(scan_message(map, Pose2{3.5, 2.5, 0.4}, 2'000'000'000));
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->first.status, reflector_matches_t::STATUS_AMBIGUOUS);
  EXPECT_EQ(r->second.status, pose2d_t::STATUS_AMBIGUOUS);
  EXPECT_EQ(r->second.reflectors_used, 0);
}

}  // namespace
}  // namespace refloc
