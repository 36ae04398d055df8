#pragma once
// The pose_solver service without LCM: one scan's matches (each with its detection) and
// the matcher's verdict in, the LASER_POSE fix out. main.cpp and refloc-eval both run this.
// On the service's path (on_message) every REFLECTOR_MATCHES is judged first (its
// detections and map positions, then its stamp and scan counter:
// common/input_stream_checks.hpp); a rejected one changes nothing and is not answered.

#include "common/input_stream_checks.hpp"
#include "common/node_event.hpp"
#include "pose_solver/laser_fix.hpp"
#include "pose_solver/pose_solver.hpp"
#include "pose_solver/range_bias_filter.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace refloc {

/// What one REFLECTOR_MATCHES did.
struct SolverOutput {
  /// false: rejected (events say why): nothing to publish.
  bool accepted = false;
  std::vector<NodeEvent> events;  ///< rejection, clock re-anchor, counter reset, gap
  int64_t missing_scans = 0;      ///< scan counters missing before this message
  /// Matches come but none was usable for over a second: DEGRADED with starved_detail.
  bool starved = false;
  std::string starved_detail;
  const LaserFix* fix = nullptr;  ///< the last accepted message's fix; null before any
  double range_bias = 0.0;        ///< [m] the estimate kept across scans (RangeBiasFilter)
  double range_bias_sigma = 0.0;  ///< [m] its sigma at the last scan

  template <class Bump>
  void for_each_counter(Bump&& bump) const {
    if (!accepted) return;  // a rejected message's counters are in events
    bump("gap_matches_messages", missing_scans);
    fix->for_each_counter(bump);
  }
  /// Calls set(name, value) for each heartbeat counter that holds a value rather than a count.
  template <class Set>
  void for_each_gauge(Set&& set) const {
    set("range_bias_um", static_cast<int64_t>(std::llround(1e6 * range_bias)));
    set("range_bias_sigma_um", static_cast<int64_t>(std::llround(1e6 * range_bias_sigma)));
  }
  /// The heartbeat detail of an OK state: why the range bias was not estimated, or empty.
  const char* ok_detail() const { return fix != nullptr ? fix->range_bias_detail() : ""; }
  /// The heartbeat state after this message: OK, else DEGRADED with this detail.
  bool ok() const { return !starved && fix != nullptr && fix->ok(); }
  const char* degraded_detail() const {
    if (starved) return starved_detail.c_str();
    return fix != nullptr ? fix->degraded_detail() : "no usable REFLECTOR_MATCHES yet";
  }
};

class SolverNode {
 public:
  SolverNode(const SolverConfig& config, const Pose2& robot_T_laser)
      : solver_(config, robot_T_laser), range_bias_(config.range_bias) {}

  /// One REFLECTOR_MATCHES as the service gets it: the scan's utime and scan counter, the
  /// verdict, its matches as detections 0..n-1 (matches_from_message), at host wall-clock
  /// time host_utime [us]. The reference stays valid until the next call.
  const SolverOutput& on_message(int64_t utime, int64_t scan_counter, MatchVerdict verdict,
                                 const std::vector<ReflectorDetection>& detections,
                                 const std::vector<ReflectorMatch>& matches, int64_t host_utime);

  /// matches index detections; the solver runs only when verdict is kOk. Offline, unchecked:
  /// for callers whose input is the chain's own (refloc-eval).
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
  /// The range offset kept across scans: each OK fix that estimated it updates it.
  const RangeBiasFilter& range_bias() const { return range_bias_; }

 private:
  PoseSolver solver_;
  PoseSolution solution_;
  RangeBiasFilter range_bias_;
  LaserFix fix_;
  std::vector<ReflectorDetection> matched_detections_;
  std::vector<ReflectorMatch> matches_;
  InputStreamChecks match_checks_{"matches", chain_stream_stamp_limits()};
  SolverOutput output_;
};

}  // namespace refloc
