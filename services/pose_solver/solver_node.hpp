#pragma once
// The pose_solver service without LCM: one scan's matches (each with its detection) and
// the matcher's verdict in, the LASER_POSE fix out. main.cpp and refloc-eval both run this.

#include "pose_solver/laser_fix.hpp"
#include "pose_solver/pose_solver.hpp"

#include <vector>

namespace refloc {

class SolverNode {
 public:
  SolverNode(const SolverConfig& config, const Pose2& robot_T_laser) : solver_(config, robot_T_laser) {}

  /// matches index detections; the solver runs only when verdict is kOk.
  const LaserFix& on_matches(int64_t utime, MatchVerdict verdict,
                             const std::vector<ReflectorDetection>& detections,
                             const std::vector<ReflectorMatch>& matches);

  /// The same for a scan's detections and the matches indexing them: each match takes its
  /// detection along, as REFLECTOR_MATCHES carries them (detections 0..n-1 in match order).
  const LaserFix& on_scan_matches(int64_t utime, MatchVerdict verdict,
                                  const std::vector<ReflectorDetection>& scan_detections,
                                  const std::vector<ReflectorMatch>& scan_matches);

  const PoseSolver& solver() const { return solver_; }
  /// The last scan's solution (stale when the verdict was not kOk).
  const PoseSolution& solution() const { return solution_; }

 private:
  PoseSolver solver_;
  PoseSolution solution_;
  LaserFix fix_;
  std::vector<ReflectorDetection> matched_detections_;
  std::vector<ReflectorMatch> matches_;
};

}  // namespace refloc
