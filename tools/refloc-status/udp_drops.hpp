#pragma once
// The kernel's UDP loss counters, so that a datagram dropped because a process
// was too slow to read its socket is never silent: the protocol totals of
// /proc/net/snmp (RcvbufErrors: receive buffer full) and the per-socket `drops`
// of /proc/net/udp for the sockets bound to the LCM port, each mapped to the
// process holding it (through /proc/<pid>/fd when readable). All counters are
// of the caller's network namespace and count since it (or the socket) began.
// Parsing is separate from reading so it is tested on captured /proc text.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace refloc {

/// The "Udp:" counters of /proc/net/snmp.
struct UdpProtocolCounters {
  int64_t in_datagrams = 0;
  int64_t in_errors = 0;      ///< every datagram received but not delivered (includes rcvbuf_errors)
  int64_t rcvbuf_errors = 0;  ///< dropped because a socket's receive buffer was full
};

/// One line of /proc/net/udp.
struct UdpSocketRow {
  uint32_t local_ipv4 = 0;  ///< host byte order
  int local_port = 0;
  int64_t rx_queue_bytes = 0;  ///< kernel memory queued unread (skb truesize, not payload)
  uint64_t inode = 0;
  int64_t drops = 0;  ///< datagrams this socket lost since it was opened
};

/// The Udp: header and value lines of /proc/net/snmp; nullopt when absent or malformed.
std::optional<UdpProtocolCounters> parse_proc_net_snmp(const std::string& text);

/// The socket lines of /proc/net/udp (the header and malformed lines are skipped).
std::vector<UdpSocketRow> parse_proc_net_udp(const std::string& text);

/// The inode of a /proc/<pid>/fd link target "socket:[12345]"; 0 for anything else.
uint64_t parse_socket_link(const std::string& link_target);

/// A socket bound to the LCM port and who holds it.
struct LcmSocketDrops {
  uint64_t inode = 0;
  int32_t pid = 0;      ///< 0 when no readable /proc/<pid>/fd holds it
  std::string process;  ///< /proc/<pid>/comm; empty when unknown
  int64_t drops = 0;
  int64_t rx_queue_bytes = 0;
};

/// What refloc-status shows about kernel UDP loss.
struct UdpDropReport {
  int lcm_port = 0;                             ///< 0: the LCM URL is not udpm, no sockets listed
  std::optional<UdpProtocolCounters> protocol;  ///< nullopt when /proc/net/snmp is unreadable
  std::vector<LcmSocketDrops> sockets;          ///< bound to lcm_port, by pid
};

/// socket inode -> (pid, comm) of the process holding it.
using SocketOwners = std::map<uint64_t, std::pair<int32_t, std::string>>;

/// The sockets of rows bound to port, with their holders from owners.
std::vector<LcmSocketDrops> lcm_sockets(const std::vector<UdpSocketRow>& rows, int port,
                                        const SocketOwners& owners);

/// Read /proc (proc_root for tests): the protocol counters and, when lcm_port > 0, the
/// sockets bound to it with their holders. Never throws; unreadable parts stay empty.
UdpDropReport read_udp_drops(int lcm_port, const std::string& proc_root = "/proc");

}  // namespace refloc
