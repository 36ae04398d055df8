#pragma once
// The emulator's side of CoLa-A text (docs/lms100-protocol.md §2.1-2.3, §4.1): numbers
// written the way an LMS100 writes them (upper-case hex, no leading zeros,
// two's-complement negatives, floats as 8 hex digits) and request arguments read
// the way it accepts them (plain hex, or decimal with an explicit +/- sign).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace refloc {

/// Appends value as upper-case hex without leading zeros ("0" for zero).
void append_cola_hex(std::string& out, uint32_t value);
/// Appends a signed value as 32-bit two's-complement hex (-450000 -> FFF92230).
void append_cola_hex_i32(std::string& out, int32_t value);
/// Appends the IEEE-754 bits of value as exactly 8 hex digits (1.0 -> 3F800000).
void append_cola_hex_float(std::string& out, float value);
/// Appends a string as "<hex length> <chars>" (the chars may contain spaces).
void append_cola_string(std::string& out, std::string_view text);

/// Splits a payload at single spaces; empty tokens (double spaces) are kept as
/// empty views so a malformed request can be told apart from a good one.
void split_cola_tokens(std::string_view payload, std::vector<std::string_view>& tokens);

/// Reads a request argument: "+5000" / "-450000" are decimal, anything else is
/// hex ("1388", "FFF92230", "03"). Hex is read as 32-bit two's complement, so
/// FFF92230 gives -450000. False on an empty token, a bad digit or overflow.
bool parse_cola_request_number(std::string_view token, int64_t& out);

/// True when every byte is printable ASCII (0x20..0x7E); a real LMS1xx answers
/// other bytes inside a CoLa-A frame with sFA 11 (sick_scan_xd #128).
bool is_printable_cola_text(std::string_view payload);

}  // namespace refloc
