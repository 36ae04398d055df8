#include "lms100_driver/lmd_scandata_parser.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "telegram_fixtures.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using test::make_scan_telegram;
using test::read_telegram_payload;

TEST(LmdScanDataParser, RealLms111TelegramDecodesEveryField) {
  const std::string payload = read_telegram_payload("lms111_cola_a_scan.txt");
  ASSERT_FALSE(payload.empty());
  LmdScanData d;
  const ParseResult r = parse_lmd_scandata(payload, d);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_FALSE(d.is_stream_event);
  EXPECT_EQ(d.version, 1u);
  EXPECT_EQ(d.device_number, 1u);
  EXPECT_EQ(d.serial_number, 0x8D4C04u);
  EXPECT_EQ(d.device_status[0], 0u);
  EXPECT_EQ(d.device_status[1], 0u);
  EXPECT_EQ(d.telegram_counter, 0x45FFu);
  EXPECT_EQ(d.scan_counter, 0x37u);
  EXPECT_EQ(d.time_since_startup_us, 164086u);
  EXPECT_EQ(d.time_of_transmission_us, 166515u);
  EXPECT_EQ(d.digital_outputs[0], 7u);
  EXPECT_EQ(d.reserved_layer_angle, 0u);
  EXPECT_EQ(d.scan_frequency_1e2hz, 5000u);
  EXPECT_EQ(d.measurement_frequency_1e1khz, 360u);
  EXPECT_TRUE(d.encoders.empty());
  ASSERT_EQ(d.channels16.size(), 1u);
  EXPECT_TRUE(d.channels8.empty());
  const LmdChannel& dist = d.channels16[0];
  EXPECT_EQ(dist.name, "DIST1");
  EXPECT_FLOAT_EQ(dist.scale, 1.0F);
  EXPECT_FLOAT_EQ(dist.offset, 0.0F);
  EXPECT_EQ(dist.start_angle_1e4deg, -450000);
  EXPECT_EQ(dist.step_1e4deg, 5000u);
  ASSERT_EQ(dist.values.size(), 541u);
  EXPECT_EQ(dist.values[0], 0x7E);
  EXPECT_EQ(dist.values[1], 0x82);
  EXPECT_EQ(dist.values[2], 0x7D);
  EXPECT_EQ(dist.values[540], 0x67);
  EXPECT_FALSE(d.has_position);
  ASSERT_TRUE(d.has_name);
  EXPECT_EQ(d.name, "Derecha");
  EXPECT_FALSE(d.has_comment);
  ASSERT_TRUE(d.has_time_info);
  EXPECT_EQ(d.time_info.year, 1970u);
  EXPECT_EQ(d.time_info.month, 1u);
  EXPECT_EQ(d.time_info.day, 1u);
  EXPECT_EQ(d.time_info.hour, 0u);
  EXPECT_EQ(d.time_info.minute, 42u);
  EXPECT_EQ(d.time_info.second, 39u);
  EXPECT_EQ(d.time_info.microsecond, 166000u);
  EXPECT_FALSE(d.has_event);
}

TEST(LmdScanDataParser, RealMrs1000TelegramHasThreeDistAndThree8BitRssiChannels) {
  const std::string payload = read_telegram_payload("mrs1000_cola_a.txt");
  ASSERT_FALSE(payload.empty());
  LmdScanData d;
  const ParseResult r = parse_lmd_scandata(payload, d);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(d.is_stream_event);
  EXPECT_EQ(d.serial_number, 0x107FA24u);
  EXPECT_EQ(d.reserved_layer_angle, 0xFE0Cu);
  ASSERT_EQ(d.channels16.size(), 3u);
  ASSERT_EQ(d.channels8.size(), 3u);
  EXPECT_EQ(d.channels16[2].name, "DIST3");
  EXPECT_EQ(d.channels8[0].name, "RSSI1");
  EXPECT_EQ(d.channels16[0].start_angle_1e4deg, -475000);
  EXPECT_EQ(d.channels16[0].step_1e4deg, 2500u);
  EXPECT_EQ(d.channels16[0].values.size(), 1101u);
  EXPECT_EQ(d.channels8[0].values.size(), 1101u);
  EXPECT_EQ(d.channels16[0].values[3], 0x6E0);
  int bits = 0;
  ASSERT_NE(d.find_channel("RSSI1", &bits), nullptr);
  EXPECT_EQ(bits, 8);
  EXPECT_TRUE(d.has_time_info);
  EXPECT_EQ(d.time_info.microsecond, 0xE9E30u);
}

