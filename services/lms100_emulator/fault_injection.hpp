#pragma once
// Faults seen on real LMS1xx links (docs/lms100-protocol.md §7), injected on
// purpose so the driver's recovery can be tested. Settings and one-shot actions
// are set from any thread; the emulator's server thread consumes them.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <random>
#include <string>
#include <vector>

namespace refloc {

enum class WriteSplitMode {
  none,        ///< every frame (or merged group) in one write
  random,      ///< cut at random positions into split_pieces writes
  boundaries,  ///< cut right after STX and right before ETX (the splitter's sync points)
};

/// Standing fault settings (they apply until changed).
struct FaultSettings {
  WriteSplitMode split_mode = WriteSplitMode::none;
  int split_pieces = 3;                  ///< writes per frame in random mode (>= 2)
  int split_gap_ms = 2;                  ///< pause between the pieces so they arrive in separate reads [ms]
  int merge_scan_telegrams = 1;          ///< > 1: this many scan telegrams go out in one write
  int junk_bytes_between_telegrams = 0;  ///< junk (never STX) written before each frame
  bool duplicate_replies = false;        ///< every command reply is sent twice
  bool refuse_readiness = false;         ///< STlms stays below 7, no scans are made
  // Implausible scan headers (issue 11): what a broken or foreign device might claim. The
  // beams are still rendered as usual; only the telegram's fields lie.
  float dist_scale = 1.0F;                    ///< DIST1 scale factor sent (an LMS1xx sends 1.0)
  float dist_offset_mm = 0.0F;                ///< DIST1 offset sent [mm] (an LMS1xx sends 0)
  uint32_t scan_frequency_1e2hz = 0;          ///< 0: the device's own; else claimed [Hz x 100]
  uint32_t measurement_frequency_1e1khz = 0;  ///< 0: the device's own; else claimed beam rate [kHz x 10]
  bool reserved_distance_codes = false;       ///< beams 0..13 carry the reserved codes 2..15
  /// Layer angle sent [deg x 1e4, uint16 two's complement]: != 0 claims a multi-layer MRS telegram.
  /// Set in the header before encoding, so it reaches CoLa-B telegrams too.
  uint16_t layer_angle_1e4deg = 0;

  /// Whether any header field is falsified.
  bool corrupts_scan_header() const;
};

/// Rewrites the header fields of an encoded LMDscandata payload (no STX/ETX, one DIST1
/// channel, no encoder) as the settings falsify them; a no-op with the default settings.
void corrupt_scan_header(const FaultSettings& settings, std::string& payload);

/// Cut positions (strictly inside (0, size)) for one write of size bytes.
void plan_write_cuts(size_t size, const FaultSettings& settings, std::mt19937& rng,
                     std::vector<size_t>& cuts);
/// Appends count junk bytes: any byte but STX, so no frame can start inside them.
void append_junk_bytes(size_t count, std::mt19937& rng, std::string& out);

class FaultInjector {
 public:
  FaultSettings settings() const;
  void set_settings(const FaultSettings& settings);

  /// The next n scans are made (scan counter advances) but not sent.
  void drop_next_scans(int n);
  /// Hold every outgoing byte for ms, then send what piled up in one burst.
  void stall_for_ms(int ms);
  /// Close the client's connection at once.
  void close_connection_now();
  /// Send the first half of the next scan telegram, then close the connection.
  void reset_mid_telegram();
  /// The next sWN (variable write) is answered with sFA 4.
  void refuse_next_write();

  // Consumers, called by the server thread.
  bool take_drop();
  int take_stall_ms();
  bool take_close_now();
  bool take_reset_mid_telegram();
  bool take_refuse_next_write();

  /// Called after every change so a waiting server thread wakes up.
  void set_change_listener(std::function<void()> listener);

 private:
  void notify();

  mutable std::mutex mutex_;
  FaultSettings settings_;
  int drops_pending_ = 0;
  int stall_ms_pending_ = 0;
  bool close_pending_ = false;
  bool reset_pending_ = false;
  bool refuse_write_pending_ = false;
  std::function<void()> listener_;
};

}  // namespace refloc
