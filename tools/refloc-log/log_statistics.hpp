#pragma once
// Per-channel statistics of a log: message counts, rates, bytes, and the gaps
// between consecutive messages of a channel (the largest, and every gap longer
// than a threshold), from the log's receive timestamps.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace refloc {

struct ChannelSummary {
  std::string channel;
  std::string type;  ///< refloc type of its first message, "?" if unknown
  int64_t count = 0;
  int64_t bytes = 0;
  int64_t first_utime = 0;  ///< [us], log time
  int64_t last_utime = 0;
  double rate_hz = 0.0;           ///< (count - 1) / (last - first); 0 with fewer than 2 messages
  double largest_gap_s = 0.0;     ///< longest time between two consecutive messages [s]
  double largest_gap_at_s = 0.0;  ///< start of that gap, from the start of the log [s]
  int64_t largest_gap_event = 0;  ///< event number of the message that ended it
};

struct LogGap {
  std::string channel;
  double start_s = 0.0;   ///< from the start of the log [s]
  double length_s = 0.0;  ///< [s]
  int64_t end_event = 0;  ///< event number of the message that ended the gap
};

struct LogSummary {
  int64_t events = 0;
  int64_t first_utime = 0;
  int64_t last_utime = 0;
  double duration_s = 0.0;
  double largest_gap_s = 0.0;  ///< longest time with no message on any channel [s]
  double largest_gap_at_s = 0.0;
  double gap_threshold_s = 0.0;
  std::vector<ChannelSummary> channels;  ///< by channel name
  std::vector<LogGap> gaps;              ///< longer than gap_threshold_s, by start time
  size_t gaps_not_listed = 0;            ///< beyond max_gaps
};

class LogStatistics {
 public:
  /// Gaps longer than gap_threshold_s are listed, at most max_gaps of them.
  explicit LogStatistics(double gap_threshold_s = 0.5, size_t max_gaps = 100,
                         double heartbeat_silence_s = 3.0);

  /// Account one event; type is the refloc type name or nullptr.
  void add(const std::string& channel, int64_t log_utime, size_t bytes, int64_t eventnum, const char* type);
  /// A HEARTBEAT of one service. Every service beats on the same channel at the
  /// same moment, so that channel's gaps say nothing; a service silent for longer
  /// than max(gap threshold, heartbeat_silence_s) is listed as "HEARTBEAT(<service>)".
  void add_heartbeat(const std::string& channel, const std::string& service, int64_t log_utime,
                     int64_t eventnum);
  LogSummary summary() const;

 private:
  struct Accumulator {
    ChannelSummary s;
    int64_t largest_gap_us = -1;
    int64_t largest_gap_start_us = 0;
  };
  void add_gap(LogGap gap);

  double threshold_s_;
  size_t max_gaps_;
  double heartbeat_silence_s_;
  std::map<std::string, int64_t> last_heartbeat_utime_;  ///< by service
  std::map<std::string, Accumulator> channels_;
  std::vector<LogGap> gaps_;
  size_t gaps_not_listed_ = 0;
  int64_t events_ = 0;
  int64_t first_utime_ = 0;
  int64_t last_utime_ = 0;
  int64_t largest_gap_us_ = 0;
  int64_t largest_gap_start_us_ = 0;
};

}  // namespace refloc
