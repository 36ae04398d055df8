#pragma once
// heartbeat_t as HeartbeatSample, at the edge: refloc-status's table and refloc-mission's
// range-bias report read the same conversion. (Header-only: only mains, which link the LCM
// types, include it; refloc_status_lib stays LCM-free.)

#include "heartbeat_table.hpp"

#include <refloc/heartbeat_t.hpp>

#include <algorithm>

namespace refloc {

/// Every field of the message; counters paired by index (a malformed count pairs the shorter list).
inline HeartbeatSample heartbeat_from_lcm(const heartbeat_t& m) {
  HeartbeatSample s;
  s.service = m.service;
  s.pid = m.pid;
  s.state = m.state;
  s.state_detail = m.state_detail;
  s.utime = m.utime;
  s.uptime_us = m.uptime_us;
  s.messages_in = m.messages_in;
  s.messages_out = m.messages_out;
  s.decode_errors = m.decode_errors;
  s.processing_p50_us = m.processing_p50_us;
  s.processing_p99_us = m.processing_p99_us;
  const size_t n = std::min(m.counter_names.size(), m.counter_values.size());
  for (size_t i = 0; i < n; ++i) s.counters.emplace_back(m.counter_names[i], m.counter_values[i]);
  return s;
}

}  // namespace refloc
