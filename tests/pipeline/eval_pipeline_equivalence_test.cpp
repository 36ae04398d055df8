// refloc-eval's LocalizationPipeline is the services' chain, not a copy of it:
//  1. a scan sequence rendered along a drive, with ODOMETRY and POSE interleaved in time
//     order, run through ExtractorNode -> REFLECTORS -> MatcherNode -> REFLECTOR_MATCHES ->
//     SolverNode exactly as the three mains do (their own edge conversions, every message
//     encoded and decoded by LCM)
//     and through the pipeline: LASER_POSE identical field by field;
//  2. logs/samples/replay_demo_4s.lcm (recorded from the service processes) fed to the
//     pipeline in log order: the recorded LASER_POSE reproduced after the matcher's cold start.

#include "common/lcm_conversions.hpp"
#include "common/reflector_map.hpp"
#include "common/robot_config.hpp"
#include "localization_pipeline.hpp"
#include "pose_solver/solver_messages.hpp"
#include "reflector_extractor/extractor_messages.hpp"
#include "reflector_matcher/matcher_messages.hpp"
#include "tests/pipeline/recorded_log_reader.hpp"
#include "world_renderer/scan_renderer.hpp"
#include "world_renderer/world_loader.hpp"

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <refloc/laser_scan_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_matches_t.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

const std::string kConfig = std::string(REFLOC_SOURCE_DIR) + "/deploy/config";

