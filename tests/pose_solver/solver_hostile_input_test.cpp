// The solver node fed what a hostile or broken peer can publish on REFLECTOR_MATCHES:
// broken matches are rejected as a whole and counted, no non-finite LASER_POSE and no OK
// from them, and good input afterwards is solved as before.

#include "pose_solver/solver_node.hpp"

#include "solver_scenario.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 1'700'000'000'000'000;
constexpr int64_t kPeriod = 20'000;
constexpr int64_t kLatency = 3'000;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

class SolverHostileInput : public ::testing::Test {
 protected:
  SolverHostileInput() : node_(SolverConfig{}, testing::corner_mount()) {
    std::mt19937 rng(3);
    const auto scan =
        testing::render_detections(map_, truth_ * testing::corner_mount(), testing::SyntheticSensor{}, rng);
    detections_ = scan.detections;
    matches_ = testing::true_matches(scan, map_);
  }

  const SolverOutput& send(const std::vector<ReflectorDetection>& detections,
                           const std::vector<ReflectorMatch>& matches, int64_t utime, int64_t counter,
                           int64_t host_utime) {
    const SolverOutput& out =
        node_.on_message(utime, counter, MatchVerdict::kOk, detections, matches, host_utime);
    for (const NodeEvent& e : out.events)
      if (e.counter != nullptr) ++counters_[e.counter];
    out.for_each_counter([&](const char* name, int64_t by) { counters_[name] += by; });
    if (out.accepted) expect_finite(*out.fix);
    return out;
  }
  const SolverOutput& good() {
    ++k_;
    return send(detections_, matches_, kT0 + k_ * kPeriod, k_, kT0 + k_ * kPeriod + kLatency);
  }
  void expect_good_fix() {
    const SolverOutput& out = good();
    ASSERT_TRUE(out.accepted);
    ASSERT_TRUE(out.ok());
    EXPECT_NEAR(out.fix->map_T_robot.x, truth_.x, 0.05);
    EXPECT_NEAR(out.fix->map_T_robot.y, truth_.y, 0.05);
  }
  static void expect_finite(const LaserFix& fix) {
    EXPECT_TRUE(std::isfinite(fix.map_T_robot.x) && std::isfinite(fix.map_T_robot.y) &&
                std::isfinite(fix.map_T_robot.theta) && std::isfinite(fix.residual));
    EXPECT_TRUE(fix.covariance.allFinite());
  }

  ReflectorMap map_ = testing::hall_map();
  Pose2 truth_{7.0, 5.0, 0.4};
  std::vector<ReflectorDetection> detections_;
  std::vector<ReflectorMatch> matches_;
  SolverNode node_;
  int64_t k_ = 0;
  std::map<std::string, int64_t> counters_;
};

