#pragma once
// The LCM edge of NodeEvent: bump the runtime's heartbeat counters, write the log lines.

#include "common/node_event.hpp"
#include "common/service_runtime.hpp"

#include <vector>

namespace refloc {

inline void report_events(ServiceRuntime& runtime, const std::vector<NodeEvent>& events) {
  for (const NodeEvent& e : events) {
    if (e.counter != nullptr) ++runtime.counter(e.counter);
    if (e.log.empty()) continue;
    const auto level = e.level == NodeEvent::Level::kWarn   ? spdlog::level::warn
                       : e.level == NodeEvent::Level::kInfo ? spdlog::level::info
                                                            : spdlog::level::debug;
    spdlog::log(level, "{}", e.log);
  }
}

}  // namespace refloc
