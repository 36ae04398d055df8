// refloc-status: listen to HEARTBEAT, POSE and LASER_POSE and show every service's state,
// message rates, processing time, errors and heartbeat age, and the robot's pose; exit 1 when
// an expected service is missing or stale, a service is in ERROR, or one runs twice.

#include "common/clock.hpp"
#include "common/guarded_main.hpp"
#include "common/lcm_bounded_decode.hpp"
#include "common/lcm_url.hpp"
#include "common/program_version.hpp"
#include "common/service_runtime.hpp"
#include "heartbeat_from_lcm.hpp"
#include "heartbeat_table.hpp"
#include "pose_watch.hpp"
#include "refresh_schedule.hpp"
#include "service_instances.hpp"
#include "status_report.hpp"
#include "udp_drop_report.hpp"

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/pose2d_t.hpp>

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

struct Options {
  std::string lcm_url;
  std::vector<std::string> expected{"lms100_driver", "reflector_extractor", "reflector_matcher",
                                    "pose_solver",   "mecanum_odometry",    "pose_fusion",
                                    "navigator",     "robot_sim",           "web_console"};
  bool once = false;
  double wait_s = 3.0;
  double max_age_s = 3.0;
  PageStyle style;
  std::string pose_channel = "POSE";
  std::string laser_pose_channel = "LASER_POSE";
};

struct Listener {
  HeartbeatTable table;
  PoseWatch pose;
  int64_t decode_errors = 0;   ///< undecodable HEARTBEATs
  ServiceInstances instances;  ///< one row per process of a service that runs twice

  StatusPage page(const std::vector<std::string>& expected, double now_s) const {
    StatusPage p{table.rows(expected, now_s), decode_errors, pose.report(now_s)};
    instances.split_duplicates(p.rows, now_s);
    return p;
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
  static void on_pose(const lcm::ReceiveBuffer* rbuf, const std::string&, Listener* self) {
    pose2d_t m;
    if (!decode_lcm_bounded(rbuf->data, rbuf->data_size, m).ok) return;
    PoseSample p{m.utime, m.x, m.y, m.theta, {}, m.status};
    std::copy(std::begin(m.covariance), std::end(m.covariance), p.covariance.begin());
    self->pose.on_pose(p, monotonic_s());
  }
  static void on_laser_pose(const lcm::ReceiveBuffer* rbuf, const std::string&, Listener* self) {
    pose2d_t m;
    if (decode_lcm_bounded(rbuf->data, rbuf->data_size, m).ok)
      self->pose.on_laser_pose(m.status, monotonic_s());
  }
};

int run(const Options& o) {
  const std::string url = resolve_lcm_url(o.lcm_url);
  const LcmUrl bus = parse_lcm_url(url, "--lcm-url");
  const int udp_port = bus.provider == "udpm" ? bus.port : 0;  // whose sockets' kernel drops to show
  auto lcm = std::make_unique<lcm::LCM>(url);
  if (!lcm->good())
    throw std::runtime_error("cannot open LCM at '" + url + "' (is there a multicast route?)");
  Listener listener{HeartbeatTable(o.max_age_s), PoseWatch(monotonic_s(), o.max_age_s), 0, {}};
  lcm->subscribeFunction("HEARTBEAT", &Listener::on_heartbeat, &listener);
  lcm->subscribeFunction(o.pose_channel, &Listener::on_pose, &listener);
  lcm->subscribeFunction(o.laser_pose_channel, &Listener::on_laser_pose, &listener);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  PageStyle style = o.style;
  style.clear_screen = !o.once && !o.style.json;
  RefreshSchedule schedule(monotonic_s(), o.once, o.wait_s);
  while (g_stop == 0 && !schedule.done()) {
    if (schedule.due(monotonic_s())) {
      const StatusPage page = listener.page(o.expected, monotonic_s());
      std::printf("%s", format_status_with_udp_drops(page, style, read_udp_drops(udp_port)).c_str());
      std::fflush(stdout);
    }
    if (schedule.done()) break;
    const double wait_ms = std::min(schedule.seconds_until_due(monotonic_s()) * 1000.0, 100.0);
    lcm->handleTimeout(static_cast<int>(wait_ms) + 1);
  }
  return status_exit_code(listener.page(o.expected, monotonic_s()).rows);
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  CLI::App app{
      "Live table of every refloc service from HEARTBEAT and the robot's pose; exit 1 when an "
      "expected service is missing or stale, or a service is in ERROR"};
  refloc::add_version_flag(app, "refloc-status");
  refloc::Options o;
  app.add_option("--lcm-url", o.lcm_url, "LCM URL (default: $LCM_DEFAULT_URL or udpm ttl=0)");
  app.add_option("--expect", o.expected, "services that must be present, comma separated")
      ->delimiter(',')
      ->capture_default_str();
  app.add_flag("--once", o.once, "listen for --wait seconds, print once and exit");
  app.add_option("--wait", o.wait_s, "seconds to listen with --once [s]")
      ->check(CLI::Range(0.1, 3600.0))
      ->capture_default_str();
  app.add_option("--max-age", o.max_age_s, "a heartbeat or POSE older than this counts as stale [s]")
      ->check(CLI::Range(0.1, 3600.0))
      ->capture_default_str();
  app.add_flag("--wide", o.style.wide,
               "every column (p50, error and normal counters, full detail), any width");
  app.add_flag("--json", o.style.json, "print JSON (one document per refresh) instead of the table");
  app.add_option("--pose-channel", o.pose_channel, "channel of the fused pose")->capture_default_str();
  app.add_option("--laser-pose-channel", o.laser_pose_channel, "channel of the laser fixes")
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  return refloc::guarded_main("refloc-status", [&] { return refloc::run(o); });
}
