// The localization chain on realistic scans: the LMS100 emulator's renderer
// (walls, racks, tape and metal distractors, mixed pixels, sensor noise) in the
// demo hall -> ReflectorExtractor -> ReflectorMatcher without a prior ->
// PoseSolver. No wrong OK, and the pose within a few centimetres.

#include "pose_solver/pose_solver.hpp"
#include "reflector_extractor/extractor.hpp"
#include "reflector_matcher/reflector_matcher.hpp"
#include "world_renderer/scan_renderer.hpp"
#include "world_renderer/world_loader.hpp"

#include "common/reflector_map.hpp"
#include "common/robot_config.hpp"

#include <gtest/gtest.h>

#include <array>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

struct Tally {
  int poses = 0, match_ok = 0, wrong_ok = 0, solved_ok = 0;
  double rms = 0.0, max_err = 0.0;
};

Tally run_pipeline(const std::string& world_file, int poses, unsigned seed) {
  const std::string dir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config";
  const sim::World world = sim::load_world(dir + "/" + world_file);
  const ReflectorMap map = load_reflector_map(world.map_file);
  const Pose2 robot_T_laser = load_robot_config(dir + "/robot.json").robot_T_laser;
  ReflectorExtractor extractor;
  ReflectorMatcher matcher(map, MatcherConfig{});
  PoseSolver solver(SolverConfig{}, robot_T_laser);
  sim::ScanRenderer renderer;
  std::mt19937_64 rng(seed);
  Eigen::Vector2d lo = map.reflectors.front().map_p_center, hi = lo;
  for (const auto& r : map.reflectors) {
    lo = lo.cwiseMin(r.map_p_center);
    hi = hi.cwiseMax(r.map_p_center);
  }
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y()), ua(-M_PI, M_PI);
  LaserScan scan;
  MatchResult match;
  PoseSolution solution;
  Tally t;
  double err2 = 0.0;
  int solved = 0;
  while (t.poses < poses) {
    const Pose2 truth{ux(rng), uy(rng), ua(rng)};
    if (!world.drivable_areas.empty() && !world.is_drivable(truth.translation())) continue;
    ++t.poses;
    renderer.render(world, truth * robot_T_laser, 1'000'000 + t.poses * 20'000, rng, scan);
    const std::vector<ReflectorDetection> detections = extractor.extract(scan);
    matcher.match(detections, nullptr, match);
    if (match.status != MatchStatus::kOk) continue;
    ++t.match_ok;
    if (!approx_equal(match.map_T_laser, truth * robot_T_laser, 0.2, 5.0 * M_PI / 180.0)) {
      ++t.wrong_ok;
      continue;
    }
    solver.solve(detections, match.matches, solution);
    if (solution.status == SolveStatus::kLost) continue;
    t.solved_ok += solution.status == SolveStatus::kOk;
    const double e = std::hypot(solution.map_T_robot.x - truth.x, solution.map_T_robot.y - truth.y);
    err2 += e * e;
    ++solved;
    t.max_err = std::max(t.max_err, e);
  }
  t.rms = solved > 0 ? std::sqrt(err2 / solved) : 0.0;
  std::printf("%s: %d poses, matcher OK %d (wrong %d), solver OK %d, RMS %.1f mm, max %.1f mm\n",
              world_file.c_str(), t.poses, t.match_ok, t.wrong_ok, t.solved_ok, 1e3 * t.rms, 1e3 * t.max_err);
  return t;
}

TEST(RenderedScanPipeline, DemoHallRelocalizesWithoutWrongOkAndSolvesWithinCentimetres) {
  const Tally t = run_pipeline("world_demo.json", 1000, 70);
  EXPECT_EQ(t.wrong_ok, 0);
  EXPECT_GE(t.match_ok, t.poses * 85 / 100);
  EXPECT_LT(t.rms, 0.015);
}

TEST(RenderedScanPipeline, SymmetricWorldIsNeverWrongOk) {
  const Tally t = run_pipeline("world_symmetric.json", 500, 71);
  EXPECT_EQ(t.wrong_ok, 0);
}

/// Scans rendered in the demo hall from random drivable poses, extracted as the service does.
struct DemoHallScenes {
  explicit DemoHallScenes(unsigned seed)
      : world(sim::load_world(config_dir() + "/world_demo.json")),
        map(load_reflector_map(world.map_file)),
        robot_T_laser(load_robot_config(config_dir() + "/robot.json").robot_T_laser),
        rng(seed) {}
  /// The next random robot pose in the drivable area, as map_T_laser.
  Pose2 next_laser_pose() {
    while (true) {
      const Pose2 truth{ux(rng), uy(rng), ua(rng)};
      if (world.drivable_areas.empty() || world.is_drivable(truth.translation()))
        return truth * robot_T_laser;
    }
  }
  std::vector<ReflectorDetection> detections(const Pose2& map_T_laser, int64_t utime) {
    renderer.render(world, map_T_laser, utime, rng, scan);
    return extractor.extract(scan);
  }

  static std::string config_dir() { return std::string(REFLOC_SOURCE_DIR) + "/deploy/config"; }

  const sim::World world;
  const ReflectorMap map;
  const Pose2 robot_T_laser;
  ReflectorExtractor extractor;
  sim::ScanRenderer renderer;
  std::mt19937_64 rng;
  std::uniform_real_distribution<double> ux{0.5, 19.5}, uy{0.5, 11.5}, ua{-M_PI, M_PI};
  LaserScan scan;
};

