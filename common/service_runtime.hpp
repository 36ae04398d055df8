#pragma once
// The LCM service runtime every main.cpp uses: one LCM handle, typed
// subscriptions that count decode errors, periodic timers, a 1 Hz HEARTBEAT,
// and a handle loop that ends cleanly on SIGINT/SIGTERM. Under systemd
// (Type=notify, WatchdogSec=) it reports READY, feeds the watchdog while the
// loop iterates and the service says it is healthy, and reports STOPPING.

#include "common/clock.hpp"
#include "common/heartbeat_peers.hpp"
#include "common/instance_lock.hpp"
#include "common/latency_window.hpp"
#include "common/lcm_bounded_decode.hpp"
#include "common/log_rate_limiter.hpp"

#include <spdlog/spdlog.h>
#include <lcm/lcm-cpp.hpp>
#include <refloc/heartbeat_t.hpp>

#include <unistd.h>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace refloc {

/// The URL to open: the explicit one if not empty, else $LCM_DEFAULT_URL, else
/// kLcmDefaultUrl (ttl=0); validated, recv_buf_size added to udpm (common/lcm_url.hpp).
/// Throws ConfigError (exit 2 under guarded_main) for an invalid URL.
std::string resolve_lcm_url(const std::string& explicit_url);

/// Send log lines of this process to stderr, prefixed with the service name.
void setup_logging(const std::string& service_name, bool verbose = false);

class ServiceRuntime {
 public:
  /// Throws ConfigError for an invalid URL, std::runtime_error when LCM cannot be created
  /// (no multicast route). WARNs, and counts lcm_recv_buf_clamped_to_bytes, when the kernel
  /// grants less receive buffer than the URL asks.
  ServiceRuntime(std::string service_name, const std::string& lcm_url);
  ~ServiceRuntime();
  ServiceRuntime(const ServiceRuntime&) = delete;
  ServiceRuntime& operator=(const ServiceRuntime&) = delete;

  /// Subscribe with a typed handler. Messages that fail to decode are counted in the
  /// heartbeat (decode_errors) and skipped, as are well-formed ones holding a NaN, infinite or
  /// huge number (counter implausible_numbers_<channel>, lower case); the handler's run time feeds
  /// processing p50/p99.
  template <class Message>
  void subscribe(const std::string& channel, std::function<void(const Message&)> handler);

  /// Encode and publish; counts messages_out. Returns false (and logs) on failure.
  template <class Message>
  bool publish(const std::string& channel, const Message& message);

  /// Call fn every period_s seconds from the handle loop (drift-free schedule).
  void add_periodic(double period_s, std::function<void()> fn);

  /// Logs the change by state name ("state DEGRADED (was OK): ..."), at most one line per 10 s
  /// while the state keeps changing, then a summary of the changes not logged (StateChangeLogLimiter).
  void set_state(int8_t state, const std::string& detail = "");
  int8_t state() const { return state_; }
  /// A service-specific counter reported in the heartbeat (created at 0 on first use).
  int64_t& counter(const std::string& name) { return counters_[name]; }
  void add_processing_time_us(double us) { processing_.add(us); }

  /// Run until a signal or request_stop(); returns 0.
  int run();
  /// While false, run() stops feeding the systemd watchdog, so systemd restarts a
  /// service that knows it is stuck (e.g. its sensor link is gone for good).
  void set_watchdog_healthy(bool healthy) { watchdog_healthy_ = healthy; }
  bool watchdog_healthy() const { return watchdog_healthy_; }
  /// Process events for at most timeout_ms; for tests and tools that drive the loop.
  void spin_once(int timeout_ms);
  void request_stop() { stop_requested_ = true; }
  bool stop_requested() const;

  const std::string& name() const { return name_; }
  lcm::LCM& lcm() { return *lcm_; }
  int64_t messages_in() const { return messages_in_; }
  int64_t decode_errors() const { return decode_errors_; }
  void publish_heartbeat();

