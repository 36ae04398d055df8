#pragma once
// CoLa-B on the wire (docs/lms100-protocol.md §3). The session builds its requests and checks
// its replies as CoLa-A text (cola_a_commands), so a CoLa-B link translates at the edge:
// requests text -> binary by the argument widths of each command the driver sends, replies
// binary -> the CoLa-A text the same checks read. Scan telegrams are not translated:
// parse_lmd_scandata_cola_b decodes them into the same LmdScanData as the CoLa-A parser.

#include <string>
#include <string_view>

#include "lms100_driver/parse_result.hpp"

namespace refloc {

/// 02020202, the payload length as big-endian uint32, the payload, the XOR of the payload.
std::string frame_cola_b(std::string_view payload);

/// One of the driver's CoLa-A requests ("sMN SetAccessMode 03 F4724744") as a CoLa-B payload
/// ("sMN SetAccessMode " 03 F4 72 47 44). Numbers with a sign are decimal, others hex, as in
/// CoLa-A. Fails for a command whose argument widths are not known here.
ParseResult encode_cola_b_request(std::string_view cola_a_request, std::string& payload);

/// A CoLa-B reply or event as the CoLa-A text the reply checks read: numbers in upper-case
/// hex, signed ones in two's complement ("sAN SetAccessMode 1", "sFA 3"). Arguments of a
/// reply whose layout is not known here are dropped ("sSN LIDoutputstate"): it can only be an
/// unexpected frame. Fails when the payload has no "type name" head or is shorter than its layout.
ParseResult decode_cola_b_reply(std::string_view payload, std::string& cola_a_text);

}  // namespace refloc
