#include "hostile_log_model.hpp"

#include "hostile_messages.hpp"
#include "hostile_numbers.hpp"
#include "log_reader.hpp"

#include <fmt/format.h>
#include <refloc/nav_status_t.hpp>

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace refloc::hostile {
namespace {

// CI (sanitized, loaded 2-core host) once logged a 297 ms pause of robot_sim's GROUND_TRUTH and an
// OK POSE stamped inside it, which the 0.25 s this was then could not judge. Interpolated across
// 0.5 s at the mission's 1 m/s and 1 rad/s the truth is within 31 mm (the chord's sagitta), far
// inside the 0.1 m bound.
constexpr int64_t kMaxTruthGapUs = 500'000;

template <class Message>
bool decode(Message& m, const LogEventView& e) {
  try {  // the stack's own messages; a broken publisher must not end the check
    return m.decode(e.data, 0, static_cast<int>(e.size)) >= 0;
  } catch (const std::exception&) {
    return false;
  }
}

/// Decodes one stack message, tallies its non-finite values; returns false if it does not decode.
template <class Message>
bool tally(LogModel& model, const LogEventView& e, Message& m) {
  auto& t = model.channels[*e.channel];
  if (!decode(m, e)) {
    ++t.undecodable;
    return false;
  }
  ++t.checked;
  const std::string bad = first_non_finite(m);
  if (!bad.empty() && t.non_finite++ == 0) {
    t.first_non_finite = fmt::format("{}.{}", Message::getTypeName(), bad);
    t.first_non_finite_utime = e.log_utime;
  }
  return true;
}

template <class Message>
void tally(LogModel& model, const LogEventView& e) {
  Message m;
  tally(model, e, m);
}

void read_stack_message(LogModel& model, const LogEventView& e) {
  const std::string& ch = *e.channel;
  if (ch == "POSE" || ch == "LASER_POSE" || ch == "GROUND_TRUTH") {
    pose2d_t p;
    if (!tally(model, e, p)) return;
    if (ch == "GROUND_TRUTH") model.truth.push_back({p.utime, {p.x, p.y}});
    if (ch != "GROUND_TRUTH" && p.status == pose2d_t::STATUS_OK)
      model.ok_poses.push_back({ch, p.utime, e.log_utime, p.x, p.y});
  } else if (ch == "HEARTBEAT") {
    heartbeat_t h;
    if (!tally(model, e, h)) return;
    Heartbeat beat{h.utime, h.pid, h.state, h.state_detail, h.decode_errors, {}};
    for (size_t i = 0; i < h.counter_names.size() && i < h.counter_values.size(); ++i)
      beat.counters[h.counter_names[i]] = h.counter_values[i];
    model.heartbeats[h.service].push_back(beat);
    model.pids[h.service].insert(h.pid);
  } else if (ch == "LMS100_SCAN") {
    tally<laser_scan_t>(model, e);
  } else if (ch == "REFLECTORS") {
    tally<reflector_detections_t>(model, e);
  } else if (ch == "REFLECTOR_MATCHES") {
    tally<reflector_matches_t>(model, e);
  } else if (ch == "ODOMETRY") {
    tally<odometry_t>(model, e);
  } else if (ch == "WHEEL_ENCODERS") {
    tally<wheel_encoders_t>(model, e);
  } else if (ch == "CMD_VEL") {
    tally<twist_t>(model, e);
  } else if (ch == "NAV_GOAL") {
    tally<nav_goal_t>(model, e);
  } else if (ch == "NAV_STATUS") {
    tally<nav_status_t>(model, e);
  } else if (ch == "REFLECTOR_CLUSTERS") {
    tally<reflector_clusters_t>(model, e);
  } else if (ch == "MAP_HEALTH") {
    tally<map_health_t>(model, e);
  } else if (ch != "LCM_SELF_TEST") {  // LCM's own start-up probe, not ours
    ++model.channels[ch].undecodable;  // a channel nobody documented: worth a look
  }
}

/// NAV_GOAL and CMD_VEL stamps are read by nobody: the navigator and robot_sim act on a goal or
/// a command when it arrives (robot_sim's command timeout runs on its own clock). A far stamp
/// there is sent (the mission and the alive checks see it is harmless) but is no rejection.
bool stamp_unused_by_consumer(const std::string& channel, const std::string& what) {
  return (channel == "NAV_GOAL" || channel == "CMD_VEL") && what.find(".utime=") != std::string::npos;
}

std::vector<Phase> read_record(const std::string& path, std::set<uint64_t>& hashes) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the hostile peer's record");
  std::vector<Phase> phases;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string utime, phase, channel, what, hash;
    if (!std::getline(fields, utime, '\t') || !std::getline(fields, phase, '\t') ||
        !std::getline(fields, channel, '\t') || !std::getline(fields, what, '\t') ||
        !std::getline(fields, hash, '\t'))
      throw std::runtime_error(path + ": malformed line: " + line);
    hashes.insert(std::stoull(hash, nullptr, 16));
    const int64_t t = std::stoll(utime);
    if (phases.empty() || phases.back().name != phase) phases.push_back({phase, t, t, {}});
    phases.back().last_utime = t;
    if (stamp_unused_by_consumer(channel, what)) {
      ++phases.back().harmless_sent;
      continue;
    }
    ++phases.back().sent_per_channel[channel];
  }
  return phases;
}

