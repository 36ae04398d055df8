#pragma once
// The names of heartbeat_t's states, for log lines and status tables ("OK", not "state 1").
// Header-only and LCM-free: refloc-status's table model uses it without the LCM types; a test
// checks the values against heartbeat_t::STATE_*.

#include <cstdint>
#include <string>

namespace refloc {

/// "STARTING", "OK", "DEGRADED", "ERROR", "STOPPING"; "STATE_7" for a value heartbeat_t does not define.
inline std::string heartbeat_state_name(int8_t state) {
  switch (state) {
    case 0:
      return "STARTING";
    case 1:
      return "OK";
    case 2:
      return "DEGRADED";
    case 3:
      return "ERROR";
    case 4:
      return "STOPPING";
    default:
      return "STATE_" + std::to_string(static_cast<int>(state));
  }
}

}  // namespace refloc
