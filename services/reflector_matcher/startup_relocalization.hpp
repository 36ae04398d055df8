#pragma once
// A freshly started matcher does not trust the POSE prior until it has
// relocalized on its own once.
//
// Why: POSE comes from pose_fusion, which is fed by this matcher's own earlier
// output. After a restart (a crash, a watchdog kill, a deploy) nothing checks
// that chain: a wrong prior, tracked from, keeps confirming itself. The global
// relocalizer looks at the scan and the map only, costs < 0.2 ms per scan on
// ordinary maps, and in a hall it can tell apart succeeds within a few scans.
// So for the first `window` seconds of scans the matcher ignores every prior and
// relocalizes globally until one scan is OK; then it tracks as usual. A map it
// cannot disambiguate (a symmetric layout: global is never OK) would leave the
// robot without fixes forever, so after the window the prior is used again.

#include "reflector_matcher/match_result.hpp"

#include <cstdint>

namespace refloc {

class StartupRelocalization {
 public:
  /// window [s] of scans without a prior after start; 0 disables the policy.
  explicit StartupRelocalization(double window);

  /// Whether a prior may be used for the scan at scan_utime [us].
  bool prior_allowed(int64_t scan_utime);
  /// The result of that scan.
  void on_result(MatchStatus status, MatchMode mode);

  bool relocalized() const { return relocalized_; }
  /// The window passed without a global OK: the prior is used again.
  bool gave_up() const { return gave_up_; }
  bool done() const { return relocalized_ || gave_up_; }
  /// A scan matched from a user's INITIAL_POSE: as good as relocalizing on its own.
  void confirm_by_user_pose() { relocalized_ = true; }

 private:
  int64_t window_us_;
  int64_t first_scan_utime_ = -1;
  bool relocalized_ = false;
  bool gave_up_ = false;
};

}  // namespace refloc
