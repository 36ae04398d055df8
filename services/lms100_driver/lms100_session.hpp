#pragma once
// One LMS100 (or another SICK scanner of a device profile) over CoLa-A or CoLa-B/TCP, kept alive forever:
// connect, configure, wait until ready, stream scans to a callback; on any failure close the socket, back off
// (0.5 s doubling to 5 s) and start over. Never exits on a sensor fault, never busy-loops.
// (docs/lms100-protocol.md §4, §7.)

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "common/cola_a_framing.hpp"
#include "common/laser_scan.hpp"
#include "lms100_driver/cola_a_commands.hpp"
#include "lms100_driver/cola_wire.hpp"
#include "lms100_driver/device_profile.hpp"
#include "lms100_driver/lmd_scandata.hpp"
#include "lms100_driver/scan_plausibility.hpp"
#include "lms100_driver/scan_stamper.hpp"
#include "lms100_driver/tcp_connection.hpp"

namespace refloc {

struct Lms100SessionConfig {
  std::string host = "192.168.0.1";
  uint16_t port = 2111;
  ColaDialect dialect = ColaDialect::kColaA;  ///< the same dialogue in either (cola_wire.hpp)
  DeviceProfile device = lms1xx_profile();    ///< limits scans are checked against, range limits
  ScanConfig scan;                            ///< sent with mLMPsetscancfg when set_scan_config
  bool set_scan_config = true;
  ScanDataOutputConfig output;
  double connect_timeout_s = 2.0;     ///< [s]
  double reply_timeout_s = 3.0;       ///< per command [s]
  double ready_timeout_s = 120.0;     ///< STlms must reach 7 within this [s] (real: 30-45 s after a change)
  double status_poll_period_s = 0.5;  ///< [s]
  double first_scan_timeout_s = 2.0;  ///< after sEA LMDscandata 1 [s]
  /// No scan for this many scan periods → reconnect. 10 (200 ms at 50 Hz): a dead link is
  /// still noticed at once, but a host starved of CPU for a few periods (3 did that under
  /// load, costing 28 scans per needless reconnect) keeps its connection.
  double scan_timeout_periods = 10.0;
  double backoff_initial_s = 0.5;       ///< [s]
  double backoff_max_s = 5.0;           ///< [s]
  double stop_reply_timeout_s = 0.5;    ///< for the polite sEN 0 / LMCstopmeas on stop [s]
  uint32_t max_parse_error_streak = 5;  ///< consecutive bad scans → reconnect
  size_t max_frame_bytes = cola::kMaxTelegramBytes;
  ScanStamperConfig stamping;  ///< clock filter and the hold after a connect (scan_stamper.hpp)

  /// Nominal scan period from the requested frequency [s].
  double scan_period_s() const { return 100.0 / scan.frequency_1e2hz; }
};

/// Everything the session counts; atomics so another thread can read them.
struct Lms100SessionCounters {
  std::atomic<uint64_t> connects{0};  ///< TCP connections established
  std::atomic<uint64_t> connect_failures{0};
  std::atomic<uint64_t> reconnects{0};  ///< sessions that failed and were restarted
  std::atomic<uint64_t> timeouts{0};    ///< reply, readiness and scan timeouts
  std::atomic<uint64_t> sfa_errors{0};
  std::atomic<uint64_t> parse_errors{0};
  std::atomic<uint64_t> garbage_bytes{0};
  std::atomic<uint64_t> resyncs{0};
  std::atomic<uint64_t> oversized_frames{0};
  std::atomic<uint64_t> unexpected_frames{0};  ///< frames that answer nothing we asked
  std::atomic<uint64_t> scans{0};
  std::atomic<uint64_t> scan_counter_gaps{0};  ///< times the scan counter skipped
  std::atomic<uint64_t> lost_scans{0};         ///< scans missing in those gaps
  /// Scans refused by check_scan_plausibility, in all and per reason (never published).
  std::atomic<uint64_t> implausible_scans{0};
  std::atomic<uint64_t> multi_layer_scans{0};  ///< layer angle != 0 (an MRS): refused, never interleaved
  std::atomic<uint64_t> implausible_scale{0};
  std::atomic<uint64_t> implausible_offset{0};
  std::atomic<uint64_t> implausible_scan_frequency{0};
  std::atomic<uint64_t> implausible_beam_count{0};
  std::atomic<uint64_t> implausible_angles{0};
  std::atomic<uint64_t> implausible_beam_timing{0};
  std::atomic<uint64_t> reserved_distance_codes{0};  ///< beams with a code 2..15, published as no echo
  // Stamping (scan_stamper.hpp): what was delayed or dropped so that every stamp is supported.
  std::atomic<uint64_t> scans_in_bursts{0};        ///< scans that shared their read with a later one
  std::atomic<uint64_t> held_scans{0};             ///< scans published after the clock settled
  std::atomic<uint64_t> held_scans_dropped{0};     ///< held scans never published
  std::atomic<uint64_t> utime_not_increasing{0};   ///< scans dropped: stamp not after the previous
  std::atomic<int64_t> held_scan_max_delay_us{0};  ///< longest read-to-publish delay of a held scan [us]
  std::atomic<uint64_t> clock_restarts{0};  ///< clock fits restarted on a host clock step or sensor reboot
};

enum class SessionState { kConnecting, kConfiguring, kWaitingReady, kStreaming, kBackoff, kStopped };
const char* to_string(SessionState state);

class Lms100Session {
 public:
  using ScanCallback = std::function<void(const LaserScan&)>;
  /// Called from the session's thread on every state change, with a human-readable detail.
  using StateCallback = std::function<void(SessionState, const std::string&)>;
  /// Called from the session's thread for every scan refused as implausible.
  using RejectCallback = std::function<void(const ScanPlausibility&)>;

