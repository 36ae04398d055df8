#include "lms100_driver/cola_b_scandata_parser.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "lms100_driver/scan_conversion.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

/// The three real LMS111 CoLa-B scan frames of tests/data/sick-real/lms111_cola_b_scans.hex.
std::vector<std::string> real_frames() {
  std::ifstream in(std::string(REFLOC_SOURCE_DIR) + "/tests/data/sick-real/lms111_cola_b_scans.hex");
  std::vector<std::string> frames;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::string bytes;
    for (size_t i = 0; i + 1 < line.size(); i += 2)
      bytes.push_back(static_cast<char>(std::stoi(line.substr(i, 2), nullptr, 16)));
    frames.push_back(bytes);
  }
  return frames;
}

TEST(ColaBScanDataParser, RealLms111FramesDecodeEveryField) {
  const auto frames = real_frames();
  ASSERT_EQ(frames.size(), 3u);
  std::string_view payload;
  ASSERT_TRUE(unframe_cola_b(frames[0], payload).ok());
  LmdScanData d;
  const ParseResult r = parse_lmd_scandata_cola_b(payload, d);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(d.is_stream_event);
  EXPECT_EQ(d.serial_number, 0x0114097Au);
  EXPECT_EQ(d.device_status[0], 1u);  // the first scans after streaming starts say "01 00"
  EXPECT_EQ(d.telegram_counter, 0xF768u);
  EXPECT_EQ(d.scan_counter, 4u);
  EXPECT_EQ(d.time_since_startup_us, 0x74287D59u);
  EXPECT_EQ(d.time_of_transmission_us, 0x74288993u);
  EXPECT_EQ(d.scan_frequency_1e2hz, 5000u);
  EXPECT_EQ(d.measurement_frequency_1e1khz, 360u);
  ASSERT_EQ(d.channels16.size(), 1u);
  EXPECT_EQ(d.channels16[0].name, "DIST1");
  EXPECT_EQ(d.channels16[0].start_angle_1e4deg, -450000);
  EXPECT_EQ(d.channels16[0].step_1e4deg, 5000u);
  ASSERT_EQ(d.channels16[0].values.size(), 541u);
  EXPECT_EQ(d.channels16[0].values[0], 93);
  EXPECT_EQ(d.channels16[0].values[1], 80);
  EXPECT_EQ(d.channels16[0].values[540], 77);
  EXPECT_TRUE(d.channels8.empty());
  ASSERT_TRUE(d.has_time_info);
  EXPECT_EQ(d.time_info.year, 1970u);
  EXPECT_EQ(d.time_info.hour, 2u);
  EXPECT_EQ(d.time_info.minute, 55u);
  EXPECT_EQ(d.time_info.second, 34u);
  EXPECT_EQ(d.time_info.microsecond, 889000u);

  LaserScan s;
  ASSERT_TRUE(to_laser_scan(d, s).ok());
  EXPECT_FLOAT_EQ(s.ranges[0], 0.093F);

  ASSERT_TRUE(unframe_cola_b(frames[2], payload).ok());
  ASSERT_TRUE(parse_lmd_scandata_cola_b(payload, d).ok());
  EXPECT_EQ(d.scan_counter, 0xAFu);
  EXPECT_EQ(d.device_status[0], 0u);
}

TEST(ColaBScanDataParser, CorruptFramesAreRejected) {
  auto frames = real_frames();
  ASSERT_FALSE(frames.empty());
  std::string frame = frames[1];
  std::string_view payload;
  std::string bad_checksum = frame;
  bad_checksum.back() = static_cast<char>(bad_checksum.back() ^ 1);
  EXPECT_FALSE(unframe_cola_b(bad_checksum, payload).ok());
  EXPECT_FALSE(unframe_cola_b(frame.substr(0, frame.size() - 1), payload).ok());
  EXPECT_FALSE(unframe_cola_b("\x02\x02\x02", payload).ok());

  ASSERT_TRUE(unframe_cola_b(frame, payload).ok());
  LmdScanData d;
  for (size_t cut = 0; cut < payload.size(); ++cut) {
    ASSERT_FALSE(parse_lmd_scandata_cola_b(payload.substr(0, cut), d).ok()) << "cut at " << cut;
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
