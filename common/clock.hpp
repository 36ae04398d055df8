#pragma once
#include <cstdint>

namespace refloc {
/// Wall-clock time in microseconds since the Unix epoch, as LCM utime fields carry it.
int64_t now_utime();
/// Monotonic time in microseconds (for durations and timers, never for messages).
int64_t monotonic_us();
}  // namespace refloc
