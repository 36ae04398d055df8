#include "lms100_driver/lms100_session.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "common/clock.hpp"
#include "lms100_driver/cola_a_format.hpp"
#include "lms100_driver/lmd_scandata_parser.hpp"
#include "lms100_driver/scan_conversion.hpp"

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

namespace {
constexpr int kMaxPollMs = 100;  // upper bound on one poll so a stop flag set without the pipe is seen
}  // namespace

Lms100Session::Lms100Session(Lms100SessionConfig config, ScanCallback on_scan, StateCallback on_state)
    : config_(std::move(config)),
      on_scan_(std::move(on_scan)),
      on_state_(std::move(on_state)),
      splitter_(config_.max_frame_bytes),
      receive_buffer_(65536),
      clock_(config_.clock) {
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
  const std::string where = fmt::format("{}:{}", config_.host, config_.port);
  set_state(SessionState::kConnecting, "connecting to " + where);
  if (const ParseResult r =
          link_.connect(config_.host, config_.port, config_.connect_timeout_s, wake_pipe_[0]);
      !r) {
    ++counters_.connect_failures;
    return r.error;
  }
  ++counters_.connects;
  splitter_.reset();
  clock_.reset();
  have_last_scan_counter_ = false;
  parse_error_streak_ = 0;
  set_state(SessionState::kConfiguring, "connected to " + where + ", configuring");

  std::string reply;
  std::string why;
  const auto step = [&](const std::string& request,
                        const std::function<ParseResult(const std::string&)>& check) {
    const Wait w = transact(request, config_.reply_timeout_s, reply, why);
    if (w != Wait::kReply) return false;
    if (const ParseResult r = check(reply); !r) {
      why = r.error;
      return false;
    }
    return true;
  };
  // A stream left on by an earlier run must not be mistaken for replies; any answer will do.
  if (const Wait w = transact(request_scandata_stream(false), config_.reply_timeout_s, reply, why);
      w != Wait::kReply && w != Wait::kSopasError) {
    return "sEN LMDscandata 0: " + why;
  }
  const ScanConfig& scan = config_.scan;
  if (!step(request_login(), [](const std::string& r) { return check_login_reply(r); }))
    return "login: " + why;
  if (config_.set_scan_config) {
    // Setting the scan configuration re-spins the motor (30-45 s on a real LMS1xx, §2.4):
    // only do it when the sensor is not already scanning the way we want.
    const Wait w = transact(request_read_scan_config(), config_.reply_timeout_s, reply, why);
    if (w != Wait::kReply && w != Wait::kSopasError) return "LMPscancfg: " + why;
    ScanConfig current;
    const bool same = w == Wait::kReply && parse_scan_config_reply(reply, current).ok() && current == scan;
    if (!same && !step(request_set_scan_config(scan),
                       [&](const std::string& r) { return check_scan_config_reply(r, scan); })) {
      return "mLMPsetscancfg: " + why;
    }
  }
  if (!step(request_set_scandata_output(config_.output),
            [](const std::string& r) { return check_simple_reply(r, "sWA LMDscandatacfg"); })) {
    return "LMDscandatacfg: " + why;
  }
  if (!step(request_start_measurement(),
            [](const std::string& r) { return check_simple_reply(r, "sAN LMCstartmeas 0"); })) {
    return "LMCstartmeas: " + why;
  }
  if (!step(request_run(), [](const std::string& r) { return check_simple_reply(r, "sAN Run 1"); })) {
    return "Run: " + why;
  }

  // The sensor may take 30-45 s to spin up after a configuration change (§2.4).
  const int64_t ready_deadline = monotonic_us() + static_cast<int64_t>(config_.ready_timeout_s * 1e6);
  uint32_t status = 0;
  uint32_t last_status = 0xFFFFFFFF;
  for (;;) {
    if (!step(request_read_status(), [&](const std::string& r) { return parse_status_reply(r, status); })) {
      return "STlms: " + why;
    }
    if (status == kStatusReadyForMeasurement) break;
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

  if (!step(request_scandata_stream(true),
            [](const std::string& r) { return check_simple_reply(r, "sEA LMDscandata 1"); })) {
    return "sEN LMDscandata 1: " + why;
  }
  set_state(SessionState::kStreaming, "streaming from " + where);

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

Lms100Session::Wait Lms100Session::transact(const std::string& request, double timeout_s, std::string& reply,
                                            std::string& why) {
  if (stop_.load()) {
    why = "stopped";
    return Wait::kStopped;
  }
  const IoStatus s = link_.send_all(frame_cola_a(request), timeout_s, wake_pipe_[0]);
  if (s != IoStatus::kOk) {
    if (s == IoStatus::kTimeout) ++counters_.timeouts;
    why = s == IoStatus::kStopped ? "stopped" : "send failed: " + link_.last_error();
    return s == IoStatus::kStopped ? Wait::kStopped : Wait::kClosed;
  }
  const Wait w = pump(&request, monotonic_us() + static_cast<int64_t>(timeout_s * 1e6), false, reply, why);
  if (w == Wait::kTimeout) {
    ++counters_.timeouts;
    why = fmt::format("no reply to '{}' within {:.1f} s", request, timeout_s);
  }
  return w;
}

Lms100Session::Wait Lms100Session::pump(const std::string* request, int64_t deadline_us, bool return_on_scan,
                                        std::string& reply, std::string& why) {
  for (;;) {
    // Frames already buffered first: one read can carry a reply and several scans.
    bool got_scan = false;
    while (splitter_.next(frame_)) {
      if (is_lmd_scandata(frame_)) {
        if (handle_scan(frame_, last_read_utime_)) {
          got_scan = true;
        } else if (parse_error_streak_ >= config_.max_parse_error_streak) {
          why = fmt::format("{} unparsable scans in a row", parse_error_streak_);
          return Wait::kParseErrors;
        }
        if (got_scan && return_on_scan) return Wait::kScan;
        continue;
      }
      uint32_t code = 0;
      if (request != nullptr && parse_sopas_error(frame_, code)) {
        ++counters_.sfa_errors;
        why = fmt::format("sensor answered '{}' with sFA {:X} ({})", *request, code, sopas_error_name(code));
        return Wait::kSopasError;
      }
      if (request != nullptr && is_reply_to(*request, frame_)) {
        ColaAMessage m;
        if (split_cola_a(frame_, m) && m.type == "sMA") continue;  // acknowledged; the sAN follows
        reply = frame_;
        return Wait::kReply;
      }
      if (parse_sopas_error(frame_, code)) ++counters_.sfa_errors;
      ++counters_.unexpected_frames;  // a late or duplicated reply (seen on real LMS111s)
    }
    if (stop_.load()) {
      why = "stopped";
      return Wait::kStopped;
    }
    const int64_t left_us = deadline_us - monotonic_us();
    if (left_us <= 0) {
      why = "timeout";
      return Wait::kTimeout;
    }
    size_t received = 0;
    const int timeout_ms = static_cast<int>(std::min<int64_t>(left_us / 1000 + 1, kMaxPollMs));
    const IoStatus s =
        link_.receive(receive_buffer_.data(), receive_buffer_.size(), timeout_ms, wake_pipe_[0], received);
    switch (s) {
      case IoStatus::kOk:
        last_read_utime_ = now_utime();
        splitter_.feed(receive_buffer_.data(), received);
        sync_splitter_counters();
        break;
      case IoStatus::kTimeout:
        break;
      case IoStatus::kStopped:
        why = "stopped";
        return Wait::kStopped;
      case IoStatus::kClosed:
      case IoStatus::kError:
        why = "link lost: " + link_.last_error();
        return Wait::kClosed;
    }
  }
}

bool Lms100Session::handle_scan(const std::string& payload, int64_t receive_utime) {
  ParseResult r = parse_lmd_scandata(payload, scan_data_);
  if (r) r = to_laser_scan(scan_data_, scan_);
  if (!r) {
    ++counters_.parse_errors;
    ++parse_error_streak_;
    return false;
  }
  parse_error_streak_ = 0;
  if (have_last_scan_counter_) {
    const uint32_t missing = (scan_data_.scan_counter - last_scan_counter_ - 1) & 0xFFFFu;
    if (missing != 0 && missing < 0x8000u) {
      ++counters_.scan_counter_gaps;
      counters_.lost_scans += missing;
    }
  }
  have_last_scan_counter_ = true;
  last_scan_counter_ = scan_data_.scan_counter;

  const SensorTimeMapping t =
      clock_.update(scan_data_.time_since_startup_us, scan_data_.time_of_transmission_us, receive_utime);
  scan_.utime = t.host_start_utime;
  scan_.receive_utime = receive_utime;
  scan_.sensor_start_us = t.sensor_start_us;
  scan_.sensor_transmit_us = t.sensor_transmit_us;
  ++counters_.scans;
  if (on_scan_) on_scan_(scan_);
  return true;
}

void Lms100Session::stop_streaming_politely() {
  // The stop pipe stays readable, so wait on the link alone for these last replies.
  const int saved = wake_pipe_[0];
  wake_pipe_[0] = -1;
  const bool was_stopped = stop_.exchange(false);
  std::string reply;
  std::string why;
  transact(request_scandata_stream(false), config_.stop_reply_timeout_s, reply, why);
  if (transact(request_login(), config_.stop_reply_timeout_s, reply, why) == Wait::kReply) {
    transact(request_stop_measurement(), config_.stop_reply_timeout_s, reply, why);
  }
  stop_.store(was_stopped || stop_.load());
  wake_pipe_[0] = saved;
}

void Lms100Session::sync_splitter_counters() {
  counters_.garbage_bytes.store(splitter_.garbage_bytes());
  counters_.resyncs.store(splitter_.resyncs());
  counters_.oversized_frames.store(splitter_.oversized_frames());
}

}  // namespace refloc
