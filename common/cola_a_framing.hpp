#pragma once
// SICK CoLa framing bytes and limits, shared by the LMS100 driver (which parses them) and
// the emulated LMS100 (which writes them). Only the constants are shared: the driver's
// parser and the emulator's encoder are written independently, so the emulator stays the
// driver's test oracle (docs/lms100-protocol.md §2.1-2.3).

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace refloc::cola {

/// CoLa-A: STX + ASCII payload + ETX, no length and no checksum.
inline constexpr char kStx = '\x02';
inline constexpr char kEtx = '\x03';

/// CoLa-B: 4 x STX magic, u32 big-endian payload length, payload, XOR checksum byte.
inline constexpr std::string_view kColaBMagic{"\x02\x02\x02\x02", 4};
inline constexpr size_t kColaBHeaderBytes = 8;    ///< magic + length field
inline constexpr size_t kColaBOverheadBytes = 9;  ///< header + checksum

/// Longest telegram payload either side keeps [bytes]: a 541-beam scan with 16-bit RSSI is
/// ~6 kB, so a frame longer than this has lost its ETX and must not grow memory.
inline constexpr size_t kMaxTelegramBytes = 65536;

}  // namespace refloc::cola
