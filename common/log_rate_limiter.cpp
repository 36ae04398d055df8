#include "common/log_rate_limiter.hpp"

namespace refloc {

bool LogRateLimiter::allow(const std::string& key, int64_t now_us, int64_t& suppressed) {
  KeyState& k = keys_[key];
  if (k.written && now_us - k.last_written_us < interval_us_) {
    ++k.suppressed;
    suppressed = 0;
    return false;
  }
  suppressed = k.suppressed;
  k.suppressed = 0;
  k.written = true;
  k.last_written_us = now_us;
  return true;
}

}  // namespace refloc
