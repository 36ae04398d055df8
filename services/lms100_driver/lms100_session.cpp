#include "lms100_driver/lms100_session.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "common/clock.hpp"

namespace refloc {

const char* to_string(SessionState state) {
  switch (state) {
    case SessionState::kConnecting:
      return "connecting";
    case SessionState::kConfiguring:
      return "configuring";
    case SessionState::kWaitingReady:
      return "waiting for ready";
    case SessionState::kStreaming:
      return "streaming";
    case SessionState::kBackoff:
      return "backoff";
    case SessionState::kStopped:
      return "stopped";
  }
  return "?";
}

Lms100Session::Lms100Session(Lms100SessionConfig config, ScanCallback on_scan, StateCallback on_state)
    : config_(std::move(config)),
      on_scan_(std::move(on_scan)),
      on_state_(std::move(on_state)),
      wire_(config_.dialect, config_.max_frame_bytes),
      receive_buffer_(65536),
      stamper_(config_.stamping) {
  if (::pipe2(wake_pipe_, O_CLOEXEC | O_NONBLOCK) != 0) {
    wake_pipe_[0] = wake_pipe_[1] = -1;  // stop() then relies on the flag and the 100 ms poll bound
  }
  frame_.reserve(8192);
}

Lms100Session::~Lms100Session() {
  join();
  for (int& fd : wake_pipe_) {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
}

void Lms100Session::stop() {
  stop_.store(true);
  if (wake_pipe_[1] >= 0) {
    const char byte = 1;
    [[maybe_unused]] const ssize_t n = ::write(wake_pipe_[1], &byte, 1);
  }
}

void Lms100Session::start_thread() {
  if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
}

void Lms100Session::join() {
  stop();
  if (thread_.joinable()) thread_.join();
}

void Lms100Session::set_state(SessionState state, const std::string& detail) {
  state_.store(state);
  if (on_state_) on_state_(state, detail);
}

bool Lms100Session::sleep_interruptible(double seconds) {
  const int64_t deadline = monotonic_us() + static_cast<int64_t>(seconds * 1e6);
  while (!stop_.load()) {
    const int64_t left_us = deadline - monotonic_us();
    if (left_us <= 0) return true;
    pollfd fds{wake_pipe_[0], POLLIN, 0};
    ::poll(&fds, wake_pipe_[0] >= 0 ? 1 : 0,
           static_cast<int>(std::min<int64_t>(left_us / 1000 + 1, kMaxPollMs)));
  }
  return false;
}

void Lms100Session::run() {
  double backoff_s = config_.backoff_initial_s;
  while (!stop_.load()) {
    const uint64_t scans_before = counters_.scans.load();
    const std::string why = run_connection();
    link_.close();
    if (stop_.load()) break;
    ++counters_.reconnects;
    // A connection that delivered scans was healthy: the next failure starts the back-off over.
    if (counters_.scans.load() > scans_before) backoff_s = config_.backoff_initial_s;
    set_state(SessionState::kBackoff, fmt::format("{}; retrying in {:.1f} s", why, backoff_s));
    if (!sleep_interruptible(backoff_s)) break;
    backoff_s = std::min(backoff_s * 2.0, config_.backoff_max_s);
  }
  link_.close();
  set_state(SessionState::kStopped, "stopped");
}

std::string Lms100Session::run_connection() {
  const std::string where = fmt::format("{}:{} ({})", config_.host, config_.port, to_string(config_.dialect));
  set_state(SessionState::kConnecting, "connecting to " + where);
  if (const ParseResult r =
          link_.connect(config_.host, config_.port, config_.connect_timeout_s, wake_pipe_[0]);
      !r) {
    ++counters_.connect_failures;
    return r.error;
  }
  ++counters_.connects;
  wire_.reset();
  stamper_.reset();
  publish_stamped_scans();  // nothing to publish: brings the counters up to date
  have_last_scan_counter_ = false;
  parse_error_streak_ = 0;
  set_state(SessionState::kConfiguring, "connected to " + where + ", configuring");

  std::string error = configure_sensor();
  if (error.empty()) error = wait_until_ready(where);
  if (!error.empty()) return error;
  std::string reply, why;
  if (!command(
          request_scandata_stream(true),
          [](const std::string& r) { return check_simple_reply(r, "sEA LMDscandata 1"); }, reply, why)) {
    return "sEN LMDscandata 1: " + why;
  }
  set_state(SessionState::kStreaming, "streaming from " + where);
  return stream_scans();
}

bool Lms100Session::command(const std::string& request, const ReplyCheck& check, std::string& reply,
                            std::string& why) {
  const Wait w = transact(request, config_.reply_timeout_s, reply, why);
  if (w != Wait::kReply) return false;
  if (const ParseResult r = check(reply); !r) {
    why = r.error;
    return false;
  }
  return true;
}

std::string Lms100Session::configure_sensor() {
  std::string reply, why;
  // A stream left on by an earlier run must not be mistaken for replies; any answer will do.
  if (const Wait w = transact(request_scandata_stream(false), config_.reply_timeout_s, reply, why);
      w != Wait::kReply && w != Wait::kSopasError) {
    return "sEN LMDscandata 0: " + why;
  }
  const ScanConfig& scan = config_.scan;
  if (!command(
          request_login(), [](const std::string& r) { return check_login_reply(r); }, reply, why))
    return "login: " + why;
  if (config_.set_scan_config) {
    // Setting the scan configuration re-spins the motor (30-45 s on a real LMS1xx, §2.4):
    // only do it when the sensor is not already scanning the way we want.
    const Wait w = transact(request_read_scan_config(), config_.reply_timeout_s, reply, why);
    if (w != Wait::kReply && w != Wait::kSopasError) return "LMPscancfg: " + why;
    ScanConfig current;
    const bool same = w == Wait::kReply && parse_scan_config_reply(reply, current).ok() && current == scan;
    if (!same && !command(
                     request_set_scan_config(scan),
                     [&](const std::string& r) { return check_scan_config_reply(r, scan); }, reply, why)) {
      return "mLMPsetscancfg: " + why;
    }
  }
  if (!command(
          request_set_scandata_output(config_.output),
          [](const std::string& r) { return check_simple_reply(r, "sWA LMDscandatacfg"); }, reply, why)) {
    return "LMDscandatacfg: " + why;
  }
  if (!command(
          request_start_measurement(),
          [](const std::string& r) { return check_simple_reply(r, "sAN LMCstartmeas 0"); }, reply, why)) {
    return "LMCstartmeas: " + why;
  }
  if (!command(
          request_run(), [](const std::string& r) { return check_simple_reply(r, "sAN Run 1"); }, reply,
          why)) {
    return "Run: " + why;
  }
  return "";
}

std::string Lms100Session::wait_until_ready(const std::string& where) {
  // The sensor may take 30-45 s to spin up after a configuration change (§2.4).
  const int64_t ready_deadline = monotonic_us() + static_cast<int64_t>(config_.ready_timeout_s * 1e6);
  std::string reply, why;
  uint32_t status = 0;
  uint32_t last_status = 0xFFFFFFFF;
  for (;;) {
    if (!command(
            request_read_status(), [&](const std::string& r) { return parse_status_reply(r, status); }, reply,
            why)) {
      return "STlms: " + why;
    }
    if (status == kStatusReadyForMeasurement) return "";
    if (status != last_status) {
      set_state(SessionState::kWaitingReady,
                fmt::format("{}: waiting for STlms 7, sensor reports {}", where, status));
      last_status = status;
    }
    if (monotonic_us() > ready_deadline) {
      ++counters_.timeouts;
      return fmt::format("sensor not ready after {:.0f} s (STlms {})", config_.ready_timeout_s, status);
    }
    // Scans cannot arrive yet, but a stop must: wait on the link, not in sleep.
    const int64_t next_poll = monotonic_us() + static_cast<int64_t>(config_.status_poll_period_s * 1e6);
    const Wait w = pump(nullptr, next_poll, false, reply, why);
    if (w != Wait::kTimeout) return "waiting for ready: " + why;
  }
}

std::string Lms100Session::stream_scans() {
  std::string reply, why;
  const double scan_timeout_s = config_.scan_timeout_periods * config_.scan_period_s();
  int64_t deadline =
      monotonic_us() + static_cast<int64_t>(std::max(config_.first_scan_timeout_s, scan_timeout_s) * 1e6);
  for (;;) {
    const Wait w = pump(nullptr, deadline, true, reply, why);
    if (w == Wait::kScan) {
      deadline = monotonic_us() + static_cast<int64_t>(scan_timeout_s * 1e6);
      continue;
    }
    if (w == Wait::kStopped) {
      stop_streaming_politely();
      return "stopped";
    }
    if (w == Wait::kTimeout) {
      ++counters_.timeouts;
      return fmt::format("no scan for {:.0f} ms", scan_timeout_s * 1e3);
    }
    return why;
  }
}

}  // namespace refloc
