#include "common/service_runtime.hpp"

#include "common/clock.hpp"
#include "common/heartbeat_peers.hpp"
#include "common/instance_lock.hpp"
#include "common/lcm_url.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>
#ifdef REFLOC_HAVE_SYSTEMD
#include <systemd/sd-daemon.h>
#endif

#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <stdexcept>
#include <tuple>

namespace refloc {
namespace {

// Signal handlers can only reach static storage; this is the one flag they set.
volatile std::sig_atomic_t g_signal_received = 0;

void on_signal(int signal_number) { g_signal_received = signal_number; }

void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  std::signal(SIGPIPE, SIG_IGN);  // a closed TCP peer must be an error code, not a death
}

// sd_notify is a no-op returning 0 when NOTIFY_SOCKET is unset (not under systemd).
void notify_systemd(const char* state) {
#ifdef REFLOC_HAVE_SYSTEMD
  sd_notify(0, state);
#else
  (void)state;
#endif
}

/// Half of the watchdog interval systemd asked for [us]; 0 when there is none.
int64_t watchdog_half_period_us() {
#ifdef REFLOC_HAVE_SYSTEMD
  uint64_t interval_us = 0;
  if (sd_watchdog_enabled(0, &interval_us) > 0 && interval_us > 0)
    return static_cast<int64_t>(interval_us / 2);
#endif
  return 0;
}

/// The receive buffer the kernel grants the URL's socket [bytes] when it is less than asked
/// (one WARN naming the sysctl); 0 when granted or unknown. LCM 1.3.1 hides its socket, so
/// net.core.rmem_max is what can be checked.
int64_t receive_buffer_clamped_to_bytes(const LcmUrl& url) {
  if (url.recv_buf_size_bytes <= 0) return 0;
  const ReceiveBufferCheck buffer =
      check_receive_buffer(url.recv_buf_size_bytes, read_rmem_max().value_or(-1));
  if (!buffer.clamped) return 0;
  spdlog::warn("{}", buffer.warning);
  return buffer.granted_bytes;
}

}  // namespace

std::string resolve_lcm_url(const std::string& explicit_url) {
  return resolve_lcm_url(explicit_url, std::getenv("LCM_DEFAULT_URL")).url;
}

void setup_logging(const std::string& service_name, bool verbose) {
  // A second call (tests, a tool hosting two services) reuses the logger instead of throwing.
  auto logger = spdlog::get(service_name);
  if (!logger) logger = spdlog::stderr_color_mt(service_name);
  logger->set_pattern("%Y-%m-%d %H:%M:%S.%e [%n] %^%l%$: %v");
  logger->set_level(verbose ? spdlog::level::debug : spdlog::level::info);
  spdlog::set_default_logger(logger);
}

ServiceRuntime::ServiceRuntime(std::string service_name, const std::string& lcm_url)
    : name_(std::move(service_name)), start_monotonic_us_(monotonic_us()) {
  const LcmUrl lcm_url_used =
      resolve_lcm_url(lcm_url, std::getenv("LCM_DEFAULT_URL"));  // ConfigError: exit 2
  const std::string url = lcm_url_used.url;
  // Before LCM: a second instance must not publish even once (InstanceConflictError: exit 2).
  instance_lock_ = std::make_unique<InstanceLock>(name_, url);
  lcm_ = std::make_unique<lcm::LCM>(url);
  if (!lcm_->good()) {
    throw std::runtime_error("cannot open LCM at '" + url +
                             "' (is there a multicast route? try: ip route add 224.0.0.0/4 dev lo)");
  }
  // Only when clamped: the heartbeat then says how small the buffer is (non-zero counters show as errors).
  if (const int64_t clamped_to_bytes = receive_buffer_clamped_to_bytes(lcm_url_used); clamped_to_bytes > 0)
    counter("lcm_recv_buf_clamped_to_bytes") = clamped_to_bytes;
  install_signal_handlers();
  add_periodic(1.0, [this] {
    publish_heartbeat();
    write_state_line(state_log_.on_tick(monotonic_us()));  // a flapping state's summary
  });
  watch_heartbeats_for_duplicates();
  lcm_url_for_log_ = url;
}

ServiceRuntime::~ServiceRuntime() = default;

void ServiceRuntime::dispatch(const lcm::ReceiveBuffer* rbuf, const std::string&, RawSubscription* sub) {
  const int64_t start = monotonic_us();
  sub->on_message(rbuf);
  sub->runtime->processing_.add(static_cast<double>(monotonic_us() - start));
}

void ServiceRuntime::add_periodic(double period_s, std::function<void()> fn) {
  const auto period_us = static_cast<int64_t>(period_s * 1e6);
  timers_.push_back({period_us > 0 ? period_us : 1, monotonic_us() + period_us, std::move(fn)});
}

void ServiceRuntime::set_state(int8_t state, const std::string& detail) {
  if (state != state_ || detail != state_detail_)
    write_state_line(state_log_.on_change(state, detail, monotonic_us()));
  state_ = state;
  state_detail_ = detail;
}

void ServiceRuntime::write_state_line(const std::optional<StateChangeLogLimiter::Line>& line) {
  if (!line) return;
  if (line->error) {
    spdlog::error("{}", line->text);
  } else {
    spdlog::info("{}", line->text);
  }
}

bool ServiceRuntime::stop_requested() const { return stop_requested_ || g_signal_received != 0; }

void ServiceRuntime::run_due_timers() {
  const int64_t now = monotonic_us();
  for (auto& t : timers_) {
    if (now >= t.next_due_us) {
      t.fn();
      t.next_due_us += t.period_us;
      // After a stall, skip missed ticks instead of firing a burst.
      if (t.next_due_us < now) t.next_due_us = now + t.period_us;
    }
  }
}

