#pragma once
// Clock sanity for one input stream: is this message's stamp believable?
//
// A stamp is judged against the host's wall clock through the stream's learned
// offset (host time minus stamp: the stream's latency plus any clock difference
// between its publisher's host and ours), not against the host clock directly,
// because a log replayed with lcm-logplayer carries the stamps of the day it was
// recorded and must still work. The offset is learned from the first message and
// then follows the stream by at most kAnchorStep_us per message, so a peer that
// sends stamps slightly ahead cannot drag it far.
//
// A stamp more than max_ahead_us newer than the offset predicts, or more than
// max_behind_us older, or not newer than the last accepted stamp, is rejected.
// One bad stamp therefore neither stalls the stream (later good stamps are still
// accepted) nor resets or bypasses anything downstream. A real clock step (an
// NTP correction on the publisher's host, a replay started over) shows as every
// message being rejected at one consistent new offset: after reanchor_after such
// messages spanning at least reanchor_span_us of host time with no accepted one
// between, the guard believes the step, re-anchors and says so (kReanchored).
// A burst of forged stamps sent within a moment cannot do that.

#include <cstdint>

namespace refloc {

struct StampGuardLimits {
  int64_t max_ahead_us = 100'000;      ///< [us] a stamp this much newer than expected is rejected
  int64_t max_behind_us = 5'000'000;   ///< [us] this much older (a stale message) is rejected
  int reanchor_after = 10;             ///< consecutive rejections agreeing on one new offset
  int64_t reanchor_span_us = 500'000;  ///< [us] host time those rejections must span at least
  bool require_increasing = true;      ///< a stamp not newer than the last accepted is rejected
};

enum class StampVerdict {
  kAccepted,
  kReanchored,     ///< accepted, after a clock step the guard now believes
  kAhead,          ///< rejected: stamped in the future
  kBehind,         ///< rejected: stamped too far in the past
  kNotIncreasing,  ///< rejected: not newer than the last accepted stamp
};

/// True for kAccepted and kReanchored.
bool stamp_accepted(StampVerdict verdict);
/// "accepted", "reanchored", "ahead", "behind", "not_increasing": for counters and logs.
const char* to_string(StampVerdict verdict);

class StampGuard {
 public:
  explicit StampGuard(StampGuardLimits limits = {});

  /// Judge one message's stamp; host_utime is the host's wall clock (now_utime()),
  /// the clock LCM utime stamps are made with.
  StampVerdict check(int64_t stamp_utime, int64_t host_utime);

  /// How far the last checked stamp was from what the offset predicted [us]:
  /// positive = older than expected. For log lines.
  int64_t last_deviation_us() const { return last_deviation_us_; }
  bool anchored() const { return anchored_; }

  static constexpr int64_t kAnchorStep_us = 1'000;

 private:
  StampVerdict reject(StampVerdict why, int64_t stamp_utime, int64_t offset_us, int64_t host_utime);

  StampGuardLimits limits_;
  bool anchored_ = false;
  int64_t anchor_offset_us_ = 0;
  bool have_last_stamp_ = false;
  int64_t last_stamp_utime_ = 0;
  int64_t last_deviation_us_ = 0;
  int candidate_count_ = 0;
  int64_t candidate_offset_us_ = 0;
  int64_t candidate_first_host_utime_ = 0;
};

}  // namespace refloc
