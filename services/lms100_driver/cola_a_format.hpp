#pragma once
// CoLa-A framing and number formatting for requests (docs/lms100-protocol.md §2.1-2.3).

#include "common/cola_a_framing.hpp"

#include <string>

namespace refloc {

/// Wraps a telegram payload in STX/ETX.
std::string frame_cola_a(const std::string& payload);

}  // namespace refloc