bool is_rejection_counter(const std::string& name) {
  static const std::regex rejection(kRejectionCounter, std::regex::ECMAScript | std::regex::icase);
  static const std::regex not_input(kNotInputRejection, std::regex::ECMAScript | std::regex::icase);
  return std::regex_search(name, rejection) && !std::regex_search(name, not_input);
}

int64_t rejections(const Heartbeat& h) {
  int64_t sum = h.decode_errors;
  for (const auto& [name, value] : h.counters)
    if (is_rejection_counter(name)) sum += value;
  return sum;
}

}  // namespace

std::string LogModel::phase_at(int64_t utime) const {
  if (phases.empty() || utime < phases.front().first_utime) return "before the peer";
  std::string name = phases.front().name;
  for (const auto& p : phases)
    if (p.first_utime <= utime) name = p.name;
  if (utime > phases.back().last_utime + 3'000'000) return "after the peer";
  return "during " + name;
}

std::optional<double> LogModel::truth_error_m(const OkPose& p) const {
  // GROUND_TRUTH comes at 100 Hz; on a loaded host it pauses (kMaxTruthGapUs). A pose further
  // from any truth sample than that was stamped with a time the robot never had.
  const auto hi = std::lower_bound(truth.begin(), truth.end(), p.utime,
                                   [](const auto& sample, int64_t t) { return sample.first < t; });
  if (hi == truth.end() || hi == truth.begin()) return std::nullopt;
  const auto lo = std::prev(hi);
  if (hi->first - lo->first > kMaxTruthGapUs) return std::nullopt;
  const double span = static_cast<double>(hi->first - lo->first);
  const double a = span > 0 ? static_cast<double>(p.utime - lo->first) / span : 0.0;
  const double x = lo->second.first + a * (hi->second.first - lo->second.first);
  const double y = lo->second.second + a * (hi->second.second - lo->second.second);
  return std::hypot(p.x - x, p.y - y);
}

Growth LogModel::rejection_growth(const std::string& service, const Phase& phase) const {
  const auto it = heartbeats.find(service);
  if (it == heartbeats.end()) return {0, "no HEARTBEAT"};
  const Heartbeat* before = nullptr;
  const Heartbeat* after = nullptr;
  for (const auto& h : it->second) {
    if (h.utime <= phase.first_utime) before = &h;
    if (!after && h.utime >= phase.last_utime + 200'000) after = &h;
  }
  if (!before) return {0, "no HEARTBEAT before"};
  if (!after) return {0, "no HEARTBEAT after"};
  if (before->pid != after->pid) return {0, "restarted"};
  return {rejections(*after) - rejections(*before), ""};
}

std::map<std::string, std::string> LogModel::grown_counters() const {
  std::map<std::string, std::string> grown;
  for (const auto& [service, beats] : heartbeats) {
    const Heartbeat& first = beats.front();
    const Heartbeat& last = beats.back();
    std::string text;
    if (last.decode_errors > first.decode_errors)
      text += fmt::format("decode_errors +{}* ", last.decode_errors - first.decode_errors);
    for (const auto& [name, value] : last.counters) {
      const auto old = first.counters.find(name);
      const int64_t delta = value - (old == first.counters.end() ? 0 : old->second);
      if (delta > 0) text += fmt::format("{} +{}{} ", name, delta, is_rejection_counter(name) ? "*" : "");
    }
    grown[service] = text.empty() ? "(none)" : text;
  }
  return grown;
}

std::string LogModel::last_state(const std::string& service) const {
  static const char* const kNames[] = {"STARTING", "OK", "DEGRADED", "ERROR", "STOPPING"};
  const auto it = heartbeats.find(service);
  if (it == heartbeats.end()) return "(no HEARTBEAT)";
  const Heartbeat& h = it->second.back();
  const std::string name = h.state >= 0 && h.state <= 4 ? kNames[h.state] : std::to_string(h.state);
  return h.detail.empty() ? name : name + " (" + h.detail + ")";
}

LogModel read_log_model(const std::string& log_file, const std::string& record_file) {
  LogModel model;
  std::set<uint64_t> hostile;
  model.phases = read_record(record_file, hostile);
  model.hostile_sent = static_cast<int64_t>(hostile.size());
  std::set<uint64_t> logged;
  for_each_log_event(log_file, [&](const LogEventView& e) {
    const uint64_t hash = datagram_hash(e.data, e.size);
    if (hostile.count(hash) != 0) {
      logged.insert(hash);
      return;
    }
    ++model.stack_messages;
    read_stack_message(model, e);
  });
  model.hostile_logged = static_cast<int64_t>(logged.size());
  std::sort(model.truth.begin(), model.truth.end());
  return model;
}

}  // namespace refloc::hostile
