#include "common/stamp_guard.hpp"

#include <algorithm>
#include <limits>

namespace refloc {
namespace {

// host - stamp without overflow: a forged INT64_MIN/INT64_MAX stamp saturates instead
// of wrapping into a plausible-looking offset.
int64_t saturating_difference(int64_t a, int64_t b) {
  int64_t d = 0;
  if (__builtin_sub_overflow(a, b, &d)) {
    return b < 0 ? std::numeric_limits<int64_t>::max() : std::numeric_limits<int64_t>::min();
  }
  return d;
}

}  // namespace

bool stamp_accepted(StampVerdict verdict) {
  return verdict == StampVerdict::kAccepted || verdict == StampVerdict::kReanchored;
}

const char* to_string(StampVerdict verdict) {
  switch (verdict) {
    case StampVerdict::kAccepted:
      return "accepted";
    case StampVerdict::kReanchored:
      return "reanchored";
    case StampVerdict::kAhead:
      return "ahead";
    case StampVerdict::kBehind:
      return "behind";
    case StampVerdict::kNotIncreasing:
      return "not_increasing";
  }
  return "unknown";
}

StampGuard::StampGuard(StampGuardLimits limits) : limits_(limits) {}

// Stamps outside (0, 1e17 us] (after the year 5138) are no clock at all. They are refused
// before they can count towards a re-anchor, so a persistent INT64_MIN/INT64_MAX stream never
// becomes the stream's clock and no later stamp difference can overflow.
constexpr int64_t kMaxPlausibleStamp_us = 100'000'000'000'000'000;

StampVerdict StampGuard::check(int64_t stamp_utime, int64_t host_utime) {
  if (stamp_utime <= 0) return StampVerdict::kBehind;
  if (stamp_utime > kMaxPlausibleStamp_us) return StampVerdict::kAhead;
  const int64_t offset_us = saturating_difference(host_utime, stamp_utime);
  if (!anchored_) {
    anchored_ = true;
    anchor_offset_us_ = offset_us;
  }
  last_deviation_us_ = saturating_difference(offset_us, anchor_offset_us_);
  if (last_deviation_us_ < -limits_.max_ahead_us)
    return reject(StampVerdict::kAhead, stamp_utime, offset_us, host_utime);
  if (last_deviation_us_ > limits_.max_behind_us)
    return reject(StampVerdict::kBehind, stamp_utime, offset_us, host_utime);
  if (limits_.require_increasing && have_last_stamp_ && stamp_utime <= last_stamp_utime_) {
    return reject(StampVerdict::kNotIncreasing, stamp_utime, offset_us, host_utime);
  }
  anchor_offset_us_ += std::clamp(last_deviation_us_, -kAnchorStep_us, kAnchorStep_us);
  have_last_stamp_ = true;
  last_stamp_utime_ = stamp_utime;
  candidate_count_ = 0;
  return StampVerdict::kAccepted;
}

StampVerdict StampGuard::reject(StampVerdict why, int64_t stamp_utime, int64_t offset_us,
                                int64_t host_utime) {
  const int64_t spread_us = saturating_difference(offset_us, candidate_offset_us_);
  const bool agrees =
      candidate_count_ > 0 && spread_us >= -limits_.max_ahead_us && spread_us <= limits_.max_ahead_us;
  if (!agrees) {
    candidate_count_ = 0;
    candidate_offset_us_ = offset_us;
    candidate_first_host_utime_ = host_utime;
  }
  ++candidate_count_;
  if (candidate_count_ >= limits_.reanchor_after &&
      saturating_difference(host_utime, candidate_first_host_utime_) >= limits_.reanchor_span_us) {
    anchor_offset_us_ = offset_us;
    last_deviation_us_ = 0;
    have_last_stamp_ = true;
    last_stamp_utime_ = stamp_utime;
    candidate_count_ = 0;
    return StampVerdict::kReanchored;
  }
  return why;
}

}  // namespace refloc
