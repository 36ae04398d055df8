#pragma once
// CoLa-B (binary) framing and LMDscandata decoding (docs/lms100-protocol.md §3, §5.1).
// Our driver speaks CoLa-A on 2111; this reads recorded CoLa-B sessions (e.g.
// the sick_scan_xd LMS111 capture) into the same LmdScanData, so the two
// dialects can be checked against each other.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "lms100_driver/lmd_scandata.hpp"
#include "lms100_driver/parse_result.hpp"

namespace refloc {

/// Checks one complete frame (02020202, uint32 big-endian length N, N payload bytes, XOR of
/// the payload) and returns its payload.
ParseResult unframe_cola_b(std::string_view frame, std::string_view& payload);

/// Decodes a CoLa-B "sSN LMDscandata " / "sRA LMDscandata " payload. Strings in the
/// name/comment blocks are read as uint16 length + characters (the width is unverified;
/// LMS1xx drivers keep these blocks off).
ParseResult parse_lmd_scandata_cola_b(std::string_view payload, LmdScanData& out);

}  // namespace refloc
