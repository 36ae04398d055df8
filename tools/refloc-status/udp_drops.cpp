#include "udp_drops.hpp"

#include <dirent.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace refloc {
namespace {

std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> words;
  std::istringstream in(line);
  std::string word;
  while (in >> word) words.push_back(word);
  return words;
}

std::optional<int64_t> to_int(const std::string& text, int base) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, base);
  if (end == nullptr || *end != '\0') return std::nullopt;
  return static_cast<int64_t>(value);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// "434CFFEF:1DF3" -> address (the kernel prints the network-order word as a host integer) and port.
bool parse_address(const std::string& text, uint32_t& ipv4, int& port) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos) return false;
  const auto address = to_int(text.substr(0, colon), 16);
  const auto port_value = to_int(text.substr(colon + 1), 16);
  if (!address || !port_value) return false;
  const auto raw = static_cast<uint32_t>(*address);
  // Little-endian hosts print the bytes reversed: 434CFFEF is 239.255.76.67.
  ipv4 = ((raw & 0xFFu) << 24) | ((raw & 0xFF00u) << 8) | ((raw >> 8) & 0xFF00u) | (raw >> 24);
  port = static_cast<int>(*port_value);
  return true;
}

/// inode -> (pid, comm) of every socket in every readable /proc/<pid>/fd.
SocketOwners socket_owners(const std::string& proc_root) {
  SocketOwners owners;
  DIR* proc = opendir(proc_root.c_str());
  if (proc == nullptr) return owners;
  while (const dirent* entry = readdir(proc)) {
    const auto pid = to_int(entry->d_name, 10);
    if (!pid || *pid <= 0) continue;
    const std::string fd_dir = proc_root + "/" + entry->d_name + "/fd";
    DIR* fds = opendir(fd_dir.c_str());
    if (fds == nullptr) continue;  // another user's process, or gone
    std::string comm;
    while (const dirent* fd = readdir(fds)) {
      char target[64];
      const ssize_t n = readlink((fd_dir + "/" + fd->d_name).c_str(), target, sizeof(target) - 1);
      if (n <= 0) continue;
      target[n] = '\0';
      const uint64_t inode = parse_socket_link(target);
      if (inode == 0) continue;
      if (comm.empty()) {
        comm = read_file(proc_root + "/" + entry->d_name + "/comm");
        comm.erase(std::remove(comm.begin(), comm.end(), '\n'), comm.end());
      }
      owners.emplace(inode, std::make_pair(static_cast<int32_t>(*pid), comm));
    }
    closedir(fds);
  }
  closedir(proc);
  return owners;
}

}  // namespace

std::optional<UdpProtocolCounters> parse_proc_net_snmp(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> names;
  while (std::getline(in, line)) {
    const auto words = split_words(line);
    if (words.empty() || words[0] != "Udp:") continue;
    if (names.empty()) {
      names = words;
      continue;
    }
    if (words.size() != names.size()) return std::nullopt;
    UdpProtocolCounters c;
    int found = 0;
    for (size_t i = 1; i < words.size(); ++i) {
      const auto value = to_int(words[i], 10);
      if (!value) return std::nullopt;
      int64_t* field = names[i] == "InDatagrams"    ? &c.in_datagrams
                       : names[i] == "InErrors"     ? &c.in_errors
                       : names[i] == "RcvbufErrors" ? &c.rcvbuf_errors
                                                    : nullptr;
      if (field == nullptr) continue;
      *field = *value;
      ++found;
    }
    if (found != 3) return std::nullopt;
    return c;
  }
  return std::nullopt;
}

std::vector<UdpSocketRow> parse_proc_net_udp(const std::string& text) {
  // sl local_address rem_address st tx_queue:rx_queue tr:tm->when retrnsmt uid timeout inode ref pointer
  // drops
  std::vector<UdpSocketRow> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto words = split_words(line);
    if (words.size() < 13 || words[0].empty() || words[0].back() != ':') continue;
    UdpSocketRow row;
    if (!parse_address(words[1], row.local_ipv4, row.local_port)) continue;
    const size_t colon = words[4].find(':');
    const auto rx_queue = colon == std::string::npos ? std::nullopt : to_int(words[4].substr(colon + 1), 16);
    const auto inode = to_int(words[9], 10);
    const auto drops = to_int(words[12], 10);
    if (!rx_queue || !inode || !drops) continue;
    row.rx_queue_bytes = *rx_queue;
    row.inode = static_cast<uint64_t>(*inode);
    row.drops = *drops;
    rows.push_back(row);
  }
  return rows;
}

uint64_t parse_socket_link(const std::string& link_target) {
  const std::string prefix = "socket:[";
  if (link_target.size() <= prefix.size() + 1 || link_target.compare(0, prefix.size(), prefix) != 0 ||
      link_target.back() != ']')
    return 0;
  const auto inode = to_int(link_target.substr(prefix.size(), link_target.size() - prefix.size() - 1), 10);
  return inode && *inode > 0 ? static_cast<uint64_t>(*inode) : 0;
}

std::vector<LcmSocketDrops> lcm_sockets(const std::vector<UdpSocketRow>& rows, int port,
                                        const SocketOwners& owners) {
  std::vector<LcmSocketDrops> sockets;
  for (const auto& row : rows) {
    if (row.local_port != port) continue;
    LcmSocketDrops s;
    s.inode = row.inode;
    s.drops = row.drops;
    s.rx_queue_bytes = row.rx_queue_bytes;
    if (const auto it = owners.find(row.inode); it != owners.end()) {
      s.pid = it->second.first;
      s.process = it->second.second;
    }
    sockets.push_back(std::move(s));
  }
  std::sort(sockets.begin(), sockets.end(), [](const LcmSocketDrops& a, const LcmSocketDrops& b) {
    return a.pid != b.pid ? a.pid < b.pid : a.inode < b.inode;
  });
  return sockets;
}

UdpDropReport read_udp_drops(int lcm_port, const std::string& proc_root) {
  UdpDropReport report;
  report.lcm_port = lcm_port;
  // /proc/net is the reading process's own network namespace.
  report.protocol = parse_proc_net_snmp(read_file(proc_root + "/net/snmp"));
  if (lcm_port > 0) {
    const auto rows = parse_proc_net_udp(read_file(proc_root + "/net/udp"));
    // Walking every /proc/<pid>/fd costs; skip it when no socket is bound to the port.
    const bool any = std::any_of(rows.begin(), rows.end(),
                                 [&](const UdpSocketRow& r) { return r.local_port == lcm_port; });
    report.sockets = lcm_sockets(rows, lcm_port, any ? socket_owners(proc_root) : SocketOwners{});
  }
  return report;
}

}  // namespace refloc
