#include "pose_solver/solver_node.hpp"

namespace refloc {

const LaserFix& SolverNode::on_matches(int64_t utime, MatchVerdict verdict,
                                       const std::vector<ReflectorDetection>& detections,
                                       const std::vector<ReflectorMatch>& matches) {
  if (verdict == MatchVerdict::kOk) solver_.solve(detections, matches, solution_);
  fix_ = make_laser_fix(utime, verdict, solution_, static_cast<int>(matches.size()));
  return fix_;
}

const LaserFix& SolverNode::on_scan_matches(int64_t utime, MatchVerdict verdict,
                                            const std::vector<ReflectorDetection>& scan_detections,
                                            const std::vector<ReflectorMatch>& scan_matches) {
  matched_detections_.clear();
  matches_.clear();
  for (const ReflectorMatch& m : scan_matches) {
    matches_.push_back(
        {static_cast<int>(matched_detections_.size()), m.map_id, m.map_p_center, m.map_radius});
    matched_detections_.push_back(scan_detections[static_cast<size_t>(m.detection_index)]);
  }
  return on_matches(utime, verdict, matched_detections_, matches_);
}

}  // namespace refloc