/// Wrong OK matches in the demo hall when tracking starts from a confident prior offset metres
/// off the truth (a kidnapped robot, an odometry jump), with and without the global check; a
/// pose counts as OK (or wrong) when either of its two scans is.
struct WrongPriorTally {
  int scans = 0, ok_checked = 0, wrong_checked = 0, ok_trusting = 0, wrong_trusting = 0;
};

WrongPriorTally run_wrong_prior(double offset, int poses, unsigned seed) {
  DemoHallScenes hall(seed);
  MatcherConfig trusting_config;
  trusting_config.tracking.max_unexplained = 1000;
  trusting_config.tracking.min_score = -1000.0;
  ReflectorMatcher checked(hall.map, MatcherConfig{}), trusting(hall.map, trusting_config);
  MatchResult match;
  WrongPriorTally t;
  while (t.scans < poses) {
    const Pose2 map_T_laser = hall.next_laser_pose();
    ++t.scans;
    const double dir = hall.ua(hall.rng);
    PosePrior prior;
    prior.map_T_laser = Pose2{map_T_laser.x + offset * std::cos(dir), map_T_laser.y + offset * std::sin(dir),
                              map_T_laser.theta};
    prior.covariance = Eigen::Vector3d(0.02 * 0.02, 0.02 * 0.02, 0.01 * 0.01).asDiagonal();
    // Two scans of the standing robot with the prior unchanged (no fix has moved POSE yet): an
    // overrule of the prior on three pairs is a fix only when the second scan repeats it.
    std::array<std::vector<ReflectorDetection>, 2> detections;
    for (int k = 0; k < 2; ++k)
      detections[static_cast<size_t>(k)] =
          hall.detections(map_T_laser, 1'000'000 + (2 * t.scans + k) * 20'000);
    for (ReflectorMatcher* m : {&checked, &trusting}) {
      bool ok = false, wrong = false;
      for (const std::vector<ReflectorDetection>& d : detections) {
        m->match(d, &prior, match);
        if (match.status != MatchStatus::kOk) continue;
        ok = true;
        wrong = wrong || !approx_equal(match.map_T_laser, map_T_laser, 0.2, 5.0 * M_PI / 180.0);
      }
      (m == &checked ? t.ok_checked : t.ok_trusting) += ok;
      (m == &checked ? t.wrong_checked : t.wrong_trusting) += wrong;
    }
  }
  std::printf("prior %.1f m off, %d scans: checked OK %d (wrong %d), trusting OK %d (wrong %d)\n", offset,
              t.scans, t.ok_checked, t.wrong_checked, t.ok_trusting, t.wrong_trusting);
  return t;
}

TEST(RenderedScanPipeline, APriorMetresOffIsOverruledByTheMapNeverConfirmed) {
  const WrongPriorTally t = run_wrong_prior(2.0, 2000, 7);
  EXPECT_EQ(t.wrong_checked, 0);
  EXPECT_GE(t.ok_checked, t.scans * 80 / 100);
  // The same scans without the check: tracking alone used to confirm some wrong priors; the
  // verifier's fit consistency test (issue 14) now refuses the inconsistent pairs a wrong prior
  // lines up, so it confirms none either.
  EXPECT_EQ(t.wrong_trusting, 0);
}

/// A user's INITIAL_POSE dropped on the robot: the true pose with the console's wide covariance
/// (0.2 m, 5 deg). Counts the scans the matcher confirms from it (OK, tracking) and the wrong OK.
struct UserPoseTally {
  int scans = 0, confirmed = 0, ok_global = 0, ambiguous = 0, wrong = 0;
};

UserPoseTally run_user_pose(int poses, unsigned seed) {
  DemoHallScenes hall(seed);
  MatchResult match;
  UserPoseTally t;
  while (t.scans < poses) {
    const Pose2 map_T_laser = hall.next_laser_pose();
    ++t.scans;
    // A fresh matcher per pose: the user's pose is the first prior it sees.
    ReflectorMatcher matcher(hall.map, MatcherConfig{});
    PosePrior prior;
    prior.map_T_laser = map_T_laser;
    const double sigma_theta = 5.0 * M_PI / 180.0;
    prior.covariance = Eigen::Vector3d(0.2 * 0.2, 0.2 * 0.2, sigma_theta * sigma_theta).asDiagonal();
    matcher.match(hall.detections(map_T_laser, 1'000'000 + t.scans * 20'000), &prior, match);
    if (match.status == MatchStatus::kAmbiguous) ++t.ambiguous;
    if (match.status != MatchStatus::kOk) continue;
    (match.mode == MatchMode::kTracking ? t.confirmed : t.ok_global) += 1;
    t.wrong += !approx_equal(match.map_T_laser, map_T_laser, 0.2, 5.0 * M_PI / 180.0);
  }
  std::printf(
      "user pose on the robot, %d scans: confirmed (OK tracking) %d, OK global %d, ambiguous %d, "
      "wrong %d\n",
      t.scans, t.confirmed, t.ok_global, t.ambiguous, t.wrong);
  return t;
}

TEST(RenderedScanPipeline, AUserPoseOnTheRobotIsConfirmed) {
  const UserPoseTally t = run_user_pose(500, 11);
  EXPECT_EQ(t.wrong, 0);
  EXPECT_EQ(t.ambiguous, 0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
