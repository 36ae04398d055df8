// The emulator's CoLa-B against what real sensors sent: its scan encoder byte for byte against
// a recorded LMS111 frame, its request reading and reply writing against the recorded LMS111 and
// LMS511 sessions (tests/data/sick-real, tests/lms100_driver/data).
#include "lms100_emulator/cola_b_wire.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "lms100_driver/cola_b_scandata_parser.hpp"
#include "lms100_emulator/lmd_scandata_encoder.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::vector<std::string> recorded_lms111_frames() {
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

TEST(ColaBWire, ScanEncoderWritesTheRecordedLms111FramesByteForByte) {
  const auto frames = recorded_lms111_frames();
  ASSERT_EQ(frames.size(), 3u);
  for (const std::string& frame : frames) {
    std::string_view recorded;
    ASSERT_TRUE(unframe_cola_b(frame, recorded).ok());
    LmdScanData d;
    ASSERT_TRUE(parse_lmd_scandata_cola_b(recorded, d).ok());
    LmdTelegramHeader h;
    h.is_stream_event = d.is_stream_event;
    h.version = d.version;
    h.device_number = d.device_number;
    h.serial_number = d.serial_number;
    h.device_status[0] = d.device_status[0];
    h.device_status[1] = d.device_status[1];
    h.telegram_counter = static_cast<uint16_t>(d.telegram_counter);
    h.scan_counter = static_cast<uint16_t>(d.scan_counter);
    h.time_since_startup_us = d.time_since_startup_us;
    h.time_of_transmission_us = d.time_of_transmission_us;
    h.digital_inputs[0] = d.digital_inputs[0];
    h.digital_inputs[1] = d.digital_inputs[1];
    h.digital_outputs[0] = d.digital_outputs[0];
    h.digital_outputs[1] = d.digital_outputs[1];
    h.reserved = d.reserved_layer_angle;
    h.scan_frequency_1e2hz = d.scan_frequency_1e2hz;
    h.measurement_frequency_1e1khz = d.measurement_frequency_1e1khz;
    const LmdChannel& dist = d.channels16.at(0);
    LmdBeamLayout layout;
    layout.start_angle_1e4deg = dist.start_angle_1e4deg;
    layout.step_1e4deg = dist.step_1e4deg;
    LmdOutputOptions options;
    options.rssi_bits = 0;
    options.send_time_info = d.has_time_info;
    options.time_info = {d.time_info.year,   d.time_info.month,  d.time_info.day,        d.time_info.hour,
                         d.time_info.minute, d.time_info.second, d.time_info.microsecond};
    std::string encoded;
    encode_lmd_scandata_cola_b(h, layout, dist.values.data(), nullptr, dist.values.size(), options, encoded);
    EXPECT_EQ(encoded, recorded);
    std::string framed;
    frame_cola_b_telegram(encoded, framed);
    EXPECT_EQ(framed, frame);
  }
}

TEST(ColaBWire, RecordedRequestsBecomeTheTextTheDeviceReads) {
  const std::pair<std::string, const char*> cases[] = {
      {std::string("sMN SetAccessMode \x03\xF4\x72\x47\x44", 23), "sMN SetAccessMode 3 F4724744"},
      {std::string("sWN LMDscandatacfg \x01\x00\x01\x00\x00\x00\x00\x00\x00\x00\x01\x00\x01", 32),
       "sWN LMDscandatacfg 1 0 1 0 0 0 0 0 0 0 1 1"},
      {std::string("sEN LMDscandata \x01", 17), "sEN LMDscandata 1"},
      {"sMN Run", "sMN Run"},
      {"sRN STlms", "sRN STlms"},
      {std::string(
           "sMN mLMPsetscancfg \x00\x00\x13\x88\x00\x01\x00\x00\x13\x88\xFF\xF9\x22\x30\x00\x22\x55\x10", 37),
       "sMN mLMPsetscancfg 1388 1 1388 -450000 +2250000"},
  };
  for (const auto& [binary, text] : cases) {
    std::string out;
    EXPECT_TRUE(cola_b_request_to_text(binary, out)) << text;
    EXPECT_EQ(out, text);
  }
  std::string out;
  EXPECT_FALSE(
      cola_b_request_to_text(std::string("sEN LMDscandata \x01\x01", 18), out));  // one byte too many
}

TEST(ColaBWire, RepliesAreWrittenAsTheRecordedSensorsWroteThem) {
  const std::pair<const char*, std::string> cases[] = {
      {"sAN SetAccessMode 1", std::string("sAN SetAccessMode \x01", 19)},
      {"sWA LMDscandatacfg", "sWA LMDscandatacfg "},
      {"sAN LMCstartmeas 0", std::string("sAN LMCstartmeas \x00", 18)},
      {"sAN Run 1", std::string("sAN Run \x01", 9)},
      {"sEA LMDscandata 1", std::string("sEA LMDscandata \x01", 17)},
      {"sFA 3", std::string("sFA\x00\x03", 5)},  // LMS511: no space, uint16 code
  };
  for (const auto& [text, binary] : cases) {
    std::string out;
    cola_b_reply_from_text(text, out);
    EXPECT_EQ(out, binary) << text;
  }
}

TEST(ColaBWire, RequestReaderSkipsJunkAndBadChecksumsAndJoinsSplitReads) {
  std::string good;
  frame_cola_b_telegram("sMN Run", good);
  std::string bad = good;
  bad.back() = static_cast<char>(bad.back() ^ 0x55);
  const std::string stream = "junk" + bad + good;
  ColaBRequestReader reader;
  std::vector<std::string> requests;
  std::string request;
  for (const char c : stream) {
    reader.feed(reinterpret_cast<const uint8_t*>(&c), 1);
    while (reader.next(request)) requests.push_back(request);
  }
  ASSERT_EQ(requests.size(), 1u);
  EXPECT_EQ(requests[0], "sMN Run");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
