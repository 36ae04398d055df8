#pragma once
// What one message did inside a service's node, for the heartbeat and the log:
// a counter to bump by one and/or a log line. Nodes (LCM-free) return these;
// main.cpp hands them to report_events() (common/node_event_report.hpp).

#include <string>

namespace refloc {

struct NodeEvent {
  enum class Level { kDebug, kInfo, kWarn };
  const char* counter = nullptr;  ///< heartbeat counter to bump by one; nullptr: none
  Level level = Level::kDebug;
  std::string log;  ///< empty: nothing to log
};

/// An event that only bumps a counter.
inline NodeEvent counted(const char* counter) { return {counter, NodeEvent::Level::kDebug, {}}; }

}  // namespace refloc
