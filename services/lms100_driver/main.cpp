// lms100_driver: a SICK LMS1xx/LMS5xx/TiM over CoLa-A or CoLa-B/TCP -> LMS100_SCAN, reconnecting forever.
// The session thread queues scans; the ServiceRuntime loop publishes them (HEARTBEAT counts them).

#include <CLI/CLI.hpp>
#include <refloc/heartbeat_t.hpp>
#include <string>
#include "common/clock.hpp"
#include "common/lcm_conversions.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "lms100_driver/driver_config_file.hpp"
#include "lms100_driver/link_health.hpp"
#include "lms100_driver/lms100_session.hpp"
#include "lms100_driver/scan_handoff.hpp"

namespace refloc {
namespace {

struct Options {
  std::string host, config_path, lcm_url;  ///< host "" = /host of the config file
  uint16_t port = 0;                       ///< 0 = /port of the config file
};

/// How often the runtime loop publishes queued scans [s]: it waits in LCM and cannot be woken
/// by the session thread, so this bounds the added latency (2 ms, a tenth of a 50 Hz period).
constexpr double kPublishPeriodS = 0.002;

int8_t to_heartbeat_state(LinkLevel level) {
  if (level == LinkLevel::kOk) return heartbeat_t::STATE_OK;
  return level == LinkLevel::kDegraded ? heartbeat_t::STATE_DEGRADED : heartbeat_t::STATE_ERROR;
}

void log_state(SessionState state, const std::string& detail) {
  if (state == SessionState::kBackoff) return spdlog::warn("{}", detail);
  spdlog::info("{}: {}", to_string(state), detail);
}

void publish_queued(ServiceRuntime& runtime, ScanHandoff& handoff, LinkHealth& health,
                    const std::string& channel) {
  handoff.drain([&](const LaserScan& scan) {
    const int64_t t0 = monotonic_us();
    const bool published = runtime.publish(channel, to_lcm(scan));
    const int64_t t1 = monotonic_us();
    health.on_scan_published(t1, t1 - t0, published);
    runtime.add_processing_time_us(static_cast<double>(t1 - t0));
  });
}

void report_link(ServiceRuntime& runtime, const Lms100Session& session, const LinkHealth& health,
                 const ScanHandoff& handoff) {
  for (const auto& [name, value] : link_counters(session.counters(), health.publish_failures()))
    runtime.counter(name) = value;
  runtime.counter("publish_queue_dropped") = static_cast<int64_t>(handoff.dropped());
  const LinkVerdict verdict = health.verdict(monotonic_us());
  runtime.set_state(to_heartbeat_state(verdict.level), verdict.detail);
}

int run(const Options& options) {
  DriverServiceConfig config = load_driver_config_file(options.config_path);
  if (!options.host.empty()) config.session.host = options.host;
  if (options.port != 0) config.session.port = options.port;
  ServiceRuntime runtime("lms100_driver", options.lcm_url);
  LinkHealth health(config.error_after_s, monotonic_us());
  ScanHandoff handoff;
  Lms100Session session(
      config.session, [&](const LaserScan& scan) { handoff.push(scan); },
      [&](SessionState state, const std::string& detail) {
        health.on_state(state, detail);
        log_state(state, detail);
      });
  session.set_reject_callback([&](const ScanPlausibility& refused) {
    if (const auto line = health.on_scan_rejected(monotonic_us(), refused.detail); !line.empty())
      spdlog::warn("{}", line);
  });
  runtime.add_periodic(kPublishPeriodS,
                       [&] { publish_queued(runtime, handoff, health, config.output_channel); });
  runtime.add_periodic(0.25, [&] { report_link(runtime, session, health, handoff); });
  session.start_thread();
  const int rc = runtime.run();
  session.join();  // turns the stream off and stops the measurement, then closes
  return rc;
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli("lms100_driver",
                                 "SICK laser scanner driver: CoLa-A/B over TCP -> LMS100_SCAN", "");
  refloc::Options o;
  cli.app.add_option("--host", o.host, "sensor address; overrides /host of the config (default 192.168.0.1)");
  cli.app.add_option("--port", o.port, "sensor TCP port; overrides /port (default 2111 CoLa-A, 2112 CoLa-B)")
      ->check(CLI::Range(1, 65535));
  cli.set_config_reader([](const refloc::JsonConfig& f) { refloc::parse_driver_config(f); });
  return cli.run(argc, argv, [&] {
    o.config_path = cli.config_path;
    o.lcm_url = cli.lcm_url;
    return refloc::run(o);
  });
}
