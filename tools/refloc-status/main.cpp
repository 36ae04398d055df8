// refloc-status: listen to HEARTBEAT and show every service's state, message
// rates, processing time, errors and heartbeat age; exit 1 when an expected
// service is missing or its heartbeat is older than --max-age.

#include "common/clock.hpp"
#include "common/guarded_main.hpp"
#include "common/lcm_bounded_decode.hpp"
#include "common/lcm_url.hpp"
#include "common/service_runtime.hpp"
#include "heartbeat_from_lcm.hpp"
#include "heartbeat_table.hpp"
#include "refresh_schedule.hpp"
#include "service_instances.hpp"
#include "status_report.hpp"
#include "udp_drop_report.hpp"

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>
#include <refloc/heartbeat_t.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <memory>

namespace refloc {
namespace {

// Signal handlers can only reach static storage; this is the one flag they set.
volatile std::sig_atomic_t g_stop = 0;
void on_signal(int) { g_stop = 1; }

double monotonic_s() { return static_cast<double>(monotonic_us()) * 1e-6; }

struct Listener {
  HeartbeatTable table;
  int64_t decode_errors = 0;
  ServiceInstances instances;  ///< one row per process of a service that runs twice

  std::vector<ServiceStatus> rows(const std::vector<std::string>& expected, double now_s) const {
    auto rows = table.rows(expected, now_s);
    instances.split_duplicates(rows, now_s);
    return rows;
  }

  static void on_heartbeat(const lcm::ReceiveBuffer* rbuf, const std::string&, Listener* self) {
    heartbeat_t m;
    if (!decode_lcm_bounded(rbuf->data, rbuf->data_size, m).ok) {
      ++self->decode_errors;
      return;
    }
    const HeartbeatSample sample = heartbeat_from_lcm(m);
    self->table.update(sample, monotonic_s());
    self->instances.update(sample, monotonic_s());
  }
};

int run(const std::string& lcm_url, const std::vector<std::string>& expected, bool once, double wait_s,
        double max_age_s, bool json) {
  const std::string url = resolve_lcm_url(lcm_url);
  const LcmUrl bus = parse_lcm_url(url, "--lcm-url");
  const int udp_port = bus.provider == "udpm" ? bus.port : 0;  // whose sockets' kernel drops to show
  auto lcm = std::make_unique<lcm::LCM>(url);
  if (!lcm->good())
    throw std::runtime_error("cannot open LCM at '" + url + "' (is there a multicast route?)");
  Listener listener{HeartbeatTable(max_age_s), 0, {}};
  lcm->subscribeFunction("HEARTBEAT", &Listener::on_heartbeat, &listener);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);

  RefreshSchedule schedule(monotonic_s(), once, wait_s);
  while (g_stop == 0 && !schedule.done()) {
    if (schedule.due(monotonic_s())) {
      const auto rows = listener.rows(expected, monotonic_s());
      std::printf("%s", format_status_with_udp_drops(rows, listener.decode_errors, json, !once && !json,
                                                     read_udp_drops(udp_port))
                            .c_str());
      std::fflush(stdout);
    }
    if (schedule.done()) break;
    const double wait_ms = std::min(schedule.seconds_until_due(monotonic_s()) * 1000.0, 100.0);
    lcm->handleTimeout(static_cast<int>(wait_ms) + 1);
  }
  return status_exit_code(listener.rows(expected, monotonic_s()));
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  CLI::App app{
      "Live table of every refloc service from HEARTBEAT; exit 1 when an expected service is missing"};
  std::string lcm_url;
  std::vector<std::string> expected{
      "lms100_driver",    "reflector_extractor", "reflector_matcher", "pose_solver",
      "mecanum_odometry", "pose_fusion",         "navigator",         "robot_sim"};
  bool once = false;
  bool json = false;
  double wait_s = 3.0;
  double max_age_s = 3.0;
  app.add_option("--lcm-url", lcm_url, "LCM URL (default: $LCM_DEFAULT_URL or udpm ttl=0)");
  app.add_option("--expect", expected, "services that must be present, comma separated")
      ->delimiter(',')
      ->capture_default_str();
  app.add_flag("--once", once, "listen for --wait seconds, print once and exit");
  app.add_option("--wait", wait_s, "seconds to listen with --once [s]")
      ->check(CLI::Range(0.1, 3600.0))
      ->capture_default_str();
  app.add_option("--max-age", max_age_s, "a heartbeat older than this counts as missing [s]")
      ->check(CLI::Range(0.1, 3600.0))
      ->capture_default_str();
  app.add_flag("--json", json, "print JSON (one document per refresh) instead of the table");
  CLI11_PARSE(app, argc, argv);
  return refloc::guarded_main("refloc-status",
                              [&] { return refloc::run(lcm_url, expected, once, wait_s, max_age_s, json); });
}
