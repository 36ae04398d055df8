// restart_log_check: reads the LCM log of restart_under_load.sh and the kill
// schedule it wrote, prints one row per SIGKILLed service and checks it:
//   pose gap   the longest silence between consecutive POSE messages (any status;
//              logger receive time) from 0.5 s before the kill to the next kill;
//   restart    kill -> the new process started (its first HEARTBEAT: utime - uptime);
//   to ok      kill -> the new process's first useful output (per service, below);
//   matcher    the restarted matcher's first OK REFLECTOR_MATCHES is MODE_GLOBAL and
//              comes within --max-matcher-ok of the new process's start.
//   restart_log_check --log FILE --kills FILE [--max-pose-gap S] [--max-to-ok S] [--max-matcher-ok S]
// Kill file lines: service old_pid kill_utime new_pid   (utime: us since epoch)

#include "log_reader.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/nav_status_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_matches_t.hpp>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace refloc {
namespace {

struct Kill {
  std::string service;
  int old_pid = 0;
  int64_t kill_utime = 0;
  int new_pid = 0;
};

/// What the analysis needs of one logged message.
struct Event {
  int64_t log_utime = 0;
  std::string channel;
  bool ok = true;       ///< status OK where the message has one; DRIVING/ARRIVED for NAV_STATUS
  int mode = -1;        ///< REFLECTOR_MATCHES mode
  std::string service;  ///< HEARTBEAT
  int pid = 0;
  int64_t start_utime = 0;  ///< HEARTBEAT: utime - uptime
};

template <class T>
std::optional<T> decode(const LogEventView& e) {
  T m;
  if (m.decode(e.data, 0, static_cast<int>(e.size)) < 0) return std::nullopt;
  return m;
}

/// The channel that shows a restarted service doing its job again.
std::string output_channel(const std::string& service) {
  static const std::map<std::string, std::string> channels{
      {"lms100_driver", "LMS100_SCAN"},
      {"reflector_extractor", "REFLECTORS"},
      {"reflector_matcher", "REFLECTOR_MATCHES"},
      {"pose_solver", "LASER_POSE"},
      {"mecanum_odometry", "ODOMETRY"},
      {"pose_fusion", "POSE"},
      {"navigator", "NAV_STATUS"},
      // no output of its own on the bus: its HEARTBEAT OK
      {"web_console", "HEARTBEAT"}};
  const auto it = channels.find(service);
  return it == channels.end() ? "" : it->second;
}

std::vector<Event> read_log(const std::string& path) {
  std::vector<Event> events;
  for_each_log_event(path, [&](const LogEventView& e) {
    Event ev;
    ev.log_utime = e.log_utime;
    ev.channel = *e.channel;
    if (ev.channel == "POSE" || ev.channel == "LASER_POSE") {
      const auto m = decode<pose2d_t>(e);
      if (!m) return;
      ev.ok = m->status == pose2d_t::STATUS_OK;
    } else if (ev.channel == "REFLECTOR_MATCHES") {
      const auto m = decode<reflector_matches_t>(e);
      if (!m) return;
      ev.ok = m->status == reflector_matches_t::STATUS_OK;
      ev.mode = m->mode;
    } else if (ev.channel == "NAV_STATUS") {
      const auto m = decode<nav_status_t>(e);
      if (!m) return;
      ev.ok = m->state == nav_status_t::STATE_DRIVING || m->state == nav_status_t::STATE_ARRIVED;
    } else if (ev.channel == "HEARTBEAT") {
      const auto m = decode<heartbeat_t>(e);
      if (!m) return;
      ev.service = m->service;
      ev.pid = m->pid;
      ev.ok = m->state == heartbeat_t::STATE_OK;
      ev.start_utime = m->utime - m->uptime_us;
    } else if (ev.channel != "LMS100_SCAN" && ev.channel != "REFLECTORS" && ev.channel != "ODOMETRY") {
      return;
    }
    events.push_back(std::move(ev));
  });
  return events;
}

std::vector<Kill> read_kills(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<Kill> kills;
  Kill k;
  while (in >> k.service >> k.old_pid >> k.kill_utime >> k.new_pid) kills.push_back(k);
  return kills;
}

int check(const std::vector<Event>& events, const std::vector<Kill>& kills, double max_pose_gap,
          double max_to_ok, double max_matcher_ok) {
  int failures = 0;
  const auto fail = [&](const std::string& what) {
    fmt::print("FAIL: {}\n", what);
    ++failures;
  };
  fmt::print("{:<20} {:>12} {:>15} {:>11} {:>10}  {}\n", "service", "pose gap ms", "POSE-OK gap ms",
             "restart ms", "to ok ms", "notes");
  for (size_t k = 0; k < kills.size(); ++k) {
    const Kill& kill = kills[k];
    const int64_t from = kill.kill_utime - 500'000;
    const int64_t to = k + 1 < kills.size() ? kills[k + 1].kill_utime : kill.kill_utime + 4'000'000;
    int64_t previous_pose = -1, previous_ok = -1, max_gap = 0, max_ok_gap = 0;
    int64_t new_start = -1;
    std::optional<int64_t> first_output, first_ok_matches;
    int first_ok_mode = -1, global_before_ok = 0, scans_before_ok = 0;
    const std::string channel = output_channel(kill.service);
    for (const Event& e : events) {
      if (e.channel == "HEARTBEAT" && e.service == kill.service && e.pid == kill.new_pid && new_start < 0) {
        new_start = e.start_utime;
      }
      if (e.log_utime < from || e.log_utime > to) continue;
      if (e.channel == "POSE") {
        if (previous_pose >= 0) max_gap = std::max(max_gap, e.log_utime - previous_pose);
        previous_pose = e.log_utime;
        if (e.ok) {
          if (previous_ok >= 0) max_ok_gap = std::max(max_ok_gap, e.log_utime - previous_ok);
          previous_ok = e.log_utime;
        }
      }
    }
    if (previous_pose < 0) fail(fmt::format("{}: no POSE around the kill", kill.service));
    if (new_start < 0) {
      fail(fmt::format("{}: no HEARTBEAT from the new pid {}", kill.service, kill.new_pid));
      new_start = kill.kill_utime;
    }
    for (const Event& e : events) {
      // Messages received after the new process started are its own: the old one was dead before it.
      if (e.channel != channel || e.log_utime <= std::max(new_start, kill.kill_utime) || e.log_utime > to)
        continue;
      if (channel == "HEARTBEAT" && (e.service != kill.service || e.pid != kill.new_pid)) continue;
      if (e.ok && !first_output) first_output = e.log_utime;
      if (kill.service == "reflector_matcher" && !first_ok_matches) {
        ++scans_before_ok;
        if (e.mode == reflector_matches_t::MODE_GLOBAL) ++global_before_ok;
        if (e.ok) {
          first_ok_matches = e.log_utime;
          first_ok_mode = e.mode;
        }
      }
    }
    const double gap_ms = 1e-3 * static_cast<double>(max_gap);
    const double restart_ms = 1e-3 * static_cast<double>(new_start - kill.kill_utime);
    const double to_ok_ms = first_output ? 1e-3 * static_cast<double>(*first_output - kill.kill_utime) : NAN;
    std::string notes;
    if (kill.service == "reflector_matcher" && first_ok_matches) {
      notes = fmt::format("first OK is {} after {} scans ({} global), {:.0f} ms after start",
                          first_ok_mode == reflector_matches_t::MODE_GLOBAL ? "GLOBAL" : "TRACKING",
                          scans_before_ok, global_before_ok,
                          1e-3 * static_cast<double>(*first_ok_matches - new_start));
    }
    fmt::print("{:<20} {:>12.0f} {:>15.0f} {:>11.0f} {:>10.0f}  {}\n", kill.service, gap_ms,
               1e-3 * static_cast<double>(max_ok_gap), restart_ms, to_ok_ms, notes);
    if (gap_ms > max_pose_gap * 1e3)
      fail(fmt::format("{}: POSE gap {:.0f} ms > {:.0f} ms", kill.service, gap_ms, max_pose_gap * 1e3));
    if (!first_output) {
      fail(fmt::format("{}: no OK {} from the restarted process", kill.service, channel));
    } else if (to_ok_ms > max_to_ok * 1e3) {
      fail(fmt::format("{}: OK {} only {:.0f} ms after the kill > {:.0f} ms", kill.service, channel, to_ok_ms,
                       max_to_ok * 1e3));
    }
    if (kill.service == "reflector_matcher") {
      if (!first_ok_matches) {
        fail("reflector_matcher: no OK REFLECTOR_MATCHES after its restart");
      } else {
        if (first_ok_mode != reflector_matches_t::MODE_GLOBAL) {
          fail(
              "reflector_matcher: the first OK after the restart came from tracking, not global "
              "relocalization");
        }
        const double ok_after_start = 1e-6 * static_cast<double>(*first_ok_matches - new_start);
        if (ok_after_start > max_matcher_ok) {
          fail(fmt::format("reflector_matcher: OK {:.2f} s after its start > {:.2f} s", ok_after_start,
                           max_matcher_ok));
        }
      }
    }
  }
  return failures;
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  CLI::App app{"Check an LCM log of restart_under_load.sh against its kill schedule"};
  std::string log_file, kills_file;
  double max_pose_gap = 1.0, max_to_ok = 3.0, max_matcher_ok = 1.0;
  app.add_option("--log", log_file, "LCM log")->required();
  app.add_option("--kills", kills_file, "kill schedule: service old_pid kill_utime new_pid per line")
      ->required();
  app.add_option("--max-pose-gap", max_pose_gap, "[s]")->capture_default_str();
  app.add_option("--max-to-ok", max_to_ok, "kill -> first OK output of the new process [s]")
      ->capture_default_str();
  app.add_option("--max-matcher-ok", max_matcher_ok, "matcher start -> first OK [s]")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    const auto kills = refloc::read_kills(kills_file);
    if (kills.empty()) {
      fmt::print("FAIL: no kills in {}\n", kills_file);
      return 1;
    }
    const auto events = refloc::read_log(log_file);
    const int failures = refloc::check(events, kills, max_pose_gap, max_to_ok, max_matcher_ok);
    fmt::print("{}\n",
               failures == 0 ? "restart checks: PASS" : fmt::format("restart checks: {} FAILED", failures));
    return failures == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "restart_log_check: {}\n", e.what());
    return 2;
  }
}
