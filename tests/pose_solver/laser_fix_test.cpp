#include "pose_solver/laser_fix.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

PoseSolution solved(SolveStatus status, int used) {
  PoseSolution s;
  s.status = status;
  s.map_T_robot = {4.0, 2.0, 0.5};
  s.covariance = Eigen::Matrix3d::Identity() * 1e-6;
  s.reflectors_used = used;
  s.rms_residual = 0.004;
  return s;
}

std::map<std::string, int64_t> counters_of(const LaserFix& fix) {
  std::map<std::string, int64_t> c;
  fix.for_each_counter([&](const char* name, int64_t by) { c[name] += by; });
  return c;
}

TEST(LaserFix, MatcherOkAndSolverOkGivesThePoseWithItsCovarianceAndCountsDroppedMatches) {
  const LaserFix fix = make_laser_fix(123, MatchVerdict::kOk, solved(SolveStatus::kOk, 5), 6);
  EXPECT_EQ(fix.utime, 123);
  EXPECT_EQ(fix.status, LaserFixStatus::kOk);
  EXPECT_TRUE(fix.has_pose);
  EXPECT_TRUE(fix.ok());
  EXPECT_EQ(fix.map_T_robot.x, 4.0);
  EXPECT_EQ(fix.map_T_robot.theta, 0.5);
  EXPECT_EQ(fix.covariance(0, 0), 1e-6);
  EXPECT_EQ(fix.reflectors_used, 5);
  EXPECT_EQ(fix.residual, 0.004);
  EXPECT_EQ(counters_of(fix), (std::map<std::string, int64_t>{{"outlier_matches", 1}}));
}

TEST(LaserFix, SolverDegradedKeepsThePoseAsDegraded) {
  const LaserFix fix = make_laser_fix(1, MatchVerdict::kOk, solved(SolveStatus::kDegraded, 3), 3);
  EXPECT_EQ(fix.status, LaserFixStatus::kDegraded);
  EXPECT_TRUE(fix.has_pose);
  EXPECT_FALSE(fix.ok());
  EXPECT_STREQ(fix.degraded_detail(), "last fix DEGRADED");
  EXPECT_EQ(counters_of(fix), (std::map<std::string, int64_t>{{"degraded_fixes", 1}}));
}

TEST(LaserFix, TheMatchersDoubtWinsAmbiguousAndLostGiveNoPoseWhateverTheSolution) {
  for (MatchVerdict verdict : {MatchVerdict::kAmbiguous, MatchVerdict::kLost}) {
    const LaserFix fix = make_laser_fix(1, verdict, solved(SolveStatus::kOk, 5), 5);
    EXPECT_EQ(fix.status,
              verdict == MatchVerdict::kAmbiguous ? LaserFixStatus::kAmbiguous : LaserFixStatus::kLost);
    EXPECT_FALSE(fix.has_pose);
    EXPECT_EQ(fix.map_T_robot.x, 0.0);
    EXPECT_EQ(fix.map_T_robot.y, 0.0);
    EXPECT_EQ(fix.map_T_robot.theta, 0.0);
    EXPECT_EQ(fix.covariance, Eigen::Matrix3d(Eigen::Matrix3d::Identity() * 1e6));
    EXPECT_EQ(fix.reflectors_used, 0);
    EXPECT_EQ(fix.residual, 0.0);
    EXPECT_STREQ(fix.degraded_detail(), "no fix from the last scan");
    EXPECT_EQ(counters_of(fix).size(), 1u);
    EXPECT_EQ(counters_of(fix).count(verdict == MatchVerdict::kAmbiguous ? "ambiguous_fixes" : "lost_fixes"),
              1u);
  }
}

TEST(LaserFix, SolverLostGivesNoPoseAndTheNoInformationCovariance) {
  const LaserFix fix = make_laser_fix(1, MatchVerdict::kOk, solved(SolveStatus::kLost, 2), 4);
  EXPECT_EQ(fix.status, LaserFixStatus::kLost);
  EXPECT_FALSE(fix.has_pose);
  EXPECT_EQ(fix.covariance(2, 2), 1e6);
  EXPECT_EQ(fix.reflectors_used, 0);
  EXPECT_EQ(counters_of(fix), (std::map<std::string, int64_t>{{"lost_fixes", 1}}));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
