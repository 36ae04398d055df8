#pragma once
// Lms100Emulator's server thread state (internal to the emulator library, included by
// lms100_emulator.cpp and emulator_scan_telegram.cpp only): the device model, the client
// socket, the fault state in force, and the reused telegram buffers.

#include "common/angles.hpp"
#include "common/clock.hpp"
#include "lms100_emulator/cola_a_request_reader.hpp"
#include "lms100_emulator/cola_b_wire.hpp"
#include "lms100_emulator/lms100_emulator.hpp"

#include <atomic>
#include <cstdint>
#include <mutex>
#include <random>
#include <string>
#include <vector>

namespace refloc {

/// Beam rate of every LMS1xx [kHz x 10] (36 kHz).
inline constexpr uint32_t kMeasurementFrequency1e1khz = 360;
/// Time between two beams [s].
inline constexpr double kTimeIncrementS = 1.0 / (kMeasurementFrequency1e1khz * 100.0);

struct Lms100Emulator::Server {
  Server(const Lms100EmulatorConfig& c, ScanSource& s, FaultInjector& f, int wake,
         std::atomic<bool>& stop_flag)
      : config(c),
        source(s),
        faults(f),
        wake_fd(wake),
        stop(stop_flag),
        device(c.device),
        telegram_counter(c.first_telegram_counter),
        rng(c.random_seed) {}

  void run();
  uint64_t device_now() const { return static_cast<uint64_t>(monotonic_us() - power_up_mono_us); }
  void accept_new_client();
  void read_client();
  void handle_request(const std::string& request);
  void emit_scan(const ScanSlot& slot, bool stream);
  void send_frame(const std::string& body, bool is_scan);
  void write_out(const std::string& bytes);
  void flush_merged();
  void disconnect();
  void apply_faults(int64_t now_mono);

  const Lms100EmulatorConfig& config;
  ScanSource& source;
  FaultInjector& faults;
  int wake_fd;
  std::atomic<bool>& stop;

  Lms100Device device;
  ColaARequestReader request_reader;
  ColaBRequestReader request_reader_b;  ///< config.cola_b
  int listen_fd = -1;
  int client_fd = -1;
  int64_t power_up_mono_us = 0;
  int64_t power_up_utime = 0;
  uint16_t telegram_counter;
  bool stream_was_enabled = false;
  int stream_telegrams = 0;
  std::mt19937 rng;
  FaultSettings settings;
  int64_t stalled_until_mono = 0;
  int merged_count = 0;

  std::string request, reply, body, framed, merge_buffer, stall_buffer, binary;
  std::vector<uint16_t> dist_mm, rssi;
  std::vector<size_t> cuts;

  std::mutex stats_mutex;
  Lms100EmulatorStats stats;
};

}  // namespace refloc