void ServiceRuntime::spin_once(int timeout_ms) {
  int64_t wait_us = static_cast<int64_t>(timeout_ms) * 1000;
  const int64_t now = monotonic_us();
  for (const auto& t : timers_) wait_us = std::min(wait_us, std::max<int64_t>(0, t.next_due_us - now));
  errno = 0;
  const int rc = lcm_->handleTimeout(static_cast<int>((wait_us + 999) / 1000));
  // A signal (SIGTERM at shutdown, SIGCHLD) interrupting the wait is not an LCM error.
  if (rc < 0 && errno != EINTR) {
    ++counter("lcm_handle_errors");
  }
  run_due_timers();
}

void ServiceRuntime::feed_watchdog_if_due() {
  if (watchdog_period_us_ <= 0 || !watchdog_healthy_) return;
  const int64_t now = monotonic_us();
  if (now < watchdog_next_due_us_) return;
  notify_systemd("WATCHDOG=1");
  watchdog_next_due_us_ = now + watchdog_period_us_;
}

int ServiceRuntime::run() {
  if (state_ == heartbeat_t::STATE_STARTING) set_state(heartbeat_t::STATE_OK);
  watchdog_period_us_ = watchdog_half_period_us();
  watchdog_next_due_us_ = monotonic_us();
  notify_systemd("READY=1");
  // Only now: everything the main set up before run() (config, map, world, sensor) succeeded.
  spdlog::info("started, pid {}, LCM {}", getpid(), lcm_url_for_log_);
  // Fed from the loop itself: a handler that blocks stops the feeding, and systemd restarts us.
  const int spin_ms = watchdog_period_us_ > 0
                          ? static_cast<int>(std::clamp<int64_t>(watchdog_period_us_ / 2000, 1, 100))
                          : 100;
  while (!stop_requested()) {
    spin_once(spin_ms);
    feed_watchdog_if_due();
  }
  notify_systemd("STOPPING=1");
  set_state(heartbeat_t::STATE_STOPPING,
            g_signal_received ? "signal " + std::to_string(g_signal_received) : "stop requested");
  publish_heartbeat();
  spdlog::info("stopped: {} in, {} out, {} decode errors", messages_in_, messages_out_, decode_errors_);
  return 0;
}

void ServiceRuntime::watch_heartbeats_for_duplicates() {
  // Raw, not subscribe(): heartbeats are not the service's input (messages_in, p50/p99).
  lcm_->subscribeFunction("HEARTBEAT", &ServiceRuntime::on_heartbeat_heard, this);
}

std::string ServiceRuntime::implausible_number_counter_name(const std::string& channel) {
  std::string name = "implausible_numbers_" + channel;
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return name;
}

void ServiceRuntime::on_heartbeat_heard(const lcm::ReceiveBuffer* rbuf, const std::string&,
                                        ServiceRuntime* self) {
  heartbeat_t hb;
  if (!decode_lcm_bounded(rbuf->data, rbuf->data_size, hb).ok) {
    ++self->counter("unreadable_heartbeats");  // not our input: counted, never logged per message
    return;
  }
  const HeartbeatIdentity sender{hb.service, hb.pid, hb.utime - hb.uptime_us,
                                 hb.state == heartbeat_t::STATE_STOPPING};
  if (self->own_name_.observe(sender, static_cast<double>(monotonic_us()) * 1e-6))
    ++self->counter("other_instance_heartbeats");
}

/// The state the heartbeat reports: ERROR while another process sends under our name.
std::pair<int8_t, std::string> ServiceRuntime::reported_state(int64_t start_utime) {
  const double now_s = static_cast<double>(monotonic_us()) * 1e-6;
  own_name_.observe_own(start_utime, now_s);
  const std::string duplicate = own_name_.conflict(now_s);
  if (duplicate != reported_duplicate_) {
    if (duplicate.empty())
      spdlog::info("no other instance of {} heard any more", name_);
    else
      spdlog::error("{} of {} on this LCM bus (from HEARTBEAT): state ERROR", duplicate, name_);
    reported_duplicate_ = duplicate;
  }
  if (duplicate.empty() || state_ == heartbeat_t::STATE_STOPPING) return {state_, state_detail_};
  return {heartbeat_t::STATE_ERROR, duplicate + (state_detail_.empty() ? "" : "; " + state_detail_)};
}

void ServiceRuntime::publish_heartbeat() {
  if (instance_lock_) instance_lock_->drain_refused_starters();
  heartbeat_t hb;
  hb.utime = now_utime();
  hb.service = name_;
  hb.pid = static_cast<int32_t>(getpid());
  hb.uptime_us = monotonic_us() - start_monotonic_us_;
  std::tie(hb.state, hb.state_detail) = reported_state(hb.utime - hb.uptime_us);
  hb.messages_in = messages_in_;
  hb.messages_out = messages_out_;
  hb.decode_errors = decode_errors_;
  hb.processing_p50_us = static_cast<float>(processing_.percentile(0.50));
  hb.processing_p99_us = static_cast<float>(processing_.percentile(0.99));
  for (const auto& [name, value] : counters_) {
    hb.counter_names.push_back(name);
    hb.counter_values.push_back(value);
  }
  hb.ncounters = static_cast<int32_t>(hb.counter_names.size());
  // Not through publish(): messages_out counts the service's data, not its heartbeats.
  lcm_->publish("HEARTBEAT", &hb);
}

}  // namespace refloc
