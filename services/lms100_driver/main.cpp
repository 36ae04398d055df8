// lms100_driver: a SICK LMS100 over CoLa-A/TCP → LMS100_SCAN (laser_scan_t), with
// reconnects forever and the link's counters in HEARTBEAT.
//
// The session blocks in poll() on its own thread and publishes each scan from
// there (lcm::LCM::publish is thread-safe); the ServiceRuntime loop on the main
// thread only copies the session's atomic counters and state into the heartbeat.

#include <CLI/CLI.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/laser_scan_t.hpp>

#include <atomic>
#include <mutex>
#include <string>

#include "common/clock.hpp"
#include "common/json_config.hpp"
#include "common/lcm_conversions.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "lms100_driver/driver_config_file.hpp"
#include "lms100_driver/lms100_session.hpp"

namespace refloc {
namespace {

struct Options {
  std::string host = "192.168.0.1";
  uint16_t port = 2111;
  std::string config_path;
  std::string lcm_url;
};

/// The session's latest state line, handed from the session thread to the heartbeat.
class StateMailbox {
 public:
  void set(SessionState state, const std::string& detail) {
    std::lock_guard<std::mutex> lock(mutex_);
    state_ = state;
    detail_ = detail;
  }
  std::pair<SessionState, std::string> get() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return {state_, detail_};
  }

 private:
  mutable std::mutex mutex_;
  SessionState state_ = SessionState::kConnecting;
  std::string detail_ = "starting";
};

int run(const Options& options) {
  DriverServiceConfig config;
  if (!options.config_path.empty()) {
    const JsonConfig file = JsonConfig::load_file(options.config_path);
    config = parse_driver_config(file);
    file.reject_unknown_keys();
  }
  config.session.host = options.host;
  config.session.port = options.port;

  ServiceRuntime runtime("lms100_driver", options.lcm_url);
  lcm::LCM& lcm = runtime.lcm();
  StateMailbox mailbox;
  std::atomic<int64_t> last_scan_monotonic_us{0};
  std::atomic<uint64_t> publish_failures{0};
  std::atomic<int64_t> last_publish_us{0};

  const std::string channel = config.output_channel;
  Lms100Session session(
      config.session,
      [&](const LaserScan& scan) {
        const int64_t t0 = monotonic_us();
        laser_scan_t msg = to_lcm(scan);
        if (lcm.publish(channel, &msg) != 0) ++publish_failures;
        last_scan_monotonic_us.store(monotonic_us());
        last_publish_us.store(monotonic_us() - t0);
      },
      [&](SessionState state, const std::string& detail) {
        mailbox.set(state, detail);
        if (state == SessionState::kBackoff) {
          spdlog::warn("{}", detail);
        } else {
          spdlog::info("{}: {}", to_string(state), detail);
        }
      });

  const int64_t started_us = monotonic_us();
  runtime.add_periodic(0.25, [&] {
    const Lms100SessionCounters& c = session.counters();
    const auto copy = [&](const char* name, const std::atomic<uint64_t>& v) {
      runtime.counter(name) = static_cast<int64_t>(v.load());
    };
    copy("connects", c.connects);
    copy("connect_failures", c.connect_failures);
    copy("reconnects", c.reconnects);
    copy("timeouts", c.timeouts);
    copy("sfa_errors", c.sfa_errors);
    copy("parse_errors", c.parse_errors);
    copy("garbage_bytes", c.garbage_bytes);
    copy("resyncs", c.resyncs);
    copy("oversized_frames", c.oversized_frames);
    copy("unexpected_frames", c.unexpected_frames);
    copy("scans", c.scans);
    copy("scan_counter_gaps", c.scan_counter_gaps);
    copy("lost_scans", c.lost_scans);
    copy("publish_failures", publish_failures);

    const auto [state, detail] = mailbox.get();
    const int64_t now = monotonic_us();
    const int64_t last = last_scan_monotonic_us.load();
    const double silent_s = (now - (last > 0 ? last : started_us)) * 1e-6;
    if (state == SessionState::kStreaming && silent_s < 1.0) {
      runtime.set_state(heartbeat_t::STATE_OK, detail);
    } else if (silent_s < config.error_after_s) {
      runtime.set_state(heartbeat_t::STATE_DEGRADED, detail);
    } else {
      runtime.set_state(heartbeat_t::STATE_ERROR, fmt::format("no scan for {:.0f} s: {}", silent_s, detail));
    }
    if (last_publish_us.load() > 0)
      runtime.add_processing_time_us(static_cast<double>(last_publish_us.exchange(0)));
  });

  session.start_thread();
  const int rc = runtime.run();
  session.join();  // turns the stream off and stops the measurement, then closes
  return rc;
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  // No default config file: the built-in defaults are the sensor's factory settings.
  refloc::ServiceCommandLine cli("lms100_driver", "SICK LMS100 driver: CoLa-A over TCP -> LMS100_SCAN", "");
  refloc::Options o;
  cli.app.add_option("--host", o.host, "sensor address (our simulator scripts pass 127.0.0.1)")
      ->capture_default_str();
  cli.app.add_option("--port", o.port, "sensor CoLa-A port")->capture_default_str();
  return cli.run(argc, argv, [&] {
    o.config_path = cli.config_path;
    o.lcm_url = cli.lcm_url;
    return refloc::run(o);
  });
}
