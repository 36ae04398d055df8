#include "status_report.hpp"

#include "counter_kind.hpp"
#include "status_table.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace refloc {
namespace {

nlohmann::json counters_json(const NamedCounters& counters) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, value] : counters) j[name] = value;
  return j;
}

nlohmann::json service_json(const ServiceStatus& s) {
  nlohmann::json j;
  j["service"] = s.service;
  j["expected"] = s.expected;
  j["present"] = s.seen && !s.stale;
  j["seen"] = s.seen;
  if (!s.seen) {
    j["state"] = "MISSING";
    return j;
  }
  j["pid"] = s.last.pid;
  j["state"] = heartbeat_state_name(s.last.state);
  j["stale"] = s.stale;
  j["in_error"] = s.in_error();
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
  j["error_counters"] = counters_json(split_counters(s.last.counters).errors);
  j["counters"] = counters_json(s.last.counters);
  return j;
}

}  // namespace

nlohmann::json status_to_json(const std::vector<ServiceStatus>& rows) {
  nlohmann::json services = nlohmann::json::array();
  for (const auto& s : rows) services.push_back(service_json(s));
  return {{"ok", status_exit_code(rows) == 0},
          {"missing", missing_services(rows)},
          {"in_error", services_in_error(rows)},
          {"services", std::move(services)}};
}

std::string format_status(const StatusPage& page, const PageStyle& style) {
  if (style.json) {
    auto doc = status_to_json(page.rows);
    doc["heartbeat_decode_errors"] = page.heartbeat_decode_errors;
    if (page.pose) doc["pose"] = pose_to_json(*page.pose);
    return doc.dump() + "\n";
  }
  std::string below;
  if (page.pose) below += format_pose_line(*page.pose);
  if (page.heartbeat_decode_errors > 0) {
    below += fmt::format("{} HEARTBEAT messages could not be decoded (other heartbeat_t version?)\n",
                         page.heartbeat_decode_errors);
  }
  std::string out = style.clear_screen ? "\033[H\033[2J" : "";
  out += format_status_table(page.rows, style.wide);
  return out + (style.wide ? below : wrap_to_width(below));
}

}  // namespace refloc
