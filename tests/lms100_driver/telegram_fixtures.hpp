#pragma once
// Test helpers: real telegrams from tests/data/sick-real and hand-written
// LMDscandata telegrams with RSSI in the 16- or 8-bit block.

#include <fmt/format.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace refloc::test {

/// The file's content without the surrounding STX/ETX.
inline std::string read_telegram_payload(const std::string& name) {
  std::ifstream in(std::string(REFLOC_SOURCE_DIR) + "/tests/data/sick-real/" + name, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t stx = bytes.find('\x02');
  const size_t etx = bytes.rfind('\x03');
  if (stx == std::string::npos || etx == std::string::npos || etx <= stx) return {};
  return bytes.substr(stx + 1, etx - stx - 1);
}

/// An LMS100-like sSN LMDscandata: 50 Hz, 0.5 deg, n beams, DIST1 (+ RSSI1 in the 16- or
/// 8-bit block when rssi_bits is 16 or 8), time info on.
inline std::string make_scan_telegram(const std::vector<unsigned>& dist_mm, const std::vector<unsigned>& rssi,
                                      int rssi_bits, unsigned scan_counter = 0x37,
                                      unsigned t_start_us = 0x280F6) {
  auto channel = [](const char* name, const std::vector<unsigned>& values) {
    std::string s = fmt::format("{} 3F800000 00000000 FFF92230 1388 {:X}", name, values.size());
    for (unsigned v : values) s += fmt::format(" {:X}", v);
    return s;
  };
  std::string t = fmt::format("sSN LMDscandata 1 1 8D4C04 0 0 {:X} {:X} {:X} {:X} 0 0 7 0 0 1388 168 0 ",
                              scan_counter + 0x4000, scan_counter, t_start_us, t_start_us + 2429);
  if (rssi_bits == 16) {
    t += "2 " + channel("DIST1", dist_mm) + " " + channel("RSSI1", rssi) + " 0";
  } else if (rssi_bits == 8) {
    t += "1 " + channel("DIST1", dist_mm) + " 1 " + channel("RSSI1", rssi);
  } else {
    t += "1 " + channel("DIST1", dist_mm) + " 0";
  }
  t += " 0 0 0 1 7EA B 1C 13 5 7 1E240 0";
  return t;
}

}  // namespace refloc::test
