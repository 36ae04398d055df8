#pragma once
// One-line text commands that change the emulator's faults at runtime (typed on
// the emulator's stdin during a demo, or sent by a test harness):
//
//   drop N | stall MS | close | reset | refuse-write | ready on|off
//   split none|random|boundaries | merge N | junk N | duplicate on|off | status

#include "lms100_emulator/fault_injection.hpp"

#include <string>

namespace refloc {

/// Applies one command; message says what was done or why the line was refused.
/// Returns false for an unknown or malformed command (nothing is changed then).
bool apply_fault_command(const std::string& line, FaultInjector& faults, std::string& message);

}  // namespace refloc
