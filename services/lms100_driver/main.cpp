// lms100_driver: a SICK LMS100 over CoLa-A/TCP → LMS100_SCAN (laser_scan_t), with
// reconnects forever, implausible scans refused, and the link's counters in HEARTBEAT.
//
// The session blocks in poll() on its own thread and publishes each scan from
// there (lcm::LCM::publish is thread-safe); the ServiceRuntime loop on the main
// thread copies LinkHealth's verdict and the counters into the heartbeat.

#include <CLI/CLI.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/laser_scan_t.hpp>
#include <string>

#include "common/clock.hpp"
#include "common/lcm_conversions.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "lms100_driver/driver_config_file.hpp"
#include "lms100_driver/link_health.hpp"
#include "lms100_driver/lms100_session.hpp"

namespace refloc {
namespace {

struct Options {
  std::string host = "192.168.0.1";
  uint16_t port = 2111;
  std::string config_path;
  std::string lcm_url;
};

int8_t to_heartbeat_state(LinkLevel level) {
  if (level == LinkLevel::kOk) return heartbeat_t::STATE_OK;
  return level == LinkLevel::kDegraded ? heartbeat_t::STATE_DEGRADED : heartbeat_t::STATE_ERROR;
}

void log_state(SessionState state, const std::string& detail) {
  if (state == SessionState::kBackoff) return spdlog::warn("{}", detail);
  spdlog::info("{}: {}", to_string(state), detail);
}

int run(const Options& options) {
  DriverServiceConfig config = load_driver_config_file(options.config_path);
  config.session.host = options.host;
  config.session.port = options.port;
  ServiceRuntime runtime("lms100_driver", options.lcm_url);
  lcm::LCM& lcm = runtime.lcm();
  LinkHealth health(config.error_after_s, monotonic_us());

  Lms100Session session(
      config.session,
      [&](const LaserScan& scan) {
        const int64_t t0 = monotonic_us();
        laser_scan_t msg = to_lcm(scan);
        const bool published = lcm.publish(config.output_channel, &msg) == 0;
        const int64_t t1 = monotonic_us();
        health.on_scan_published(t1, t1 - t0, published);
      },
      [&](SessionState state, const std::string& detail) {
        health.on_state(state, detail);
        log_state(state, detail);
      });
  session.set_reject_callback([&](const ScanPlausibility& refused) {
    if (const auto line = health.on_scan_rejected(monotonic_us(), refused.detail); !line.empty())
      spdlog::warn("{}", line);
  });

  runtime.add_periodic(0.25, [&] {
    for (const auto& [name, value] : link_counters(session.counters(), health.publish_failures()))
      runtime.counter(name) = value;
    const LinkVerdict verdict = health.verdict(monotonic_us());
    runtime.set_state(to_heartbeat_state(verdict.level), verdict.detail);
    const int64_t publish_us = health.take_publish_time_us();
    if (publish_us > 0) runtime.add_processing_time_us(static_cast<double>(publish_us));
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