TEST(LmdScanDataParser, Rssi16BitChannelIsSecondChannelOfThe16BitBlock) {
  LmdScanData d;
  const ParseResult r =
      parse_lmd_scandata(make_scan_telegram({500, 1, 0, 20000}, {100, 65535, 0, 64800}, 16), d);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(d.channels16.size(), 2u);
  EXPECT_EQ(d.channels16[1].name, "RSSI1");
  EXPECT_EQ(d.channels16[1].values, (std::vector<uint16_t>{100, 65535, 0, 64800}));
  EXPECT_EQ(d.channels16[0].values, (std::vector<uint16_t>{500, 1, 0, 20000}));
  EXPECT_TRUE(d.channels8.empty());
  EXPECT_EQ(d.time_info.year, 2026u);
  EXPECT_EQ(d.time_info.microsecond, 123456u);
}

TEST(LmdScanDataParser, Rssi8BitChannelIsInThe8BitBlock) {
  LmdScanData d;
  const ParseResult r = parse_lmd_scandata(make_scan_telegram({500, 600}, {254, 255}, 8), d);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(d.channels16.size(), 1u);
  ASSERT_EQ(d.channels8.size(), 1u);
  EXPECT_EQ(d.channels8[0].values, (std::vector<uint16_t>{254, 255}));
}

TEST(LmdScanDataParser, NameWithSpacesAndEncoderAndEventAreDecoded) {
  const std::string t =
      "sSN LMDscandata 1 1 1 0 0 1 2 3 4 0 0 0 0 0 9C4 168 1 3E8 2 1 DIST1 3F800000 00000000 6DDD0 9C4 2 10 "
      "11 0 "
      "0 1 B not defined 1 2 hi 0 1 FDIN 5 6 FFFFFFFF";
  LmdScanData d;
  const ParseResult r = parse_lmd_scandata(t, d);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(d.encoders.size(), 1u);
  EXPECT_EQ(d.encoders[0].position_ticks, 1000u);
  EXPECT_EQ(d.encoders[0].speed_ticks_per_mm, 2u);
  EXPECT_EQ(d.channels16[0].start_angle_1e4deg, 450000);
  EXPECT_EQ(d.name, "not defined");
  EXPECT_EQ(d.comment, "hi");
  ASSERT_TRUE(d.has_event);
  EXPECT_EQ(d.event.type, "FDIN");
  EXPECT_EQ(d.event.angle_1e4deg, -1);
}

TEST(LmdScanDataParser, ParsingAgainReusesVectorsWithoutGrowingThem) {
  const std::string payload = read_telegram_payload("lms111_cola_a_scan.txt");
  LmdScanData d;
  ASSERT_TRUE(parse_lmd_scandata(payload, d).ok());
  const uint16_t* data = d.channels16[0].values.data();
  ASSERT_TRUE(parse_lmd_scandata(payload, d).ok());
  EXPECT_EQ(d.channels16[0].values.data(), data);
}

TEST(LmdScanDataParser, TruncationAtEveryTokenIsAnError) {
  const std::string payload = read_telegram_payload("lms111_cola_a_scan.txt");
  LmdScanData d;
  size_t cuts = 0;
  for (size_t i = 0; i < payload.size(); ++i) {
    if (payload[i] != ' ') continue;
    ++cuts;
    // Both "...token" and "...token " must fail.
    EXPECT_FALSE(parse_lmd_scandata(payload.substr(0, i), d).ok()) << "cut before char " << i;
    EXPECT_FALSE(parse_lmd_scandata(payload.substr(0, i + 1), d).ok()) << "cut after char " << i;
  }
  EXPECT_EQ(cuts, 581u);
}

