#include "status_report.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace refloc {
namespace {

std::string state_column(const ServiceStatus& s) {
  if (!s.seen) return "MISSING";
  const std::string name = heartbeat_state_name(s.last.state);
  return s.stale ? "STALE:" + name : name;
}

std::string rate_column(double rate_hz, bool known) { return known ? fmt::format("{:.1f}", rate_hz) : "-"; }

/// Decode errors first, then the service's own non-zero counters (name=value).
std::string errors_column(const ServiceStatus& s) {
  std::string text = fmt::format("{}", s.last.decode_errors);
  for (const auto& [name, value] : s.last.counters) {
    if (value != 0) text += fmt::format(" {}={}", name, value);
  }
  return text;
}

}  // namespace

std::string format_status_table(const std::vector<ServiceStatus>& rows) {
  std::string out =
      fmt::format("{:<20} {:>8} {:<14} {:>8} {:>8} {:>9} {:>9} {:>6}  {:<24} {}\n", "SERVICE", "PID", "STATE",
                  "IN/s", "OUT/s", "P50[us]", "P99[us]", "AGE[s]", "ERRORS", "DETAIL");
  for (const auto& s : rows) {
    if (!s.seen) {
      out += fmt::format("{:<20} {:>8} {:<14} {:>8} {:>8} {:>9} {:>9} {:>6}  {:<24} {}\n", s.service, "-",
                         state_column(s), "-", "-", "-", "-", "-", "-", "no heartbeat");
      continue;
    }
    std::string detail = s.last.state_detail;
    if (s.pid_changes > 0)
      detail += fmt::format("{}(pid changed {}x)", detail.empty() ? "" : " ", s.pid_changes);
    out += fmt::format("{:<20} {:>8} {:<14} {:>8} {:>8} {:>9.0f} {:>9.0f} {:>6.1f}  {:<24} {}\n", s.service,
                       s.last.pid, state_column(s), rate_column(s.rate_in_hz, s.has_rates()),
                       rate_column(s.rate_out_hz, s.has_rates()), s.last.processing_p50_us,
                       s.last.processing_p99_us, s.age_s, errors_column(s), detail);
  }
  const auto missing = missing_services(rows);
  size_t expected = 0;
  for (const auto& s : rows) expected += s.expected ? 1 : 0;
  if (missing.empty()) {
    out += fmt::format("all {} expected services alive\n", expected);
  } else {
    out += fmt::format("MISSING or stale: {}\n", fmt::join(missing, ", "));
  }
  std::vector<std::string> twice;
  for (const auto& s : rows) {
    if (s.duplicate && (twice.empty() || twice.back() != s.service)) twice.push_back(s.service);
  }
  if (!twice.empty()) out += fmt::format("RUNNING MORE THAN ONCE: {}\n", fmt::join(twice, ", "));
  return out;
}

nlohmann::json status_to_json(const std::vector<ServiceStatus>& rows) {
  nlohmann::json services = nlohmann::json::array();
  for (const auto& s : rows) {
    nlohmann::json j;
    j["service"] = s.service;
    j["expected"] = s.expected;
    j["present"] = s.seen && !s.stale;
    j["seen"] = s.seen;
    if (!s.seen) {
      j["state"] = "MISSING";
      services.push_back(std::move(j));
      continue;
    }
    j["pid"] = s.last.pid;
    j["state"] = heartbeat_state_name(s.last.state);
    j["stale"] = s.stale;
    j["state_detail"] = s.last.state_detail;
    j["age_s"] = s.age_s;
    j["uptime_s"] = static_cast<double>(s.last.uptime_us) * 1e-6;
    j["rate_in_hz"] = s.has_rates() ? nlohmann::json(s.rate_in_hz) : nlohmann::json();
    j["rate_out_hz"] = s.has_rates() ? nlohmann::json(s.rate_out_hz) : nlohmann::json();
    j["messages_in"] = s.last.messages_in;
    j["messages_out"] = s.last.messages_out;
    j["decode_errors"] = s.last.decode_errors;
    j["processing_p50_us"] = s.last.processing_p50_us;
    j["processing_p99_us"] = s.last.processing_p99_us;
    j["pid_changes"] = s.pid_changes;
    j["duplicate"] = s.duplicate;
    nlohmann::json counters = nlohmann::json::object();
    for (const auto& [name, value] : s.last.counters) counters[name] = value;
    j["counters"] = std::move(counters);
    services.push_back(std::move(j));
  }
  const auto missing = missing_services(rows);
  const bool duplicate =
      std::any_of(rows.begin(), rows.end(), [](const ServiceStatus& s) { return s.duplicate; });
  return {{"ok", missing.empty() && !duplicate}, {"missing", missing}, {"services", std::move(services)}};
}

std::string format_status(const std::vector<ServiceStatus>& rows, int64_t heartbeat_decode_errors, bool json,
                          bool clear_screen) {
  if (json) {
    auto doc = status_to_json(rows);
    doc["heartbeat_decode_errors"] = heartbeat_decode_errors;
    return doc.dump() + "\n";
  }
  std::string out = clear_screen ? "\033[H\033[2J" : "";
  out += format_status_table(rows);
  if (heartbeat_decode_errors > 0) {
    out += fmt::format("{} HEARTBEAT messages could not be decoded (other heartbeat_t version?)\n",
                       heartbeat_decode_errors);
  }
  return out;
}

}  // namespace refloc