 private:
  struct RawSubscription {
    ServiceRuntime* runtime;
    std::function<void(const lcm::ReceiveBuffer*)> on_message;
  };
  static std::string implausible_number_counter_name(const std::string& channel);
  static void dispatch(const lcm::ReceiveBuffer* rbuf, const std::string& channel, RawSubscription* sub);
  void run_due_timers();
  void watch_heartbeats_for_duplicates();
  static void on_heartbeat_heard(const lcm::ReceiveBuffer* rbuf, const std::string& channel,
                                 ServiceRuntime* self);
  std::pair<int8_t, std::string> reported_state(int64_t start_utime);
  void feed_watchdog_if_due();
  static void write_state_line(const std::optional<StateChangeLogLimiter::Line>& line);

  struct Periodic {
    int64_t period_us;
    int64_t next_due_us;
    std::function<void()> fn;
  };

  std::string name_;
  std::unique_ptr<InstanceLock> instance_lock_;  ///< taken before lcm_, released after it
  std::unique_ptr<lcm::LCM> lcm_;
  std::vector<std::unique_ptr<RawSubscription>> subscriptions_;
  std::vector<Periodic> timers_;
  std::map<std::string, int64_t> counters_;
  LatencyWindow processing_;
  int8_t state_ = heartbeat_t::STATE_STARTING;
  std::string state_detail_;
  StateChangeLogLimiter state_log_;
  int64_t start_monotonic_us_ = 0;
  int64_t messages_in_ = 0;
  int64_t messages_out_ = 0;
  int64_t decode_errors_ = 0;
  bool stop_requested_ = false;
  bool watchdog_healthy_ = true;
  int64_t watchdog_period_us_ = 0;  ///< half of WatchdogSec; 0 when systemd asked for none
  int64_t watchdog_next_due_us_ = 0;
  std::string lcm_url_for_log_;
  OwnNameMonitor own_name_{name_, static_cast<int32_t>(getpid())};
  std::string reported_duplicate_;  ///< the duplicate last logged ("" = none)
};

template <class Message>
void ServiceRuntime::subscribe(const std::string& channel, std::function<void(const Message&)> handler) {
  auto sub = std::make_unique<RawSubscription>();
  sub->runtime = this;
  const std::string channel_name = channel;
  int64_t& implausible_count = counter(implausible_number_counter_name(channel));
  sub->on_message = [this, channel_name, &implausible_count, handler = std::move(handler),
                     log_limiter = DecodeErrorLogLimiter()](const lcm::ReceiveBuffer* rbuf) mutable {
    Message message;
    // Bounds-checked first: a lying array length must not reach lcm-gen's resize(). A NaN,
    // inf or 1e300 anywhere refuses the whole message, so no handler ever sees one.
    const LcmDecodeResult decoded =
        decode_lcm_bounded(rbuf->data, rbuf->data_size, message, LcmNumbers::kPlausibleOnly);
    if (!decoded.ok) {
      const int64_t in_all = decoded.implausible_number ? ++implausible_count : ++decode_errors_;
      if (const int64_t covered = log_limiter.on_error(monotonic_us()))
        spdlog::warn("{}: {} of {} bytes skipped: {} ({} refused since the last line, {} {} in all)",
                     channel_name, Message::getTypeName(), rbuf->data_size, decoded.reason, covered, in_all,
                     decoded.implausible_number ? "with an implausible number" : "decode errors");
      return;
    }
    ++messages_in_;
    handler(message);
  };
  lcm::Subscription* s = lcm_->subscribeFunction(channel, &ServiceRuntime::dispatch, sub.get());
  // Bursts (log replay at full speed) must not be dropped silently by LCM's 30-message queue.
  s->setQueueCapacity(1000);
  subscriptions_.push_back(std::move(sub));
}

template <class Message>
bool ServiceRuntime::publish(const std::string& channel, const Message& message) {
  const int size = message.getEncodedSize();
  std::vector<uint8_t> buffer(static_cast<size_t>(size));
  if (message.encode(buffer.data(), 0, size) < 0 ||
      lcm_->publish(channel, buffer.data(), static_cast<unsigned>(size)) != 0) {
    spdlog::error("{}: publishing a {} failed", channel, Message::getTypeName());
    return false;
  }
  ++messages_out_;
  return true;
}

}  // namespace refloc
