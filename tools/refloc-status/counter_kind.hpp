#pragma once
// Which heartbeat counters are faults and which only describe normal work. HEARTBEAT carries
// both kinds under one list; refloc-status shows the faults apart so a glance finds them.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace refloc {

using NamedCounters = std::vector<std::pair<std::string, int64_t>>;

/// False for the counters and gauges that count normal work (connects, scans, fixes_accepted,
/// range_bias_um, ...: the list in counter_kind.cpp); true for every other name, so a fault
/// counter a service adds later shows as an error until it is listed as normal.
bool is_error_counter(const std::string& name);

struct SplitCounters {
  NamedCounters errors;  ///< non-zero fault counters, in the heartbeat's order
  NamedCounters normal;  ///< non-zero counters of normal work
};

/// The non-zero counters of one heartbeat, split by is_error_counter.
SplitCounters split_counters(const NamedCounters& counters);

/// How many fault counters are non-zero, decode_errors included: the narrow table's ERRORS
/// column. Kinds, not a sum: some fault counters are gauges (lcm_recv_buf_clamped_to_bytes).
int error_kinds(int64_t decode_errors, const NamedCounters& counters);

}  // namespace refloc
