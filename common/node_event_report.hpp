#pragma once
// The LCM edge of NodeEvent: bump the runtime's heartbeat counters, write the log lines.
// Lines of an event with a counter are rate-limited per counter (one a second, saying how
// many were held back): every event is counted, not every event is written.

#include "common/clock.hpp"
#include "common/log_rate_limiter.hpp"
#include "common/node_event.hpp"
#include "common/service_runtime.hpp"

#include <vector>

namespace refloc {

inline void report_events(ServiceRuntime& runtime, const std::vector<NodeEvent>& events) {
  static LogRateLimiter limiter;  // one process, one runtime: one limiter
  for (const NodeEvent& e : events) {
    if (e.counter != nullptr) ++runtime.counter(e.counter);
    if (e.log.empty()) continue;
    int64_t suppressed = 0;
    if (e.counter != nullptr && !limiter.allow(e.counter, monotonic_us(), suppressed)) continue;
    const auto level = e.level == NodeEvent::Level::kWarn   ? spdlog::level::warn
                       : e.level == NodeEvent::Level::kInfo ? spdlog::level::info
                                                            : spdlog::level::debug;
    if (suppressed > 0) {
      spdlog::log(level, "{} ({} more like it in the last second, counter {})", e.log, suppressed, e.counter);
    } else {
      spdlog::log(level, "{}", e.log);
    }
  }
}

}  // namespace refloc
