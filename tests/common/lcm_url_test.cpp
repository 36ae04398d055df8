#include "common/lcm_url.hpp"
#include "common/json_config.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::string refusal_of(const std::string& url) {
  try {
    parse_lcm_url(url, "--lcm-url");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(LcmUrlResolution, ExplicitUrlWinsOverEnvironmentAndDefault) {
  const LcmUrl u = resolve_lcm_url("udpm://239.255.76.68:7668?ttl=1", "udpm://239.255.76.67:7667?ttl=0");
  EXPECT_EQ(u.origin, "--lcm-url");
  EXPECT_EQ(u.multicast_address, "239.255.76.68");
  EXPECT_EQ(u.port, 7668);
  EXPECT_EQ(u.ttl, 1);
}

TEST(LcmUrlResolution, EnvironmentWinsOverDefault) {
  const LcmUrl u = resolve_lcm_url("", "udpm://239.255.76.67:7667?ttl=1");
  EXPECT_EQ(u.origin, "$LCM_DEFAULT_URL");
  EXPECT_EQ(u.ttl, 1);
}

TEST(LcmUrlResolution, EmptyEnvironmentMeansDefault) {
  EXPECT_EQ(resolve_lcm_url("", "").origin, "default");
  EXPECT_EQ(resolve_lcm_url("", nullptr).origin, "default");
}

TEST(LcmUrlResolution, DefaultStaysOnTheHostAndAsksForTheStallBuffer) {
  const LcmUrl u = resolve_lcm_url("", nullptr);
  EXPECT_EQ(u.url, kLcmDefaultUrl);
  EXPECT_EQ(u.provider, "udpm");
  EXPECT_EQ(u.ttl, 0);
  EXPECT_EQ(u.recv_buf_size_bytes, kLcmRecvBufSizeBytes);
  EXPECT_FALSE(u.recv_buf_size_added);
}

TEST(LcmUrlResolution, UdpmUrlWithoutReceiveBufferGetsTheDefaultOne) {
  EXPECT_EQ(parse_lcm_url("udpm://239.255.76.67:7667?ttl=0", "x").url,
            "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=2097152");
  const LcmUrl bare = parse_lcm_url("udpm://239.255.76.67:7667", "x");
  EXPECT_EQ(bare.url, "udpm://239.255.76.67:7667?recv_buf_size=2097152");
  EXPECT_TRUE(bare.recv_buf_size_added);
  EXPECT_EQ(bare.recv_buf_size_bytes, 2097152);
}

TEST(LcmUrlResolution, ExplicitReceiveBufferIsKept) {
  const LcmUrl u = parse_lcm_url("udpm://239.255.76.67:7667?recv_buf_size=4096&ttl=0", "x");
  EXPECT_EQ(u.url, "udpm://239.255.76.67:7667?recv_buf_size=4096&ttl=0");
  EXPECT_EQ(u.recv_buf_size_bytes, 4096);
  EXPECT_FALSE(u.recv_buf_size_added);
}

TEST(LcmUrlResolution, EmptyUdpmNetworkIsLcmsDefaultGroup) {
  const LcmUrl u = parse_lcm_url("udpm://?ttl=0", "x");
  EXPECT_EQ(u.multicast_address, "239.255.76.67");
  EXPECT_EQ(u.port, 7667);
}

TEST(LcmUrlResolution, OtherProvidersPassUnchangedWithoutReceiveBuffer) {
  EXPECT_EQ(parse_lcm_url("memq://", "x").url, "memq://");
  EXPECT_EQ(parse_lcm_url("memq://", "x").recv_buf_size_bytes, 0);
  EXPECT_EQ(parse_lcm_url("file:///tmp/a.lcm?speed=0", "x").url, "file:///tmp/a.lcm?speed=0");
  EXPECT_EQ(parse_lcm_url("file:///tmp/a.lcm?mode=w", "x").provider, "file");
}

TEST(LcmUrlRefusal, NegativeTtlWhichLcmWouldTurnInto255) {
  const std::string why = refusal_of("udpm://239.255.76.67:7667?ttl=-1");
  EXPECT_NE(why.find("ttl must be a whole number in 0..255, got '-1'"), std::string::npos) << why;
  EXPECT_NE(why.find("LCM URL 'udpm://239.255.76.67:7667?ttl=-1' (from --lcm-url)"), std::string::npos)
      << why;
}

TEST(LcmUrlRefusal, TtlAbove255OrNotANumber) {
  EXPECT_NE(refusal_of("udpm://239.255.76.67:7667?ttl=256").find("ttl must be"), std::string::npos);
  EXPECT_NE(refusal_of("udpm://239.255.76.67:7667?ttl=one").find("got 'one'"), std::string::npos);
  EXPECT_NE(refusal_of("udpm://239.255.76.67:7667?ttl=").find("ttl must be"), std::string::npos);
  EXPECT_NE(refusal_of("udpm://239.255.76.67:7667?ttl=0x1").find("ttl must be"), std::string::npos);
}

TEST(LcmUrlRefusal, UnknownProvider) {
  EXPECT_NE(refusal_of("udp://239.255.76.67:7667").find("unknown provider 'udp'"), std::string::npos);
  EXPECT_NE(refusal_of("239.255.76.67:7667").find("expected provider://network?options"), std::string::npos);
}

TEST(LcmUrlRefusal, BadPort) {
  EXPECT_NE(refusal_of("udpm://239.255.76.67:0").find("port '0' is not a number in 1..65535"),
            std::string::npos);
  EXPECT_NE(refusal_of("udpm://239.255.76.67:65536").find("port '65536'"), std::string::npos);
  EXPECT_NE(refusal_of("udpm://239.255.76.67:port").find("port 'port'"), std::string::npos);
  EXPECT_NE(refusal_of("udpm://239.255.76.67:").find("port ''"), std::string::npos);
}

TEST(LcmUrlRefusal, AddressThatIsNotIpv4Multicast) {
  EXPECT_NE(refusal_of("udpm://10.0.0.1:7667").find("not an IPv4 multicast address"), std::string::npos);
  EXPECT_NE(refusal_of("udpm://239.255.76:7667").find("not an IPv4 multicast address"), std::string::npos);
  EXPECT_NE(refusal_of("udpm://239.256.76.67:7667").find("not an IPv4 multicast address"), std::string::npos);
  EXPECT_NE(refusal_of("udpm://lcm.local:7667").find("not an IPv4 multicast address"), std::string::npos);
}

TEST(LcmUrlRefusal, UnparsableOrUnknownOrRepeatedOption) {
  EXPECT_NE(refusal_of("udpm://239.255.76.67:7667?ttl").find("option 'ttl' is not key=value"),
            std::string::npos);
  EXPECT_NE(refusal_of("udpm://239.255.76.67:7667?ttl=0&").find("option '' is not key=value"),
            std::string::npos);
  EXPECT_NE(refusal_of("udpm://239.255.76.67:7667?").find("empty option list"), std::string::npos);
  EXPECT_NE(refusal_of("udpm://239.255.76.67:7667?tll=0").find("unknown udpm option 'tll'"),
            std::string::npos);
  EXPECT_NE(refusal_of("udpm://239.255.76.67:7667?ttl=0&ttl=1").find("option 'ttl' given twice"),
            std::string::npos);
  EXPECT_NE(refusal_of("memq://?speed=1").find("unknown memq option 'speed'"), std::string::npos);
  EXPECT_NE(refusal_of("file://").find("file:// needs a path"), std::string::npos);
}

TEST(LcmUrlRefusal, ReceiveBufferThatIsNotPositiveOrFitsNoInt) {
  const std::string base = "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=";
  for (const char* bad : {"0", "-1", "2147483648", "1e6", "4M", ""}) {
    EXPECT_NE(refusal_of(base + bad).find("recv_buf_size must be a whole number of bytes in 1..2147483647"),
              std::string::npos)
        << bad;
  }
  EXPECT_EQ(refusal_of(base + "2147483647"), "");
}

TEST(LcmUrlRefusal, MessageIsOneLine) {
  EXPECT_EQ(refusal_of("udpm://239.255.76.67:7667?ttl=-1").find('\n'), std::string::npos);
}

TEST(ReceiveBufferCheck, GrantedWhenRmemMaxIsLargeEnough) {
  const ReceiveBufferCheck c = check_receive_buffer(2097152, 4194304);
  EXPECT_FALSE(c.clamped);
  EXPECT_EQ(c.granted_bytes, 2097152);
  EXPECT_TRUE(c.warning.empty());
  EXPECT_FALSE(check_receive_buffer(2097152, 2097152).clamped);
}

TEST(ReceiveBufferCheck, ClampedToRmemMaxWithTheSysctlToSet) {
  const ReceiveBufferCheck c = check_receive_buffer(2097152, 212992);
  EXPECT_TRUE(c.clamped);
  EXPECT_EQ(c.granted_bytes, 212992);
  EXPECT_NE(c.warning.find("net.core.rmem_max = 212992"), std::string::npos) << c.warning;
  EXPECT_NE(c.warning.find("sysctl -w net.core.rmem_max=2097152"), std::string::npos) << c.warning;
  EXPECT_EQ(c.warning.find('\n'), std::string::npos);
}

TEST(ReceiveBufferCheck, UnknownRmemMaxClaimsNothing) {
  const ReceiveBufferCheck c = check_receive_buffer(2097152, -1);
  EXPECT_FALSE(c.clamped);
  EXPECT_TRUE(c.warning.empty());
}

TEST(ReceiveBufferCheck, ReadsRmemMaxFromProcText) {
  const std::string path = ::testing::TempDir() + "/lcm_url_test_rmem_max";
  {
    std::ofstream out(path);
    out << "212992\n";
  }
  EXPECT_EQ(read_rmem_max(path), 212992);
  {
    std::ofstream out(path);
    out << "garbage\n";
  }
  EXPECT_EQ(read_rmem_max(path), std::nullopt);
  std::remove(path.c_str());
  EXPECT_EQ(read_rmem_max(path), std::nullopt);
}

TEST(LcmUrlDeployment, DeployScriptDefaultEqualsTheCodeDefault) {
  // deploy/refloc hands the URL to lcm-logger (not our code): its default must be ours.
  const std::string script = read_text(std::string(REFLOC_SOURCE_DIR) + "/deploy/refloc");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(script, m, std::regex(R"(LCM_DEFAULT_URL:-([^}"]+))")))
      << "no default in deploy/refloc";
  EXPECT_EQ(m[1].str(), kLcmDefaultUrl);
}

TEST(LcmUrlDeployment, InstallDepsSetsRmemMaxToWhatTheUrlAsks) {
  const std::string script = read_text(std::string(REFLOC_SOURCE_DIR) + "/deploy/install-deps.sh");
  EXPECT_NE(script.find("rmem_max_bytes=" + std::to_string(kLcmRecvBufSizeBytes)), std::string::npos);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
