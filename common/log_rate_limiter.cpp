#include "common/log_rate_limiter.hpp"

#include "common/heartbeat_state_name.hpp"

namespace refloc {
namespace {

// heartbeat_t::STATE_ERROR and STATE_STOPPING (common/ has no LCM types; the names' header agrees).
constexpr int8_t kStateError = 3;
constexpr int8_t kStateStopping = 4;

}  // namespace

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

StateChangeLogLimiter::Line StateChangeLogLimiter::change_line(int8_t state,
                                                               const std::string& detail) const {
  std::string text = "state " + heartbeat_state_name(state);
  if (logged_ && logged_state_ != state) text += " (was " + heartbeat_state_name(logged_state_) + ")";
  if (!detail.empty()) text += ": " + detail;
  return {state == kStateError, text};
}

std::optional<StateChangeLogLimiter::Line> StateChangeLogLimiter::on_change(int8_t state,
                                                                            const std::string& detail,
                                                                            int64_t now_us) {
  const bool quiet_interval = !logged_ || now_us - last_line_us_ >= interval_us_;
  const bool new_error = state == kStateError && state_ != kStateError &&
                         (!error_logged_ || now_us - last_error_line_us_ >= interval_us_);
  const bool urgent = new_error || state == kStateStopping;
  state_ = state;
  detail_ = detail;
  if (!quiet_interval && !urgent) {
    ++held_back_;
    ++held_back_to_[state];
    return std::nullopt;
  }
  Line line = change_line(state, detail);
  if (quiet_interval) line.text += take_held_back(now_us);
  logged_ = true;
  last_line_us_ = now_us;
  logged_state_ = state;
  if (state == kStateError) {
    error_logged_ = true;
    last_error_line_us_ = now_us;
  }
  return line;
}

std::string StateChangeLogLimiter::take_held_back(int64_t now_us) {
  if (held_back_ == 0) return "";
  std::string into;
  for (const auto& [state, count] : held_back_to_)
    into += (into.empty() ? "" : ", ") + std::to_string(count) + "x " + heartbeat_state_name(state);
  const int64_t seconds = (now_us - last_line_us_ + 500'000) / 1'000'000;
  const std::string text = " (" + std::to_string(held_back_) + (held_back_ == 1 ? " change" : " changes") +
                           " in the last " + std::to_string(seconds) + " s not logged one by one: " + into +
                           ")";
  held_back_ = 0;
  held_back_to_.clear();
  return text;
}

std::optional<StateChangeLogLimiter::Line> StateChangeLogLimiter::on_tick(int64_t now_us) {
  if (held_back_ == 0 || now_us - last_line_us_ < interval_us_) return std::nullopt;
  Line line{state_ == kStateError, "state " + heartbeat_state_name(state_) +
                                       (detail_.empty() ? "" : ": " + detail_) + take_held_back(now_us)};
  last_line_us_ = now_us;
  logged_state_ = state_;
  return line;
}

}  // namespace refloc
