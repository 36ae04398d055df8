#include "pose_solver/solver_node.hpp"

#include "common/input_sanity.hpp"
#include "common/reflector_detection_check.hpp"

#include <fmt/format.h>

namespace refloc {

const SolverOutput& SolverNode::on_message(int64_t utime, int64_t scan_counter, MatchVerdict verdict,
                                           const std::vector<ReflectorDetection>& detections,
                                           const std::vector<ReflectorMatch>& matches, int64_t host_utime) {
  output_.events.clear();
  output_.accepted = false;
  output_.missing_scans = 0;
  output_.starved = false;
  if (const InputFault fault = check_matches(detections, matches)) {
    output_.events.push_back(match_checks_.rejected(fault.reason, fault.detail, host_utime));
  } else if (match_checks_.stamp_accepted(utime, host_utime, output_.events)) {
    match_checks_.accepted(host_utime);
    output_.accepted = true;
  }
  if (!output_.accepted) {
    output_.starved = match_checks_.starved(host_utime);
    if (output_.starved) output_.starved_detail = match_checks_.starved_detail(host_utime);
    return output_;
  }
  output_.missing_scans = match_checks_.missing_before(scan_counter, utime, output_.events);
  output_.fix = &on_matches(utime, verdict, detections, matches);
  output_.range_bias = range_bias_.mean();
  output_.range_bias_sigma = range_bias_.sigma();
  return output_;
}

const LaserFix& SolverNode::on_matches(int64_t utime, MatchVerdict verdict,
                                       const std::vector<ReflectorDetection>& detections,
                                       const std::vector<ReflectorMatch>& matches) {
  if (verdict == MatchVerdict::kOk) {
    solver_.set_range_bias_prior(range_bias_.prior_at(utime));
    solver_.solve(detections, matches, solution_);
    // Only an OK fix teaches b: a DEGRADED one may hold an outlier or a bad residual b would absorb.
    if (solution_.status == SolveStatus::kOk && solution_.range_bias_use == RangeBiasUse::kEstimated)
      range_bias_.update(solution_.range_bias, solution_.range_bias_sigma);
  }
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
