#pragma once
// CoLa-A framing and number formatting for requests (LMS100_PROTOCOL.md §1.2).

#include <string>

namespace refloc {

inline constexpr char kColaStx = '\x02';
inline constexpr char kColaEtx = '\x03';

/// Wraps a telegram payload in STX/ETX.
std::string frame_cola_a(const std::string& payload);

}  // namespace refloc
