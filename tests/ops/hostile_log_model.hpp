#pragma once
// What hostile_log_check needs of the hostile-bus mission's LCM log and the peer's record:
// per-channel non-finite counts over the stack's own messages, the OK poses and the ground
// truth, every HEARTBEAT, and the peer's phases with what they sent where.

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace refloc::hostile {

/// Input channels per service, as in deploy/config/*.json; every ServiceRuntime also reads
/// HEARTBEAT (a second instance of itself), counting unreadable ones (lms100_driver: TCP only).
const std::vector<std::pair<std::string, std::vector<std::string>>> kSubscriptions = {
    {"lms100_driver", {"HEARTBEAT"}},
    {"reflector_extractor", {"LMS100_SCAN", "ODOMETRY", "HEARTBEAT"}},
    {"reflector_matcher", {"REFLECTORS", "POSE", "HEARTBEAT"}},
    {"pose_solver", {"REFLECTOR_MATCHES", "HEARTBEAT"}},
    {"mecanum_odometry", {"WHEEL_ENCODERS", "HEARTBEAT"}},
    {"pose_fusion", {"ODOMETRY", "LASER_POSE", "HEARTBEAT"}},
    {"navigator", {"NAV_GOAL", "POSE", "HEARTBEAT"}},
    {"robot_sim", {"CMD_VEL", "HEARTBEAT"}}};

/// A HEARTBEAT counter counts rejected input messages when its name matches kRejectionCounter
/// and not kNotInputRejection (ECMAScript, icase): decode_errors is added separately; the
/// extractor's rejected_occluded/shape/too_few_beams reject clusters of good scans, and
/// aggregates (goals_refused = the navigator's rejected_nav_goal_*) would count twice.
constexpr const char* kRejectionCounter =
    "^(rejected_|refused_|invalid_|unreadable_|implausible_|nonfinite_)";
constexpr const char* kNotInputRejection = "^rejected_(occluded|shape|too_few_beams)$";

struct Phase {
  std::string name;
  int64_t first_utime = 0;  ///< send time of its first datagram [us]
  int64_t last_utime = 0;
  std::map<std::string, int> sent_per_channel;  ///< what its consumer must refuse and count
  int harmless_sent = 0;                        ///< stamps nobody reads (NAV_GOAL, CMD_VEL)
  int sent_on(const std::string& channel) const {
    const auto it = sent_per_channel.find(channel);
    return it == sent_per_channel.end() ? 0 : it->second;
  }
};

struct ChannelTally {
  int64_t checked = 0;
  int64_t non_finite = 0;
  int64_t undecodable = 0;
  std::string first_non_finite;
  int64_t first_non_finite_utime = 0;  ///< logger time
};

struct OkPose {
  std::string channel;
  int64_t utime = 0;
  int64_t log_utime = 0;
  double x = 0, y = 0;
};

struct Heartbeat {
  int64_t utime = 0;
  int32_t pid = 0;
  int8_t state = 0;
  std::string detail;
  int64_t decode_errors = 0;
  std::map<std::string, int64_t> counters;
};

struct Growth {
  int64_t counted = 0;
  std::string why_unknown;  ///< set when no window could be measured (no heartbeat, restart)
};

struct LogModel {
  std::vector<Phase> phases;
  std::map<std::string, ChannelTally> channels;
  std::vector<OkPose> ok_poses;
  std::vector<std::pair<int64_t, std::pair<double, double>>> truth;  ///< utime -> (x, y), sorted
  std::map<std::string, std::vector<Heartbeat>> heartbeats;          ///< per service, in log order
  std::map<std::string, std::set<int32_t>> pids;
  int64_t hostile_sent = 0;
  int64_t hostile_logged = 0;
  int64_t stack_messages = 0;

  /// The phase whose window (its first datagram to the next phase's) holds t [us].
  std::string phase_at(int64_t utime) const;
  /// Distance of p from GROUND_TRUTH interpolated at p.utime; none without truth within 50 ms.
  std::optional<double> truth_error_m(const OkPose& p) const;
  /// p is stamped outside the span GROUND_TRUTH covers (robot_sim, the referee, had not started
  /// or had already stopped: `refloc stop` ends the programs one by one), so it cannot be judged.
  bool outside_truth_span(const OkPose& p) const {
    return truth.empty() || p.utime < truth.front().first || p.utime > truth.back().first;
  }
  /// decode_errors + rejection counters of service: growth over the phase's window.
  Growth rejection_growth(const std::string& service, const Phase& phase) const;
  /// Per service: the counters that grew over the whole log, "name +n" ("*": rejection counter).
  std::map<std::string, std::string> grown_counters() const;
  std::string last_state(const std::string& service) const;
};

/// Throws std::runtime_error when a file cannot be read.
LogModel read_log_model(const std::string& log_file, const std::string& record_file);

}  // namespace refloc::hostile
