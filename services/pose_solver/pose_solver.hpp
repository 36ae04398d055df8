#pragma once
// The solver pipeline: matched detections in, map_T_robot with covariance out.
// Paper mode is §3.6 (eq. 4-8); the default mode starts from the same linear
// position with a circular-mean heading and refines (x, y, theta) jointly,
// dropping the worst match while its normalised residual is too large.

#include "pose_solver/point_observation.hpp"
#include "pose_solver/pose_solution.hpp"
#include "pose_solver/range_bias_refinement.hpp"
#include "pose_solver/solver_config.hpp"

#include "common/reflector_detection.hpp"
#include "common/se2.hpp"

#include <vector>

namespace refloc {

class PoseSolver {
 public:
  /// robot_T_laser: the laser mount on the robot.
  PoseSolver(const SolverConfig& config, const Pose2& robot_T_laser);

  /// Solve one scan; solution is overwritten (its vector reused). solution.used is per match.
  void solve(const std::vector<ReflectorDetection>& detections, const std::vector<ReflectorMatch>& matches,
             PoseSolution& solution);

  /// The range offset's prior for the next solves (default: the config's, RangeBiasFilter's
  /// per scan in SolverNode).
  void set_range_bias_prior(const RangeBiasPrior& prior) { range_bias_prior_ = prior; }
  const RangeBiasPrior& range_bias_prior() const { return range_bias_prior_; }

  const SolverConfig& config() const { return config_; }
  const Pose2& robot_T_laser() const { return robot_T_laser_; }

 private:
  void solve_paper(PoseSolution& solution);
  void solve_default(PoseSolution& solution);
  bool solve_biased(Pose2 estimate, PoseSolution& solution);
  void finish(PoseSolution& solution) const;

  SolverConfig config_;
  Pose2 robot_T_laser_;
  RangeBiasPrior range_bias_prior_;
  std::vector<PointObservation> observations_;
  std::vector<PointObservation> corrected_;  ///< observations_ with the scan's b taken off
  std::vector<int> observation_match_;       ///< index into matches of each observation
  std::vector<char> use_;
};

}  // namespace refloc
