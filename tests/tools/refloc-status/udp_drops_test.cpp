#include "udp_drops.hpp"
#include "udp_drop_report.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

// Captured on Linux 6.18 in a network namespace after 20 datagrams of 1000 bytes were sent to
// a socket with a 4 kB receive buffer on 239.255.76.67:7667: 17 dropped.
const char* kSnmp =
    "Ip: Forwarding DefaultTTL InReceives InHdrErrors InAddrErrors ForwDatagrams InUnknownProtos InDiscards "
    "InDelivers OutRequests OutDiscards OutNoRoutes ReasmTimeout ReasmReqds ReasmOKs ReasmFails FragOKs "
    "FragFails "
    "FragCreates OutTransmits\n"
    "Ip: 2 64 21 0 0 0 0 0 20 21 0 0 0 0 0 0 0 0 0 21\n"
    "Tcp: RtoAlgorithm RtoMin RtoMax MaxConn ActiveOpens PassiveOpens AttemptFails EstabResets CurrEstab "
    "InSegs "
    "OutSegs RetransSegs InErrs OutRsts InCsumErrors\n"
    "Tcp: 1 200 120000 -1 0 0 0 0 0 0 0 0 0 0 0\n"
    "Udp: InDatagrams NoPorts InErrors OutDatagrams RcvbufErrors SndbufErrors InCsumErrors IgnoredMulti "
    "MemErrors\n"
    "Udp: 3 0 17 20 17 0 0 0 0\n"
    "UdpLite: InDatagrams NoPorts InErrors OutDatagrams RcvbufErrors SndbufErrors InCsumErrors IgnoredMulti "
    "MemErrors\n"
    "UdpLite: 0 0 5 0 5 0 0 0 0\n";

const char* kUdp =
    "   sl  local_address rem_address   st tx_queue rx_queue tr tm->when retrnsmt   uid  timeout inode ref "
    "pointer drops            \n"
    " 6848: 434CFFEF:1DF3 00000000:0000 07 00000000:00001B00 00:00000000 00000000     0        0 164163 2 "
    "0000000077c11b79 17       \n"
    "10813: 00000000:ED70 00000000:0000 07 00000000:00000000 00:00000000 00000000     0        0 164164 2 "
    "00000000c7292cee 0        \n"
    " 6849: 434CFFEF:1DF3 00000000:0000 07 00000000:00000000 00:00000000 00000000     0        0 164170 2 "
    "00000000c7292cef 0        \n";

TEST(UdpDropParsing, ReadsTheUdpLineNotUdpLite) {
  const auto c = parse_proc_net_snmp(kSnmp);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->rcvbuf_errors, 17);
  EXPECT_EQ(c->in_errors, 17);
  EXPECT_EQ(c->in_datagrams, 3);
}

TEST(UdpDropParsing, SnmpWithoutUdpOrWithShortValuesIsUnknown) {
  EXPECT_FALSE(parse_proc_net_snmp("").has_value());
  EXPECT_FALSE(parse_proc_net_snmp("Udp: InDatagrams InErrors RcvbufErrors\nUdp: 1 2\n").has_value());
  EXPECT_FALSE(parse_proc_net_snmp("Udp: InDatagrams InErrors RcvbufErrors\nUdp: 1 x 3\n").has_value());
  EXPECT_FALSE(parse_proc_net_snmp("Udp: InDatagrams NoPorts\nUdp: 1 2\n").has_value());
}

TEST(UdpDropParsing, SocketLinesGiveAddressPortQueueInodeAndDrops) {
  const auto rows = parse_proc_net_udp(kUdp);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].local_ipv4, (239u << 24) | (255u << 16) | (76u << 8) | 67u);
  EXPECT_EQ(rows[0].local_port, 7667);
  EXPECT_EQ(rows[0].rx_queue_bytes, 0x1B00);
  EXPECT_EQ(rows[0].inode, 164163u);
  EXPECT_EQ(rows[0].drops, 17);
  EXPECT_EQ(rows[1].local_port, 0xED70);
  EXPECT_EQ(rows[1].drops, 0);
}

TEST(UdpDropParsing, MalformedSocketLinesAreSkipped) {
  EXPECT_TRUE(parse_proc_net_udp("garbage\n 1: zz:1DF3 0 07 0:0 0 0 0 0 5 2 0 0\n").empty());
  EXPECT_TRUE(parse_proc_net_udp(" 1: 434CFFEF:1DF3 00000000:0000 07 00000000:00000000\n").empty());
}

TEST(UdpDropParsing, SocketLinkTargetsGiveInodes) {
  EXPECT_EQ(parse_socket_link("socket:[164163]"), 164163u);
  EXPECT_EQ(parse_socket_link("pipe:[164163]"), 0u);
  EXPECT_EQ(parse_socket_link("socket:[]"), 0u);
  EXPECT_EQ(parse_socket_link("/dev/null"), 0u);
}