TEST_F(SolverHostileInput, BrokenDetectionsOrMapPositionsAreRejectedAndTheNextScanIsSolved) {
  for (int i = 0; i < 3; ++i) expect_good_fix();
  using Spoil = std::function<void(std::vector<ReflectorDetection>&, std::vector<ReflectorMatch>&)>;
  const std::vector<std::pair<Spoil, std::string>> hostile = {
      {[](auto& d, auto&) { d[0].laser_p_center.x() = kNan; }, "nonfinite"},
      {[](auto& d, auto&) { d[1].covariance(0, 0) = kInf; }, "nonfinite"},
      {[](auto& d, auto&) { d[2].range = kNan; }, "nonfinite"},
      {[](auto&, auto& m) { m[0].map_p_center.x() = kNan; }, "nonfinite"},
      {[](auto&, auto& m) { m[1].map_radius = kInf; }, "nonfinite"},
      {[](auto& d, auto&) { d[0].laser_p_center.y() = 1e300; }, "out_of_bounds"},
      {[](auto&, auto& m) { m[0].map_p_center.y() = 1e300; }, "out_of_bounds"},
      {[](auto&, auto& m) { m[0].map_radius = 0.0; }, "out_of_bounds"},
      {[](auto&, auto& m) { m[0].detection_index = 99; }, "out_of_bounds"},
      {[](auto& d, auto&) { d[0].covariance << 1.0, 2.0, 2.0, 1.0; }, "covariance"},
      {[](auto& d, auto&) { d[0].covariance *= 1e12; }, "covariance"},
  };
  std::map<std::string, int64_t> expected;
  for (const auto& [spoil, reason] : hostile) {
    auto d = detections_;
    auto m = matches_;
    spoil(d, m);
    const int64_t utime = kT0 + k_ * kPeriod + kPeriod / 2;
    const SolverOutput& out = send(d, m, utime, 40'000, utime + kLatency);
    EXPECT_FALSE(out.accepted) << reason;
    EXPECT_TRUE(out.ok());  // the last fix's state: an isolated rejection is only counted
    ++expected["rejected_matches_" + reason];
    expect_good_fix();
  }
  for (const auto& [name, n] : expected) EXPECT_EQ(counters_[name], n) << name;
  EXPECT_EQ(counters_["gap_matches_messages"], 0);
}

TEST_F(SolverHostileInput, BadStampsAreRejectedAndMissingScanCountersCounted) {
  for (int i = 0; i < 3; ++i) expect_good_fix();
  const int64_t hour = 3'600'000'000;
  for (int64_t stamp : {kT0 + hour, std::numeric_limits<int64_t>::max(), int64_t{0}, kT0 - hour}) {
    EXPECT_FALSE(send(detections_, matches_, stamp, k_ + 1, kT0 + k_ * kPeriod + kPeriod / 2).accepted);
    expect_good_fix();
  }
  EXPECT_EQ(counters_["rejected_matches_stamp_ahead"], 2);
  EXPECT_EQ(counters_["rejected_matches_stamp_behind"], 2);
  k_ += 2;
  expect_good_fix();
  EXPECT_EQ(counters_["gap_matches_messages"], 2);
}

TEST_F(SolverHostileInput, OnlyRejectedMatchesForOverASecondDegradeWithTheReason) {
  expect_good_fix();
  auto d = detections_;
  d[0].laser_p_center.x() = kNan;
  const SolverOutput* out = nullptr;
  for (int i = 1; i <= 60; ++i) {
    const int64_t utime = kT0 + (k_ + i) * kPeriod;
    out = &send(d, matches_, utime, k_ + i, utime + kLatency);
  }
  EXPECT_FALSE(out->ok());
  EXPECT_NE(std::string(out->degraded_detail()).find("no usable matches"), std::string::npos);
}

TEST(LaserFixCheck, ANonFiniteOrUnusableSolutionIsLostAndCountedNeverOk) {
  const std::vector<std::function<void(PoseSolution&)>> spoil = {
      [](PoseSolution& s) { s.map_T_robot.x = kNan; },
      [](PoseSolution& s) { s.map_T_robot.theta = kInf; },
      [](PoseSolution& s) { s.rms_residual = kNan; },
      [](PoseSolution& s) { s.covariance(2, 2) = kNan; },
      [](PoseSolution& s) { s.covariance = -Eigen::Matrix3d::Identity(); },
      [](PoseSolution& s) { s.covariance = Eigen::Matrix3d::Identity() * 1e300; },
  };
  for (const auto& f : spoil) {
    PoseSolution solution;
    solution.status = SolveStatus::kOk;
    solution.map_T_robot = {1.0, 2.0, 0.3};
    solution.covariance = Eigen::Matrix3d::Identity() * 1e-4;
    solution.reflectors_used = 4;
    f(solution);
    const LaserFix fix = make_laser_fix(7, MatchVerdict::kOk, solution, 4);
    EXPECT_EQ(fix.status, LaserFixStatus::kLost);
    EXPECT_FALSE(fix.has_pose);
    EXPECT_FALSE(fix.ok());
    EXPECT_TRUE(fix.unusable_solution);
    EXPECT_TRUE(fix.covariance.allFinite());
    EXPECT_TRUE(std::isfinite(fix.map_T_robot.x) && std::isfinite(fix.map_T_robot.theta));
    int64_t unusable = 0;
    fix.for_each_counter([&](const char* name, int64_t by) {
      if (std::string(name) == "unusable_solutions") unusable += by;
    });
    EXPECT_EQ(unusable, 1);
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
