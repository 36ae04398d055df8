#include "lms100_emulator/lmd_scandata_encoder.hpp"

#include "lms100_driver/lmd_scandata_parser.hpp"
#include "lms100_emulator/cola_a_text.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::string read_real_lms111_payload() {
  std::ifstream in(std::string(REFLOC_SOURCE_DIR) + "/tests/data/sick-real/lms111_cola_a_scan.txt",
                   std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t stx = bytes.find('\x02');
  const size_t etx = bytes.rfind('\x03');
  if (stx == std::string::npos || etx == std::string::npos) return {};
  return bytes.substr(stx + 1, etx - stx - 1);
}

TEST(LmdScandataEncoder, ReproducesRealLms111TelegramByteForByte) {
  const std::string real = read_real_lms111_payload();
  ASSERT_FALSE(real.empty());
  std::vector<std::string_view> tokens;
  split_cola_tokens(real, tokens);
  ASSERT_EQ(tokens[25], "21D");
  std::vector<uint16_t> dist;
  for (size_t i = 0; i < 0x21D; ++i) {
    int64_t v = 0;
    ASSERT_TRUE(parse_cola_request_number(tokens[26 + i], v));
    dist.push_back(static_cast<uint16_t>(v));
  }

  LmdTelegramHeader header;
  header.is_stream_event = false;
  header.serial_number = 0x8D4C04;
  header.telegram_counter = 0x45FF;
  header.scan_counter = 0x37;
  header.time_since_startup_us = 0x280F6;
  header.time_of_transmission_us = 0x28A73;
  LmdOutputOptions options;
  options.rssi_bits = 0;
  options.send_device_name = true;
  options.device_name = "Derecha";
  options.send_time_info = true;
  options.time_info = calendar_time_from_epoch_us(42ULL * 60 * 1000000 + 39ULL * 1000000 + 166000);
  std::string encoded;
  encode_lmd_scandata(header, LmdBeamLayout{}, dist.data(), nullptr, dist.size(), options, encoded);
  EXPECT_EQ(encoded, real);
}

TEST(LmdScandataEncoder, Rssi16BitGoesInTheSixteenBitBlockAfterDist1) {
  const uint16_t dist[3] = {16, 0x1234, 0};
  const uint16_t rssi[3] = {0, 65000, 65535};
  LmdTelegramHeader header;
  std::string out;
  encode_lmd_scandata(header, LmdBeamLayout{}, dist, rssi, 3, LmdOutputOptions{}, out);
  EXPECT_EQ(out,
            "sSN LMDscandata 1 1 8D4C04 0 0 0 0 0 0 0 0 7 0 0 1388 168 0 2 "
            "DIST1 3F800000 00000000 FFF92230 1388 3 10 1234 0 "
            "RSSI1 3F800000 00000000 FFF92230 1388 3 0 FDE8 FFFF 0 0 0 0 0 0");
}

TEST(LmdScandataEncoder, Rssi8BitGoesInTheEightBitBlockClampedTo255) {
  const uint16_t dist[2] = {500, 600};
  const uint16_t rssi[2] = {254, 1000};
  LmdTelegramHeader header;
  header.scan_frequency_1e2hz = 2500;
  LmdBeamLayout layout;
  layout.step_1e4deg = 2500;
  LmdOutputOptions options;
  options.rssi_bits = 8;
  std::string out;
  encode_lmd_scandata(header, layout, dist, rssi, 2, options, out);
  EXPECT_EQ(out,
            "sSN LMDscandata 1 1 8D4C04 0 0 0 0 0 0 0 0 7 0 0 9C4 168 0 1 "
            "DIST1 3F800000 00000000 FFF92230 9C4 2 1F4 258 1 "
            "RSSI1 3F800000 00000000 FFF92230 9C4 2 FE FF 0 0 0 0 0");
}

