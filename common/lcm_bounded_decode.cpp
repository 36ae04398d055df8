#include "common/lcm_bounded_decode.hpp"

namespace refloc {

int64_t DecodeErrorLogLimiter::on_error(int64_t now_us) {
  ++unlogged_;
  // A clock step backwards (now_us < last) counts as due rather than silencing the log.
  if (logged_any_ && now_us >= last_logged_us_ && now_us - last_logged_us_ < kIntervalUs) return 0;
  logged_any_ = true;
  last_logged_us_ = now_us;
  const int64_t covered = unlogged_;
  unlogged_ = 0;
  return covered;
}

}  // namespace refloc