  Lms100Session(Lms100SessionConfig config, ScanCallback on_scan, StateCallback on_state = {});
  ~Lms100Session();
  Lms100Session(const Lms100Session&) = delete;
  Lms100Session& operator=(const Lms100Session&) = delete;

  /// Set before run()/start_thread(): who hears about refused scans.
  void set_reject_callback(RejectCallback on_rejected) { on_rejected_ = std::move(on_rejected); }

  /// Runs until stop(); blocks the calling thread.
  void run();
  /// Makes run() return within a poll cycle. Thread-safe and async-signal-safe
  /// (an atomic store and a write() to a pipe), so it may be called from a signal handler.
  void stop();
  /// run() on a thread owned by the session; join() or the destructor ends it.
  void start_thread();
  /// stop() and wait for the thread started by start_thread().
  void join();

  const Lms100SessionCounters& counters() const { return counters_; }
  SessionState state() const { return state_.load(); }
  bool stop_requested() const { return stop_.load(); }

 private:
  enum class Wait { kReply, kScan, kTimeout, kStopped, kClosed, kSopasError, kParseErrors };

  using ReplyCheck = std::function<ParseResult(const std::string&)>;

  /// One connection from connect to failure or stop; returns why it ended.
  std::string run_connection();
  /// Login, scan and output configuration, start of measurement; "" or why it failed.
  std::string configure_sensor();
  /// Polls STlms until 7 (ready) or ready_timeout_s; "" or why it failed.
  std::string wait_until_ready(const std::string& where);
  /// Receives scans until a scan timeout, a link failure or a stop; returns why it ended.
  std::string stream_scans();
  /// transact() and check the reply; false with why on no reply or a failed check.
  bool command(const std::string& request, const ReplyCheck& check, std::string& reply, std::string& why);
  /// Sends request and waits for its reply (scans meanwhile go to the scan path).
  Wait transact(const std::string& request, double timeout_s, std::string& reply, std::string& why);
  /// Reads and dispatches frames until a reply to request (if any), a scan (if return_on_scan),
  /// the deadline, a stop, or a link failure.
  Wait pump(const std::string* request, int64_t deadline_us, bool return_on_scan, std::string& reply,
            std::string& why);
  /// Parses one sSN/sRA LMDscandata and adds it to the stamper when plausible (else counts it
  /// and tells on_rejected_); false on a parse error. Nothing is published here.
  bool handle_scan(const std::string& payload, int64_t receive_utime);
  /// Every frame read so far is handled: the stamper's releasable scans go to on_scan_.
  void publish_stamped_scans();
  void stop_streaming_politely();
  void set_state(SessionState state, const std::string& detail);
  bool sleep_interruptible(double seconds);
  void sync_wire_counters();
  void count_rejection(const ScanPlausibility& verdict);

  /// Upper bound on one poll() so a stop flag set without the wake pipe is seen [ms].
  static constexpr int kMaxPollMs = 100;

  Lms100SessionConfig config_;
  ScanCallback on_scan_;
  StateCallback on_state_;
  RejectCallback on_rejected_;
  Lms100SessionCounters counters_;
  std::atomic<SessionState> state_{SessionState::kConnecting};
  std::atomic<bool> stop_{false};
  int wake_pipe_[2] = {-1, -1};
  std::thread thread_;

  TcpConnection link_;
  ColaWire wire_;
  std::vector<uint8_t> receive_buffer_;
  std::string frame_;
  std::string frame_text_;  ///< frame_ as CoLa-A text (itself on a CoLa-A link)
  LmdScanData scan_data_;
  LaserScan scan_;
  ScanStamper stamper_;
  bool have_last_scan_counter_ = false;
  uint32_t last_scan_counter_ = 0;
  uint32_t parse_error_streak_ = 0;
  int64_t last_read_utime_ = 0;  ///< host time of the read that completed the frames being handled
};

}  // namespace refloc
