// The recorded CoLa-B sessions of a real LMS111 and LMS511 (sick_scan_xd's captures, the sensor's
// side: dialogue replies, events, scans; tests/lms100_driver/data/README.md) through the driver's
// own receive path: ColaWire's splitter and reply translation, the CoLa-B scan parser, the
// conversion and the device profile's plausibility check, as lms100_session_io.cpp runs them.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "lms100_driver/cola_b_commands.hpp"
#include "lms100_driver/cola_wire.hpp"
#include "lms100_driver/lmd_scandata_parser.hpp"
#include "lms100_driver/scan_conversion.hpp"
#include "lms100_driver/scan_plausibility.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

/// The captured TCP segments of the sensor, in order, as bytes.
std::vector<std::string> read_segments(const std::string& name) {
  std::ifstream in(std::string(REFLOC_SOURCE_DIR) + "/tests/lms100_driver/data/" + name);
  std::vector<std::string> segments;
  std::string line;
  while (std::getline(in, line)) {
    std::string bytes;
    for (size_t i = 0; i + 1 < line.size(); i += 2)
      bytes.push_back(static_cast<char>(std::stoi(line.substr(i, 2), nullptr, 16)));
    segments.push_back(bytes);
  }
  return segments;
}

struct Received {
  std::vector<LaserScan> scans;
  std::vector<ScanPlausibility> verdicts;
  std::vector<std::string> texts;  ///< every other frame as CoLa-A text
  std::vector<std::string> errors;
};

/// Feeds the bytes in pieces of chunk bytes (0: as captured) and handles every frame.
Received receive(const std::vector<std::string>& segments, size_t chunk, const DeviceProfile& device) {
  ColaWire wire(ColaDialect::kColaB, 65536);
  std::string stream;
  for (const auto& s : segments) stream += s;
  std::vector<std::string> pieces = segments;
  if (chunk > 0) {
    pieces.clear();
    for (size_t i = 0; i < stream.size(); i += chunk) pieces.push_back(stream.substr(i, chunk));
  }
  Received r;
  std::string frame;
  for (const auto& piece : pieces) {
    wire.feed(reinterpret_cast<const uint8_t*>(piece.data()), piece.size());
    while (wire.next(frame)) {
      if (is_lmd_scandata(frame)) {
        LmdScanData data;
        LaserScan scan;
        ParseResult p = wire.parse_scan(frame, data);
        if (p) p = to_laser_scan(data, scan);
        if (!p) {
          r.errors.push_back(p.error);
          continue;
        }
        r.scans.push_back(scan);
        r.verdicts.push_back(check_scan_plausibility(data, device));
        continue;
      }
      std::string text;
      if (const ParseResult p = wire.to_text(frame, text); !p) r.errors.push_back(p.error);
      r.texts.push_back(text);
    }
  }
  EXPECT_EQ(wire.garbage_bytes(), 0u);
  EXPECT_EQ(wire.resyncs(), 0u);
  return r;
}

bool contains(const std::vector<std::string>& texts, const std::string& text) {
  for (const auto& t : texts) {
    if (t == text) return true;
  }
  return false;
}

