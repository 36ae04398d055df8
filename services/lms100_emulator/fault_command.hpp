#pragma once
// One-line text commands that change the emulator's faults at runtime (typed on
// the emulator's stdin during a demo, or sent by a test harness):
//
//   drop N | stall MS | close | reset | refuse-write | ready on|off
//   split none|random|boundaries | merge N | junk N | duplicate on|off | status
//   scale F | offset MM | scan-frequency N (Hz x 100, 0 = own) | beam-rate N (x 100 Hz, 0 = own)
//   codes on|off (reserved distance codes 2..15 in beams 0..13) | layer N (layer angle, x 1e-4 deg,
//   uint16; != 0 is a multi-layer telegram) | header ok (every header field honest)

#include "lms100_emulator/fault_injection.hpp"

#include <atomic>
#include <functional>
#include <string>
#include <thread>
#include <utility>

namespace refloc {

/// Applies one command; message says what was done or why the line was refused.
/// Returns false for an unknown or malformed command (nothing is changed then).
bool apply_fault_command(const std::string& line, FaultInjector& faults, std::string& message);

/// Called with each non-blank command line's outcome: accepted, and the message.
using FaultCommandReport = std::function<void(bool accepted, const std::string& message)>;

/// Reads newline-ended commands from fd (the emulator's stdin) and applies them until stop
/// is set (seen within 200 ms) or fd ends.
void run_fault_commands(int fd, FaultInjector& faults, const std::atomic<bool>& stop,
                        const FaultCommandReport& report);

/// run_fault_commands() on its own thread from construction to destruction.
class FaultCommandThread {
 public:
  FaultCommandThread(int fd, FaultInjector& faults, FaultCommandReport report)
      : thread_([this, fd, &faults, report = std::move(report)] {
          run_fault_commands(fd, faults, stop_, report);
        }) {}
  ~FaultCommandThread() {
    stop_ = true;
    thread_.join();
  }
  FaultCommandThread(const FaultCommandThread&) = delete;
  FaultCommandThread& operator=(const FaultCommandThread&) = delete;

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace refloc