TEST(LmdScandataEncoder, RoundTripsThroughTheDriverParser) {
  std::vector<uint16_t> dist(541), rssi(541);
  for (size_t i = 0; i < dist.size(); ++i) {
    dist[i] = static_cast<uint16_t>(i * 97 % 20000);
    rssi[i] = static_cast<uint16_t>(i * 131 % 65536);
  }
  LmdTelegramHeader header;
  header.telegram_counter = 0xFFFF;
  header.scan_counter = 0xABCD;
  header.time_since_startup_us = 0xFFFFF000u;
  header.time_of_transmission_us = 0x00000A00u;
  header.device_status[0] = 1;
  LmdOutputOptions options;
  options.send_device_name = true;
  options.device_name = "two words";
  options.send_time_info = true;
  options.time_info = calendar_time_from_epoch_us(1700000000123456ULL);
  std::string out;
  encode_lmd_scandata(header, LmdBeamLayout{}, dist.data(), rssi.data(), dist.size(), options, out);

  LmdScanData parsed;
  const ParseResult result = parse_lmd_scandata(out, parsed);
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_TRUE(parsed.is_stream_event);
  EXPECT_EQ(parsed.serial_number, 0x8D4C04u);
  EXPECT_EQ(parsed.device_status[0], 1u);
  EXPECT_EQ(parsed.telegram_counter, 0xFFFFu);
  EXPECT_EQ(parsed.scan_counter, 0xABCDu);
  EXPECT_EQ(parsed.time_since_startup_us, 0xFFFFF000u);
  EXPECT_EQ(parsed.time_of_transmission_us, 0xA00u);
  EXPECT_EQ(parsed.scan_frequency_1e2hz, 5000u);
  EXPECT_EQ(parsed.measurement_frequency_1e1khz, 360u);
  ASSERT_EQ(parsed.channels16.size(), 2u);
  EXPECT_EQ(parsed.channels16[0].name, "DIST1");
  EXPECT_EQ(parsed.channels16[0].start_angle_1e4deg, -450000);
  EXPECT_EQ(parsed.channels16[0].step_1e4deg, 5000u);
  EXPECT_EQ(parsed.channels16[0].values, dist);
  EXPECT_EQ(parsed.channels16[1].name, "RSSI1");
  EXPECT_EQ(parsed.channels16[1].values, rssi);
  EXPECT_TRUE(parsed.channels8.empty());
  EXPECT_TRUE(parsed.has_name);
  EXPECT_EQ(parsed.name, "two words");
  ASSERT_TRUE(parsed.has_time_info);
  EXPECT_EQ(parsed.time_info.year, 2023u);
  EXPECT_EQ(parsed.time_info.month, 11u);
  EXPECT_EQ(parsed.time_info.day, 14u);
  EXPECT_EQ(parsed.time_info.hour, 22u);
  EXPECT_EQ(parsed.time_info.minute, 13u);
  EXPECT_EQ(parsed.time_info.second, 20u);
  EXPECT_EQ(parsed.time_info.microsecond, 123456u);
}

TEST(LmdScandataEncoder, EightBitRssiRoundTripsThroughTheDriverParser) {
  std::vector<uint16_t> dist = {100, 200, 300}, rssi = {1, 254, 255};
  LmdOutputOptions options;
  options.rssi_bits = 8;
  std::string out;
  encode_lmd_scandata(LmdTelegramHeader{}, LmdBeamLayout{}, dist.data(), rssi.data(), 3, options, out);
  LmdScanData parsed;
  ASSERT_TRUE(parse_lmd_scandata(out, parsed).ok());
  ASSERT_EQ(parsed.channels8.size(), 1u);
  int bits = 0;
  const LmdChannel* channel = parsed.find_channel("RSSI1", &bits);
  ASSERT_NE(channel, nullptr);
  EXPECT_EQ(bits, 8);
  EXPECT_EQ(channel->values, rssi);
}

TEST(LmdScandataEncoder, EmptyScanKeepsItsChannelsAndParses) {
  std::string out;
  encode_lmd_scandata(LmdTelegramHeader{}, LmdBeamLayout{}, nullptr, nullptr, 0, LmdOutputOptions{}, out);
  EXPECT_EQ(out,
            "sSN LMDscandata 1 1 8D4C04 0 0 0 0 0 0 0 0 7 0 0 1388 168 0 2 "
            "DIST1 3F800000 00000000 FFF92230 1388 0 RSSI1 3F800000 00000000 FFF92230 1388 0 0 0 0 0 0 0");
  LmdScanData parsed;
  EXPECT_TRUE(parse_lmd_scandata(out, parsed).ok());
}

TEST(ColaAText, WritesHexUpperCaseWithoutLeadingZeros) {
  std::string s;
  append_cola_hex(s, 0);
  s += ' ';
  append_cola_hex(s, 0x21D);
  s += ' ';
  append_cola_hex_i32(s, -450000);
  s += ' ';
  append_cola_hex_float(s, 1.0F);
  s += ' ';
  append_cola_hex_float(s, 0.0F);
  s += ' ';
  append_cola_string(s, "not defined");
  EXPECT_EQ(s, "0 21D FFF92230 3F800000 00000000 B not defined");
}

TEST(ColaAText, ReadsSignedDecimalAndPlainHexRequestNumbers) {
  int64_t v = 0;
  EXPECT_TRUE(parse_cola_request_number("+5000", v));
  EXPECT_EQ(v, 5000);
  EXPECT_TRUE(parse_cola_request_number("-450000", v));
  EXPECT_EQ(v, -450000);
  EXPECT_TRUE(parse_cola_request_number("1388", v));
  EXPECT_EQ(v, 5000);
  EXPECT_TRUE(parse_cola_request_number("FFF92230", v));
  EXPECT_EQ(v, -450000);
  EXPECT_TRUE(parse_cola_request_number("03", v));
  EXPECT_EQ(v, 3);
  EXPECT_FALSE(parse_cola_request_number("", v));
  EXPECT_FALSE(parse_cola_request_number("+", v));
  EXPECT_FALSE(parse_cola_request_number("12G", v));
  EXPECT_FALSE(parse_cola_request_number("123456789", v));
  EXPECT_FALSE(parse_cola_request_number("+12a", v));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