/// An LCM message as a process on the other side of the wire gets it.
template <class Message>
Message over_the_wire(const Message& m) {
  std::vector<uint8_t> bytes(static_cast<size_t>(m.getEncodedSize()));
  EXPECT_GE(m.encode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  Message out;
  EXPECT_GE(out.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  return out;
}

std::vector<std::string> differing_fields(const pose2d_t& a, const pose2d_t& b) {
  std::vector<std::string> d;
  if (a.utime != b.utime) d.push_back("utime");
  if (a.x != b.x) d.push_back("x");
  if (a.y != b.y) d.push_back("y");
  if (a.theta != b.theta) d.push_back("theta");
  for (int i = 0; i < 9; ++i)
    if (a.covariance[i] != b.covariance[i]) d.push_back("covariance[" + std::to_string(i) + "]");
  if (a.status != b.status) d.push_back("status");
  if (a.reflectors_used != b.reflectors_used) d.push_back("reflectors_used");
  if (a.residual != b.residual) d.push_back("residual");
  return d;
}

/// The three services as their mains run them, each message crossing LCM.
class ServiceChain {
 public:
  ServiceChain(const PipelineConfigs& c, const ReflectorMap& map, const Pose2& robot_T_laser)
      : extractor_(c.extractor, robot_T_laser),
        matcher_(map, c.matcher, robot_T_laser),
        solver_(c.solver.solver, robot_T_laser) {}

  void on_odometry(const odometry_t& sent) {
    extractor_.on_odometry(odometry_twist_from_message(over_the_wire(sent)));
  }
  void on_pose(const pose2d_t& sent) { matcher_.on_pose(fused_pose_from_message(over_the_wire(sent))); }
  pose2d_t on_scan(const laser_scan_t& sent) {
    LaserScan scan;
    scan_from_message(over_the_wire(sent), scan);
    reflector_detections_t reflectors{};
    const ExtractorOutput& extracted = extractor_.on_scan(scan);
    EXPECT_TRUE(extracted.accepted) << (extracted.events.empty() ? "" : extracted.events[0].log);
    to_message(extracted, reflectors);
    reflectors = over_the_wire(reflectors);

    std::vector<ReflectorDetection> detections;
    detections_from_message(reflectors, detections);
    reflector_matches_t matches{};
    // The message's own stamp is the host clock: the drive is replayed faster than real time.
    const MatcherOutput& matched_scan =
        matcher_.on_detections(reflectors.utime, reflectors.scan_counter, detections, reflectors.utime);
    EXPECT_TRUE(matched_scan.accepted) << (matched_scan.events.empty() ? "" : matched_scan.events[0].log);
    to_message(reflectors, matched_scan.result, matches);
    matches = over_the_wire(matches);

    std::vector<ReflectorDetection> matched;
    std::vector<ReflectorMatch> solver_matches;
    matches_from_message(matches, matched, solver_matches);
    pose2d_t laser_pose{};
    const SolverOutput& solved =
        solver_.on_message(matches.utime, matches.scan_counter, match_verdict_from_message(matches.status),
                           matched, solver_matches, matches.utime);
    EXPECT_TRUE(solved.accepted) << (solved.events.empty() ? "" : solved.events[0].log);
    if (solved.accepted) to_message(*solved.fix, laser_pose);
    return over_the_wire(laser_pose);
  }

 private:
  ExtractorNode extractor_;
  MatcherNode matcher_;
  SolverNode solver_;
};

TEST(EvalPipelineEquivalence,
     RenderedDriveThroughTheServiceNodesAndThroughThePipelineGivesIdenticalLaserPose) {
  const sim::World world = sim::load_world(kConfig + "/world_demo.json");
  const ReflectorMap map = load_reflector_map(world.map_file);
  const Pose2 robot_T_laser = load_robot_config(kConfig + "/robot.json").robot_T_laser;
  const PipelineConfigs configs = load_deployed_pipeline_configs(kConfig);
  ServiceChain services(configs, map, robot_T_laser);
  LocalizationPipeline pipeline(PipelineMode::kDefault, configs, map, robot_T_laser);

  // 4 s along a curve: 100 Hz ODOMETRY and POSE (the truth, 1 cm / 0.5 deg), 50 Hz scans.
  const BodyTwist twist{0.6, 0.1, 0.15};
  const Pose2 start{4.0, 2.0, 0.0};
  const auto truth_at = [&](int64_t t_us) {
    return start * se2_exp(twist, 1e-6 * static_cast<double>(t_us));
  };
  sim::ScanRenderer renderer{sim::ScanRenderConfig{}};
  std::mt19937_64 rng(5);
  const int64_t t0 = 1'700'000'000'000'000;
  size_t compared = 0, identical = 0, with_pose = 0;
  for (int64_t t = 0; t <= 4'000'000; t += 10'000) {
    odometry_t odo{};
    odo.utime = t0 + t;
    odo.vx = twist.vx;
    odo.vy = twist.vy;
    odo.wz = twist.wz;
    services.on_odometry(odo);
    pipeline.on_odometry(odometry_twist_from_message(over_the_wire(odo)));
    pose2d_t pose{};
    pose.utime = t0 + t;
    const Pose2 p = truth_at(t);
    pose.x = p.x, pose.y = p.y, pose.theta = p.theta;
    pose.covariance[0] = pose.covariance[4] = 1e-4;
    pose.covariance[8] = std::pow(0.5 * M_PI / 180.0, 2);
    pose.status = pose2d_t::STATUS_OK;
    services.on_pose(pose);
    pipeline.on_pose(fused_pose_from_message(over_the_wire(pose)));
    if (t % 20'000 != 0) continue;
    LaserScan rendered;
    renderer.render(
        world, [&](int64_t u) { return truth_at(u - t0) * robot_T_laser; }, t0 + t, rng, rendered);
    // The scan as lms100_driver publishes it (laser_scan_t keeps angles and times as float):
    // both chains start from LMS100_SCAN.
    const laser_scan_t published = to_lcm(rendered);
    LaserScan scan;
    ASSERT_TRUE(from_lcm(over_the_wire(published), scan));
    const pose2d_t via_services = services.on_scan(published);
    pose2d_t via_pipeline{};
    to_message(*pipeline.on_scan(scan).fix, via_pipeline);
    ++compared;
    if (via_services.status == pose2d_t::STATUS_OK || via_services.status == pose2d_t::STATUS_DEGRADED)
      ++with_pose;
    const auto d = differing_fields(via_services, via_pipeline);
    if (d.empty()) {
      ++identical;
    } else {
      std::string fields;
      for (const auto& f : d) fields += " " + f;
      ADD_FAILURE() << "scan at t = " << t << " us differs in:" << fields;
    }
  }
  std::printf("rendered drive: %zu of %zu LASER_POSE identical in every field (%zu with a pose)\n", identical,
              compared, with_pose);
  EXPECT_EQ(compared, 201u);
  EXPECT_EQ(identical, compared);
  EXPECT_GE(with_pose, compared / 2);  // the comparison covers fixes, not only their absence
}

TEST(EvalPipelineEquivalence, RecordedLogInLogOrderThroughThePipelineReproducesTheRecordedLaserPose) {
  PipelineConfigs configs = load_deployed_pipeline_configs(kConfig);
  // The sample was recorded before the range-bias model (issue 12): b held at 0 with no sigma,
  // as it was. Re-recording the sample drops this.
  configs.solver.solver.range_bias.estimate = false;
  configs.solver.solver.range_bias.prior_sigma = 0.0;
  // Nor had the extractor its beam-spot model or the matcher its fit consistency test (issue 14).
  configs.extractor.extractor.fit.spot.enabled = false;
  configs.matcher.matcher.relocalization.fit_consistency_sigmas = 0.0;
  const ReflectorMap map = load_reflector_map(configs.matcher.map_file);
  const Pose2 robot_T_laser = load_robot_config(kConfig + "/robot.json").robot_T_laser;
  LocalizationPipeline pipeline(PipelineMode::kDefault, configs, map, robot_T_laser);

  std::map<int64_t, pose2d_t> recorded, replayed;
  std::vector<int64_t> scan_order;
  test::RecordedLogReader reader;
  reader.on<laser_scan_t>("LMS100_SCAN", [&](const laser_scan_t& m) {
    LaserScan scan;
    ASSERT_TRUE(from_lcm(m, scan));
    pose2d_t p{};
    to_message(*pipeline.on_scan(scan).fix, p);
    replayed[p.utime] = p;
    scan_order.push_back(p.utime);
  });
  reader.on<odometry_t>("ODOMETRY",
                        [&](const odometry_t& m) { pipeline.on_odometry(odometry_twist_from_message(m)); });
  reader.on<pose2d_t>("POSE", [&](const pose2d_t& m) { pipeline.on_pose(fused_pose_from_message(m)); });
  reader.on<pose2d_t>("LASER_POSE", [&](const pose2d_t& m) { recorded[m.utime] = m; });
  ASSERT_TRUE(reader.read(std::string(REFLOC_SOURCE_DIR) + "/logs/samples/replay_demo_4s.lcm"));
  ASSERT_EQ(reader.undecodable(), 0);
  constexpr size_t kColdStartScans = 60;  // 1.2 s at 50 Hz, as in replay_integration
  size_t compared = 0, identical = 0, same_status = 0, first_ok = scan_order.size(), identical_all = 0;
  double worst_xy = 0.0, worst_theta = 0.0;
  for (size_t i = 0; i < scan_order.size(); ++i) {
    const pose2d_t& mine = replayed[scan_order[i]];
    if (mine.status == pose2d_t::STATUS_OK) first_ok = std::min(first_ok, i);
    const auto it = recorded.find(scan_order[i]);
    if (it != recorded.end()) {
      const auto d = differing_fields(mine, it->second);
      if (d.empty()) {
        ++identical_all;
      } else {
        std::string fields;
        for (const auto& f : d) fields += " " + f;
        std::printf("scan %zu: status recorded %d, pipeline %d; differs in:%s\n", i, it->second.status,
                    mine.status, fields.c_str());
      }
    }
    if (i < kColdStartScans || it == recorded.end()) continue;
    ++compared;
    if (differing_fields(mine, it->second).empty()) ++identical;
    if (mine.status != it->second.status) {
      std::printf("scan %zu: recorded status %d, pipeline %d\n", i, it->second.status, mine.status);
      continue;
    }
    ++same_status;
    if (mine.status != pose2d_t::STATUS_OK && mine.status != pose2d_t::STATUS_DEGRADED) continue;
    worst_xy = std::max(worst_xy, std::hypot(mine.x - it->second.x, mine.y - it->second.y));
    worst_theta = std::max(worst_theta, std::abs(std::remainder(mine.theta - it->second.theta, 2 * M_PI)));
  }
  std::printf(
      "log replay: %zu scans, %zu recorded LASER_POSE, first OK at scan %zu; after the cold start %zu "
      "compared, "
      "%zu same status, %zu identical in every field (%zu of all), worst %.6f mm %.6f deg\n",
      scan_order.size(), recorded.size(), first_ok, compared, same_status, identical, identical_all,
      1000 * worst_xy, worst_theta * 180 / M_PI);
  EXPECT_LE(first_ok, kColdStartScans);
  EXPECT_GE(compared, (recorded.size() - kColdStartScans) * 95 / 100);
  EXPECT_GE(same_status, compared * 98 / 100);
  EXPECT_LT(worst_xy, 0.001);
  EXPECT_LT(worst_theta, 0.05 * M_PI / 180.0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