TEST(ColaBCapture, Lms111SessionRepliesAndTwentyScansPassTheDriversReceivePath) {
  const auto segments = read_segments("lms111_cola_b_session.hex");
  ASSERT_EQ(segments.size(), 73u);
  for (const size_t chunk : {size_t{0}, size_t{7}, size_t{1500}}) {
    const Received r = receive(segments, chunk, lms1xx_profile());
    EXPECT_TRUE(r.errors.empty()) << r.errors.front();
    ASSERT_EQ(r.scans.size(), 20u) << "chunk " << chunk;
    size_t repeated = 0;  // the capture holds one TCP retransmission of a scan segment
    for (size_t k = 0; k < r.scans.size(); ++k) {
      EXPECT_TRUE(r.verdicts[k]) << r.verdicts[k].detail;
      EXPECT_EQ(r.scans[k].ranges.size(), 541u);
      EXPECT_NEAR(r.scans[k].scan_period, 0.02, 1e-9);
      if (k == 0) continue;
      const uint32_t step = (r.scans[k].scan_counter - r.scans[k - 1].scan_counter) & 0xFFFFu;
      EXPECT_LE(step, 1u) << "scan " << k;
      repeated += step == 0;
    }
    EXPECT_EQ(repeated, 1u);
    // The replies the session checks, translated to the text its checks read.
    EXPECT_TRUE(contains(r.texts, "sAN SetAccessMode 1"));
    EXPECT_TRUE(contains(r.texts, "sWA LMDscandatacfg"));
    EXPECT_TRUE(contains(r.texts, "sAN LMCstartmeas 0"));
    EXPECT_TRUE(contains(r.texts, "sAN Run 1"));
    EXPECT_TRUE(contains(r.texts, "sEA LMDscandata 1"));
    EXPECT_TRUE(contains(r.texts, "sSN LIDoutputstate"));  // an event the session counts as unexpected
  }
}

TEST(ColaBCapture, Lms511SessionWithRssiAndSensorErrorsPassesWithTheLms5xxProfile) {
  const auto segments = read_segments("lms511_cola_b_session.hex");
  const DeviceProfile& lms5xx = *find_device_profile("lms5xx");
  const Received r = receive(segments, 0, lms5xx);
  EXPECT_TRUE(r.errors.empty()) << r.errors.front();
  ASSERT_EQ(r.scans.size(), 8u);
  for (size_t k = 0; k < r.scans.size(); ++k) {
    EXPECT_TRUE(r.verdicts[k]) << r.verdicts[k].detail;
    EXPECT_EQ(r.scans[k].ranges.size(), 1141u);
    EXPECT_EQ(r.scans[k].rssi_bits, 8);
    EXPECT_NEAR(r.scans[k].scan_period, 0.04, 1e-9);
  }
  EXPECT_TRUE(contains(r.texts, "sFA 3"));  // "sFA" + uint16 code: VARIABLE_UNKNOWNINDEX
  EXPECT_TRUE(contains(r.texts, "sAN SetAccessMode 1"));
  EXPECT_TRUE(contains(r.texts, "sEA LMDscandata 1"));
}

TEST(ColaBCapture, RecordedRequestsAreWhatTheDriverEncodes) {
  // Host requests of the LMS111 session, as sick_scan_xd sent them.
  const std::pair<const char*, std::string> cases[] = {
      {"sMN SetAccessMode 03 F4724744", std::string("sMN SetAccessMode \x03\xF4\x72\x47\x44", 23)},
      {"sEN LMDscandata 1", std::string("sEN LMDscandata \x01", 17)},
      {"sMN LMCstartmeas", "sMN LMCstartmeas"},
      {"sMN Run", "sMN Run"},
      {"sWN LMDscandatacfg 01 00 0 0 0 00 00 0 0 0 1 +1",
       std::string("sWN LMDscandatacfg \x01\x00\x00\x00\x00\x00\x00\x00\x00\x00\x01\x00\x01", 32)},
  };
  for (const auto& [text, binary] : cases) {
    std::string payload;
    ASSERT_TRUE(encode_cola_b_request(text, payload)) << text;
    EXPECT_EQ(payload, binary) << text;
  }
  std::string payload;
  EXPECT_FALSE(encode_cola_b_request("sMN SomethingElse 1", payload));
  EXPECT_FALSE(encode_cola_b_request("sEN LMDscandata 100", payload));  // does not fit a byte
}

TEST(ColaBCapture, ATruncatedReplyIsAnErrorNotARead) {
  std::string text;
  EXPECT_FALSE(decode_cola_b_reply("sAN SetAccessMode ", text));
  EXPECT_FALSE(decode_cola_b_reply(std::string("sFA\x00", 4), text));
  EXPECT_FALSE(decode_cola_b_reply("xy", text));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
