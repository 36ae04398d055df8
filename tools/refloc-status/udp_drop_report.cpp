#include "udp_drop_report.hpp"

#include "status_report.hpp"
#include "status_table.hpp"

#include <fmt/format.h>

namespace refloc {

std::string socket_holder_name(const LcmSocketDrops& socket, const std::vector<ServiceStatus>& rows) {
  if (socket.pid > 0) {
    for (const auto& r : rows) {
      if (r.seen && r.last.pid == socket.pid) return r.service;
    }
  }
  if (!socket.process.empty()) return socket.process;
  return socket.pid > 0 ? fmt::format("pid {}", socket.pid) : "?";
}

std::string format_udp_drops(const UdpDropReport& report, const std::vector<ServiceStatus>& rows) {
  std::string out;
  if (report.protocol) {
    out += fmt::format(
        "UDP, this network namespace: {} datagrams dropped for a full receive buffer (RcvbufErrors), "
        "{} InErrors\n",
        report.protocol->rcvbuf_errors, report.protocol->in_errors);
  } else {
    out += "UDP drop counters: /proc/net/snmp not readable\n";
  }
  if (report.lcm_port <= 0) return out;
  std::vector<std::string> dropping;
  for (const auto& s : report.sockets) {
    if (s.drops > 0)
      dropping.push_back(fmt::format("{} (pid {}): {}", socket_holder_name(s, rows), s.pid, s.drops));
  }
  if (dropping.empty()) {
    out +=
        fmt::format("LCM sockets on UDP port {}: {}, none dropped\n", report.lcm_port, report.sockets.size());
  } else {
    out += fmt::format("LCM sockets on UDP port {}: DROPPED datagrams: {}\n", report.lcm_port,
                       fmt::join(dropping, ", "));
  }
  return out;
}

nlohmann::json udp_drops_to_json(const UdpDropReport& report, const std::vector<ServiceStatus>& rows) {
  nlohmann::json j;
  const auto number_or_null = [&](int64_t UdpProtocolCounters::*field) {
    return report.protocol ? nlohmann::json((*report.protocol).*field) : nlohmann::json();
  };
  j["rcvbuf_errors"] = number_or_null(&UdpProtocolCounters::rcvbuf_errors);
  j["in_errors"] = number_or_null(&UdpProtocolCounters::in_errors);
  j["in_datagrams"] = number_or_null(&UdpProtocolCounters::in_datagrams);
  j["lcm_port"] = report.lcm_port;
  nlohmann::json sockets = nlohmann::json::array();
  nlohmann::json dropping = nlohmann::json::array();
  for (const auto& s : report.sockets) {
    const std::string holder = socket_holder_name(s, rows);
    sockets.push_back({{"holder", holder},
                       {"pid", s.pid},
                       {"process", s.process},
                       {"drops", s.drops},
                       {"rx_queue_bytes", s.rx_queue_bytes}});
    if (s.drops > 0) dropping.push_back(holder);
  }
  j["sockets"] = std::move(sockets);
  j["dropping"] = std::move(dropping);
  return j;
}

std::string format_status_with_udp_drops(const StatusPage& page, const PageStyle& style,
                                         const UdpDropReport& udp) {
  // Composed from format_status's output rather than inside it, so both stay one concept.
  if (style.json) {
    auto doc = nlohmann::json::parse(format_status(page, style));
    doc["udp"] = udp_drops_to_json(udp, page.rows);
    return doc.dump() + "\n";
  }
  const std::string drops = format_udp_drops(udp, page.rows);
  return format_status(page, style) + (style.wide ? drops : wrap_to_width(drops));
}

}  // namespace refloc