TEST(UdpDropParsing, OnlyLcmPortSocketsWithTheirHolders) {
  const auto sockets = lcm_sockets(parse_proc_net_udp(kUdp), 7667, {{164163, {4321, "reflector_match"}}});
  ASSERT_EQ(sockets.size(), 2u);
  EXPECT_EQ(sockets[0].pid, 0);  // no readable fd holds 164170: sorted first, unknown
  EXPECT_EQ(sockets[1].pid, 4321);
  EXPECT_EQ(sockets[1].process, "reflector_match");
  EXPECT_EQ(sockets[1].drops, 17);
}

std::vector<ServiceStatus> one_service(const std::string& name, int32_t pid) {
  ServiceStatus s;
  s.service = name;
  s.seen = true;
  s.last.pid = pid;
  return {s};
}

TEST(UdpDropReport, DroppingSocketIsNamedByTheServiceWithItsPid) {
  UdpDropReport report;
  report.lcm_port = 7667;
  report.protocol = UdpProtocolCounters{3, 17, 17};
  report.sockets = lcm_sockets(parse_proc_net_udp(kUdp), 7667, {{164163, {4321, "reflector_match"}}});
  const auto rows = one_service("reflector_matcher", 4321);
  const std::string text = format_udp_drops(report, rows);
  EXPECT_NE(text.find("17 datagrams dropped for a full receive buffer (RcvbufErrors)"), std::string::npos)
      << text;
  EXPECT_NE(text.find("DROPPED datagrams: reflector_matcher (pid 4321): 17"), std::string::npos) << text;
  const auto j = udp_drops_to_json(report, rows);
  EXPECT_EQ(j["rcvbuf_errors"], 17);
  EXPECT_EQ(j["dropping"], nlohmann::json::array({"reflector_matcher"}));
  EXPECT_EQ(j["sockets"][1]["holder"], "reflector_matcher");
  EXPECT_EQ(j["sockets"][0]["holder"], "?");
}

TEST(UdpDropReport, NoDropsSaysSoAndUnreadableCountersAreNull) {
  UdpDropReport report;
  report.lcm_port = 7667;
  LcmSocketDrops quiet;
  quiet.pid = 99;
  quiet.process = "pose_solver";
  report.sockets = {quiet};
  const std::string text = format_udp_drops(report, {});
  EXPECT_NE(text.find("/proc/net/snmp not readable"), std::string::npos) << text;
  EXPECT_NE(text.find("LCM sockets on UDP port 7667: 1, none dropped"), std::string::npos) << text;
  const auto j = udp_drops_to_json(report, {});
  EXPECT_TRUE(j["rcvbuf_errors"].is_null());
  EXPECT_EQ(j["sockets"][0]["holder"], "pose_solver");
}

TEST(UdpDropReport, JsonStatusIsOneDocumentWithUdp) {
  UdpDropReport report;
  report.protocol = UdpProtocolCounters{1, 0, 0};
  PageStyle json;
  json.json = true;
  const std::string out = format_status_with_udp_drops({one_service("navigator", 5), 0, {}}, json, report);
  ASSERT_EQ(out.back(), '\n');
  EXPECT_EQ(out.find('\n'), out.size() - 1);
  const auto doc = nlohmann::json::parse(out);
  EXPECT_EQ(doc["udp"]["rcvbuf_errors"], 0);
  EXPECT_TRUE(doc.contains("services"));
}

TEST(UdpDropReport, ReadsAProcTreeAndFindsTheHolderThroughItsFds) {
  const std::string root = ::testing::TempDir() + "/udp_drops_proc_" + std::to_string(getpid());
  ASSERT_EQ(std::system(("rm -rf " + root + " && mkdir -p " + root + "/net " + root + "/4321/fd").c_str()),
            0);
  std::ofstream(root + "/net/snmp") << kSnmp;
  std::ofstream(root + "/net/udp") << kUdp;
  std::ofstream(root + "/4321/comm") << "reflector_match\n";
  ASSERT_EQ(symlink("socket:[164163]", (root + "/4321/fd/7").c_str()), 0);
  ASSERT_EQ(symlink("/dev/null", (root + "/4321/fd/0").c_str()), 0);
  const UdpDropReport report = read_udp_drops(7667, root);
  ASSERT_TRUE(report.protocol.has_value());
  EXPECT_EQ(report.protocol->rcvbuf_errors, 17);
  ASSERT_EQ(report.sockets.size(), 2u);
  EXPECT_EQ(report.sockets[1].pid, 4321);
  EXPECT_EQ(report.sockets[1].process, "reflector_match");
  EXPECT_TRUE(read_udp_drops(0, root).sockets.empty());
  std::system(("rm -rf " + root).c_str());
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
