// hostile_log_check: reads the LCM log of hostile_bus_mission.sh and the hostile peer's record
// of what it sent, and checks what the stack did with it:
//   poison     no non-finite number in any message on any channel, except the peer's own
//              datagrams (recognized by their FNV-1a hash from the record: the peer writes to
//              the stack's input channels, so channel alone cannot tell);
//   pose       no POSE / LASER_POSE with status OK more than --max-ok-error-m from
//              GROUND_TRUTH interpolated at its utime, and none stamped where there is no
//              GROUND_TRUTH (a clock lie passed through);
//   counted    per phase and receiving service: HEARTBEAT decode_errors plus its rejection
//              counters (names matching kRejectionCounter) grow by at least the datagrams
//              of that phase on the channels it subscribes to (kSubscriptions, as in
//              deploy/config/*.json), between its last HEARTBEAT before the phase's first
//              datagram and its first HEARTBEAT 0.2 s after the last one;
//   alive      one pid per service over the whole log.
//   hostile_log_check --log FILE --record FILE [--max-ok-error-m M]
// Prints one table per check and "FAIL <check> <service/channel> <phase>: why" per failure.

#include "hostile_log_model.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

namespace refloc::hostile {
namespace {

int check_poison(const LogModel& log) {
  int failures = 0;
  fmt::print("\n== non-finite values on the stack's messages (peer's own excluded)\n");
  fmt::print("{:<20} {:>8} {:>10}  first\n", "channel", "checked", "nonfinite");
  for (const auto& [channel, c] : log.channels) {
    fmt::print("{:<20} {:>8} {:>10}  {}\n", channel, c.checked, c.non_finite, c.first_non_finite);
    if (c.non_finite > 0) {
      fmt::print("FAIL poison {} {}: {} messages with a non-finite value, first {}\n", channel,
                 log.phase_at(c.first_non_finite_utime), c.non_finite, c.first_non_finite);
      ++failures;
    }
    if (c.undecodable > 0) {
      fmt::print("FAIL poison {}: {} messages of the stack that do not decode\n", channel, c.undecodable);
      ++failures;
    }
  }
  return failures;
}

int check_poses(const LogModel& log, double max_error_m) {
  int failures = 0;
  fmt::print("\n== status OK poses vs GROUND_TRUTH (max {:.3f} m)\n", max_error_m);
  fmt::print("{:<12} {:>8} {:>12} {:>10} {:>12}\n", "channel", "ok", "max err [m]", "too far", "no truth");
  for (const std::string channel : {"POSE", "LASER_POSE"}) {
    int ok = 0, far = 0, untimed = 0, unjudged = 0;
    double worst = 0.0;
    std::string first;
    for (const auto& p : log.ok_poses) {
      if (p.channel != channel) continue;
      // While `refloc stop` ends the programs one by one, robot_sim (the referee) may go first:
      // a pose stamped after its last GROUND_TRUTH is counted and printed, not judged.
      if (log.outside_truth_span(p)) {
        ++unjudged;
        continue;
      }
      ++ok;
      const auto error = log.truth_error_m(p);
      if (!error) ++untimed;
      if (error) worst = std::max(worst, *error);
      if (error && !(*error <= max_error_m)) ++far;
      if (first.empty() && (!error || !(*error <= max_error_m)))
        first = fmt::format("utime {} = logged {:+.3f} s ({}): {}", p.utime, (p.utime - p.log_utime) * 1e-6,
                            log.phase_at(p.log_utime),
                            error ? fmt::format("{:.3f} m off", *error) : "no GROUND_TRUTH at that stamp");
    }
    fmt::print("{:<12} {:>8} {:>12.4f} {:>10} {:>12}\n", channel, ok, worst, far, untimed);
    if (unjudged > 0)
      fmt::print("{:<12} {} OK poses stamped before the first or after the last GROUND_TRUTH: not judged\n",
                 channel, unjudged);
    if (far + untimed > 0) {
      fmt::print("FAIL pose {}: {} OK poses too far, {} stamped where there is no truth; first {}\n", channel,
                 far, untimed, first);
      ++failures;
    }
  }
  return failures;
}

int check_counted(const LogModel& log) {
  std::vector<std::string> failures;
  fmt::print(
      "\n== rejections counted in HEARTBEAT: datagrams sent to the service / counted (decode_errors + "
      "rejection counters); ! = fewer counted than sent\n");
  fmt::print("{:<28}", "phase");
  for (const auto& [service, channels] : kSubscriptions) fmt::print(" {:>19}", service);
  fmt::print("\n");
  for (const auto& phase : log.phases) {
    fmt::print("{:<28}", phase.name);
    for (const auto& [service, channels] : kSubscriptions) {
      int sent = 0;
      for (const auto& ch : channels) sent += phase.sent_on(ch);
      const auto growth = log.rejection_growth(service, phase);
      const std::string counted =
          growth.why_unknown.empty() ? std::to_string(growth.counted) : growth.why_unknown;
      const bool short_count = sent > 0 && (!growth.why_unknown.empty() || growth.counted < sent);
      fmt::print(" {:>19}", sent == 0 ? "-" : fmt::format("{}/{}{}", sent, counted, short_count ? " !" : ""));
      if (short_count)
        failures.push_back(fmt::format("FAIL counted {} {}: {} hostile datagrams on {}, counted {}", service,
                                       phase.name, sent, fmt::join(channels, ","), counted));
    }
    fmt::print("\n");
  }
  int heartbeat_sent = 0;
  for (const auto& p : log.phases) heartbeat_sent += p.sent_on("HEARTBEAT");
  fmt::print(
      "HEARTBEAT: {} hostile datagrams, read by every service runtime (counter unreadable_heartbeats)\n",
      heartbeat_sent);
  fmt::print("\ncounters that grew during the run, per service (* = counted as rejections):\n");
  for (const auto& [service, names] : log.grown_counters()) fmt::print("  {:<20} {}\n", service, names);
  for (const auto& f : failures) fmt::print("{}\n", f);
  return static_cast<int>(failures.size());
}

int check_alive(const LogModel& log) {
  int failures = 0;
  fmt::print("\n== one process per service over the whole log\n");
  for (const auto& [service, channels] : kSubscriptions) {
    const auto it = log.pids.find(service);
    const size_t n = it == log.pids.end() ? 0 : it->second.size();
    fmt::print("{:<20} pids {}  last state {}\n", service,
               n == 0 ? "none" : fmt::format("{}", fmt::join(it->second, ",")), log.last_state(service));
    if (n != 1) {
      fmt::print("FAIL alive {}: {} processes in the log (died and restarted, or never ran)\n", service, n);
      ++failures;
    }
  }
  return failures;
}

}  // namespace
}  // namespace refloc::hostile

int main(int argc, char** argv) {
  CLI::App app{"Check an LCM log of the hostile-bus mission against the hostile peer's record"};
  std::string log_file, record_file;
  double max_ok_error_m = 0.1;
  app.add_option("--log", log_file, "LCM log (lcm-logger)")->required();
  app.add_option("--record", record_file, "hostile_peer --record file")->required();
  app.add_option("--max-ok-error-m", max_ok_error_m, "largest OK pose error vs GROUND_TRUTH [m]")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  try {
    using namespace refloc::hostile;
    const LogModel log = read_log_model(log_file, record_file);
    fmt::print("hostile datagrams: {} sent, {} in the log; {} stack messages checked\n", log.hostile_sent,
               log.hostile_logged, log.stack_messages);
    int failures =
        check_poison(log) + check_poses(log, max_ok_error_m) + check_counted(log) + check_alive(log);
    if (log.hostile_logged < log.hostile_sent) {
      fmt::print("FAIL delivery: only {} of {} hostile datagrams reached lcm-logger\n", log.hostile_logged,
                 log.hostile_sent);
      ++failures;
    }
    fmt::print("\nhostile_log_check: {} failure(s)\n", failures);
    return failures == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "hostile_log_check: {}\n", e.what());
    return 2;
  }
}
