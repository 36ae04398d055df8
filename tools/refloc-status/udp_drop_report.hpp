#pragma once
// How refloc-status shows kernel UDP loss next to the heartbeat table: which
// service's LCM socket dropped datagrams (its pid matched to the HEARTBEAT rows),
// and the namespace's RcvbufErrors total.

#include "heartbeat_table.hpp"
#include "status_report.hpp"
#include "udp_drops.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace refloc {

/// Who holds a socket: the service whose heartbeat carries its pid, else the process
/// name, else "pid N" / "?".
std::string socket_holder_name(const LcmSocketDrops& socket, const std::vector<ServiceStatus>& rows);

/// Lines below the table: the protocol totals, the sockets that dropped (by holder) or
/// "none dropped".
std::string format_udp_drops(const UdpDropReport& report, const std::vector<ServiceStatus>& rows);

/// {"rcvbuf_errors", "in_errors", "in_datagrams" (null when unreadable), "lcm_port",
///  "sockets": [{"holder", "pid", "process", "drops", "rx_queue_bytes"}], "dropping": [holders]}.
nlohmann::json udp_drops_to_json(const UdpDropReport& report, const std::vector<ServiceStatus>& rows);

/// format_status with the UDP drops: "udp" added to the one JSON document, or the lines after the table.
std::string format_status_with_udp_drops(const StatusPage& page, const PageStyle& style,
                                         const UdpDropReport& udp);

}  // namespace refloc
