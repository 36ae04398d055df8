#pragma once
// An LMS100 on TCP: CoLa-A (or CoLa-B) requests in, replies and the scan stream out, on a
// real-time, drift-free scan schedule, with fault injection. One client at a time
// (a new connection replaces the old one, as the device's single host port does).
// The server runs in its own thread between start() and stop().

#include "lms100_emulator/fault_injection.hpp"
#include "lms100_emulator/lms100_device.hpp"
#include "lms100_emulator/scan_source.hpp"

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

namespace refloc {

struct Lms100EmulatorConfig {
  std::string bind_address = "127.0.0.1";
  uint16_t port = 2111;  ///< 0 = ephemeral (tests); see Lms100Emulator::port()
  bool cola_b = false;   ///< speak CoLa-B (binary, SICK's port 2112) instead of CoLa-A
  Lms100DeviceConfig device;
  double processing_delay_s = 0.001;  ///< last beam to telegram ready [s]
  /// Transmission stamp to the bytes reaching the host, unseen by the host (a real LMS100's
  /// Ethernet: ~0.4 ms for a 5 kB telegram at 100 Mbit/s). The emulator writes the telegram this
  /// long after the stamp it puts in it, so the driver's stamps run this much late [s].
  double link_delay_s = 0.0;
  uint32_t power_up_clock_us = 0;       ///< device clock at power-up [us]; near 2^32 tests the wrap
  uint16_t first_telegram_counter = 0;  ///< near 65535 tests the counter wrap
  int startup_status_scans = 0;      ///< stream telegrams after sEN with device status "1 0" (real LMS111: 7)
  bool rtc_from_host_clock = false;  ///< time-info block: host UTC instead of the unset RTC (1970 + uptime)
  bool refuse_first_write_after_power_up = false;  ///< sFA 4 on the first sWN (sick_scan #44)
  int send_timeout_ms = 1000;  ///< a client that does not read for this long is dropped [ms]
  uint32_t random_seed = 1;    ///< for the split and junk faults
  FaultSettings faults;        ///< standing faults at start
};

/// Counts since start(), readable from any thread.
struct Lms100EmulatorStats {
  uint64_t clients_accepted = 0;
  uint64_t requests = 0;
  uint64_t scan_telegrams_sent = 0;  ///< sSN LMDscandata
  uint64_t scans_dropped = 0;        ///< by the drop fault
  uint64_t disconnects = 0;          ///< client closed, errors, and faults
};

class Lms100Emulator {
 public:
  Lms100Emulator(const Lms100EmulatorConfig& config, ScanSource source);
  ~Lms100Emulator();
  Lms100Emulator(const Lms100Emulator&) = delete;
  Lms100Emulator& operator=(const Lms100Emulator&) = delete;

  /// Power-up: binds, listens and starts the server thread. Throws std::runtime_error
  /// when the address cannot be bound.
  void start();
  /// Closes every socket and joins the thread; safe to call twice.
  void stop();
  /// The port actually listened on (valid after start()).
  uint16_t port() const { return bound_port_; }
  /// Runtime fault knobs (thread-safe).
  FaultInjector& faults() { return faults_; }
  Lms100EmulatorStats stats() const;
  /// Host wall-clock time [us] at which the device clock read power_up_clock_us.
  int64_t power_up_utime() const { return power_up_utime_; }

 private:
  struct Server;
  Lms100EmulatorConfig config_;
  ScanSource source_;
  FaultInjector faults_;
  std::unique_ptr<Server> server_;
  std::thread thread_;
  uint16_t bound_port_ = 0;
  int64_t power_up_utime_ = 0;
  int wake_pipe_[2] = {-1, -1};
  std::atomic<bool> stop_requested_{false};
};

}  // namespace refloc
