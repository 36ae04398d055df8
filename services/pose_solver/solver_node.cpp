#include "pose_solver/solver_node.hpp"

namespace refloc {

const LaserFix& SolverNode::on_matches(int64_t utime, MatchVerdict verdict,
                                       const std::vector<ReflectorDetection>& detections,
                                       const std::vector<ReflectorMatch>& matches) {
  if (verdict == MatchVerdict::kOk) solver_.solve(detections, matches, solution_);
  fix_ = make_laser_fix(utime, verdict, solution_, static_cast<int>(matches.size()));
  return fix_;
}

}  // namespace refloc
