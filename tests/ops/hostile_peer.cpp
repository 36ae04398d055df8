// hostile_peer: a hostile (or merely buggy) peer on the live bus of hostile_bus_mission.sh. It
// listens to the real traffic, and sends every recipe of hostile_plan() built from the latest
// real message of its channel, in bursts (a few a second, interleaved with the real traffic,
// not a flood), phase after phase with a pause between phases so the log check can attribute
// HEARTBEAT counter growth to one phase. Every datagram sent is recorded (TSV: send utime,
// phase, channel, what, FNV-1a hash, size) so the log check can tell the peer's messages from
// the stack's on the same channels.
//   hostile_peer --record FILE [--lcm-url URL] [--rate HZ] [--burst N] [--phase-gap-s S]

#include "hostile_messages.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>

namespace refloc {
namespace {

int64_t now_us() {
  using namespace std::chrono;
  return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
}

/// Keeps the latest real message of every input channel as the base of the next hostile one.
class Listener {
 public:
  explicit Listener(Bases& bases) : bases_(bases) {}
  std::set<uint64_t> sent;
  std::map<std::string, int64_t> real_seen;

  void on_message(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
    const auto* data = static_cast<const uint8_t*>(rbuf->data);
    if (sent.count(datagram_hash(data, rbuf->data_size)) != 0) return;  // our own echo
    const int size = static_cast<int>(rbuf->data_size);
    if (channel == "LMS100_SCAN") take(bases_.scan, data, size, channel);
    if (channel == "LASER_POSE") take(bases_.laser_pose, data, size, channel);
    if (channel == "POSE") take(bases_.pose, data, size, channel);
    if (channel == "ODOMETRY") take(bases_.odometry, data, size, channel);
    if (channel == "WHEEL_ENCODERS") take(bases_.encoders, data, size, channel);
    if (channel == "CMD_VEL") take(bases_.command, data, size, channel);
    reflector_detections_t d;
    if (channel == "REFLECTORS" && decodes(d, data, size) && d.nreflectors > 0)
      keep(bases_.detections, d, channel);
    reflector_matches_t m;
    if (channel == "REFLECTOR_MATCHES" && decodes(m, data, size) && m.nmatches > 0)
      keep(bases_.matches, m, channel);
    nav_goal_t g;
    if (channel == "NAV_GOAL" && decodes(g, data, size) && g.nwaypoints > 0) keep(bases_.goal, g, channel);
  }

 private:
  template <class Message>
  static bool decodes(Message& m, const uint8_t* data, int size) {
    try {  // real traffic only (our own datagrams are filtered above), but a test tool must not die of it
      return m.decode(data, 0, size) >= 0;
    } catch (const std::exception&) {
      return false;
    }
  }
  template <class Message>
  void keep(Message& base, const Message& m, const std::string& channel) {
    base = m;
    ++real_seen[channel];
  }
  template <class Message>
  void take(Message& base, const uint8_t* data, int size, const std::string& channel) {
    Message m;
    if (decodes(m, data, size)) keep(base, m, channel);
  }
  Bases& bases_;
};

void handle_until(lcm::LCM& lcm, int64_t until_us) {
  for (int64_t now = now_us(); now < until_us; now = now_us())
    lcm.handleTimeout(static_cast<int>(std::max<int64_t>(1, (until_us - now) / 1000)));
}

int run(const std::string& url, const std::string& record_file, double rate_hz, int burst, double gap_s) {
  lcm::LCM lcm(url);
  if (!lcm.good()) throw std::runtime_error("hostile_peer: no LCM on " + url);
  Bases bases = synthetic_bases(now_us());
  Listener listener(bases);
  lcm.subscribe(".*", &Listener::on_message, &listener);
  std::ofstream record(record_file);
  if (!record) throw std::runtime_error("hostile_peer: cannot write " + record_file);
  handle_until(lcm, now_us() + 1'000'000);  // one second of real traffic for the bases
  const auto burst_period_us = static_cast<int64_t>(1e6 * burst / rate_hz);
  std::map<std::string, int> per_phase;
  for (const auto& phase : hostile_plan()) {
    int64_t next_burst = now_us();
    for (size_t i = 0; i < phase.recipes.size(); ++i) {
      if (i % static_cast<size_t>(burst) == 0) {
        handle_until(lcm, next_burst);
        next_burst += burst_period_us;
      }
      const auto& recipe = phase.recipes[i];
      const int64_t t = now_us();
      const auto bytes = recipe.build(bases, t);
      const uint64_t hash = datagram_hash(bytes.data(), bytes.size());
      listener.sent.insert(hash);
      if (lcm.publish(recipe.channel, bytes.data(), static_cast<unsigned>(bytes.size())) != 0)
        throw std::runtime_error("hostile_peer: publish failed on " + recipe.channel);
      record << fmt::format("{}\t{}\t{}\t{}\t{:016x}\t{}\n", t, phase.name, recipe.channel, recipe.what, hash,
                            bytes.size());
      ++per_phase[phase.name];
    }
    record.flush();
    handle_until(lcm, now_us() + static_cast<int64_t>(gap_s * 1e6));
  }
  int total = 0;
  for (const auto& [name, n] : per_phase) {
    fmt::print("hostile_peer: phase {:<28} {:>4} datagrams\n", name, n);
    total += n;
  }
  for (const auto& [channel, n] : listener.real_seen)
    fmt::print("hostile_peer: real base messages seen on {:<18} {:>6}\n", channel, n);
  fmt::print("hostile_peer: {} hostile datagrams sent, recorded in {}\n", total, record_file);
  return 0;
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  CLI::App app{"Send hostile LCM messages (lying lengths, non-finite values, bad stamps, absurd twists)"};
  std::string url = "udpm://239.255.76.67:7667?ttl=0", record;
  double rate_hz = 8.0, gap_s = 2.0;
  int burst = 4;
  app.add_option("--lcm-url", url, "LCM URL")->capture_default_str();
  app.add_option("--record", record, "TSV file of every datagram sent")->required();
  app.add_option("--rate", rate_hz, "hostile datagrams per second [Hz]")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--burst", burst, "datagrams sent back to back")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--phase-gap-s", gap_s, "pause between phases [s]")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  try {
    return refloc::run(url, record, rate_hz, burst, gap_s);
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}\n", e.what());
    return 1;
  }
}
