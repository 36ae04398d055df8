#pragma once
// When refloc-status prints: with --once a single time, --wait seconds after the start;
// live, every second, catching up after a stall without printing in a burst.

namespace refloc {

class RefreshSchedule {
 public:
  /// start_s: monotonic start [s]; wait_s: the --once listening time [s].
  RefreshSchedule(double start_s, bool once, double wait_s);

  /// True when a refresh is due at now_s [s]; then the next one is scheduled.
  bool due(double now_s);
  /// Time until the next refresh [s], at least 0.
  double seconds_until_due(double now_s) const;
  /// --once and printed.
  bool done() const { return done_; }

 private:
  bool once_;
  double next_s_;
  bool done_ = false;
};

}  // namespace refloc