TEST(LmdScanDataParser, TruncationAtEveryByteNeverCrashes) {
  const std::string payload = read_telegram_payload("mrs1000_cola_a.txt");
  LmdScanData d;
  size_t failures = 0;
  for (size_t i = 0; i < payload.size(); ++i)
    failures += parse_lmd_scandata(payload.substr(0, i), d).ok() ? 0 : 1;
  EXPECT_EQ(failures, payload.size());
}

TEST(LmdScanDataParser, NonHexDigitNamesTheField) {
  std::string t = make_scan_telegram({500, 600}, {}, 0);
  t.replace(t.find(" 1F4 "), 5, " 1G4 ");
  LmdScanData d;
  const ParseResult r = parse_lmd_scandata(t, d);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error.find("data value"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("1G4"), std::string::npos) << r.error;
}

TEST(LmdScanDataParser, CountLargerThanDataIsAnError) {
  std::string t = make_scan_telegram({500, 600}, {}, 0);
  t.replace(t.find(" 1388 2 "), 8, " 1388 3 ");
  LmdScanData d;
  const ParseResult r = parse_lmd_scandata(t, d);
  EXPECT_FALSE(r.ok());
}

TEST(LmdScanDataParser, HugeCountIsRejectedBeforeAllocating) {
  std::string t = make_scan_telegram({500, 600}, {}, 0);
  t.replace(t.find(" 1388 2 "), 8, " 1388 FFFF ");
  LmdScanData d;
  const ParseResult r = parse_lmd_scandata(t, d);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error.find("number of data exceeds the telegram"), std::string::npos) << r.error;
  EXPECT_LT(d.channels16[0].values.capacity(), 100u);
}

TEST(LmdScanDataParser, CountSmallerThanDataLeavesTokensAndIsAnError) {
  std::string t = make_scan_telegram({500, 600, 700}, {}, 0);
  t.replace(t.find(" 1388 3 "), 8, " 1388 2 ");
  LmdScanData d;
  EXPECT_FALSE(parse_lmd_scandata(t, d).ok());
}

TEST(LmdScanDataParser, ValueTooLargeFor8BitChannelIsAnError) {
  LmdScanData d;
  const ParseResult r = parse_lmd_scandata(make_scan_telegram({500}, {256}, 8), d);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error.find("out of range"), std::string::npos) << r.error;
}

TEST(LmdScanDataParser, OverlongHexNumberIsAnError) {
  std::string t = make_scan_telegram({500}, {}, 0);
  t.replace(t.find(" 8D4C04 "), 8, " 123456789 ");
  LmdScanData d;
  const ParseResult r = parse_lmd_scandata(t, d);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error.find("serial number"), std::string::npos) << r.error;
}

TEST(LmdScanDataParser, StringLengthBeyondTelegramIsAnError) {
  LmdScanData d;
  const ParseResult r =
      parse_lmd_scandata("sSN LMDscandata 1 1 1 0 0 1 2 3 4 0 0 0 0 0 9C4 168 0 0 0 0 1 FF short", d);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error.find("device name"), std::string::npos) << r.error;
}

TEST(LmdScanDataParser, OtherTelegramsAreNotScanData) {
  LmdScanData d;
  EXPECT_FALSE(parse_lmd_scandata("sAN SetAccessMode 1", d).ok());
  EXPECT_FALSE(parse_lmd_scandata("", d).ok());
  EXPECT_TRUE(is_lmd_scandata("sSN LMDscandata 1"));
  EXPECT_FALSE(is_lmd_scandata("sEA LMDscandata 1"));
}

TEST(LmdScanDataParser, DoubleSpaceIsAnError) {
  std::string t = make_scan_telegram({500}, {}, 0);
  t.replace(t.find(" 8D4C04 "), 8, " 8D4C04  ");
  LmdScanData d;
  EXPECT_FALSE(parse_lmd_scandata(t, d).ok());
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
