#pragma once
// Cumulative int32 encoder counts wrap around; differences must not.

#include <cstdint>

namespace refloc {

/// now - before for counters that wrap as int32: correct as long as the true
/// difference is within +-2^31 ticks.
inline int32_t tick_delta(int32_t now, int32_t before) {
  // Unsigned arithmetic is modular by definition; the conversion back to int32
  // is modular in GCC/Clang (and by definition from C++20).
  return static_cast<int32_t>(static_cast<uint32_t>(now) - static_cast<uint32_t>(before));
}

}  // namespace refloc
