#pragma once
// The hostile peer's catalogue (tests/ops/hostile_bus_mission.sh): every bad message it sends
// to the live stack, grouped into phases. A message is built at send time from the latest REAL
// message on its channel (Bases), so it is interleaved with and looks like the real traffic,
// except for the one thing that is wrong: a lying length, a non-finite or huge field, a stamp
// far from now, an absurd twist.

#include <refloc/heartbeat_t.hpp>
#include <refloc/laser_scan_t.hpp>
#include <refloc/nav_goal_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_matches_t.hpp>
#include <refloc/twist_t.hpp>
#include <refloc/wheel_encoders_t.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace refloc {

/// The latest real message per input channel (synthetic until one was seen).
struct Bases {
  laser_scan_t scan;                  ///< LMS100_SCAN
  reflector_detections_t detections;  ///< REFLECTORS, latest with >= 1 reflector
  reflector_matches_t matches;        ///< REFLECTOR_MATCHES, latest with >= 1 match
  pose2d_t laser_pose;                ///< LASER_POSE
  pose2d_t pose;                      ///< POSE
  odometry_t odometry;                ///< ODOMETRY
  wheel_encoders_t encoders;          ///< WHEEL_ENCODERS
  twist_t command;                    ///< CMD_VEL
  nav_goal_t goal;                    ///< NAV_GOAL (the mission's own goal once seen)
  heartbeat_t heartbeat;              ///< HEARTBEAT (always synthetic: service "hostile_peer")
};

/// Plausible stand-ins for channels not seen yet.
Bases synthetic_bases(int64_t now_utime);

/// One bad datagram to publish.
struct HostileDatagram {
  std::string what;  ///< e.g. "laser_scan_t.nranges=-1", "odometry_t.vx=nan"
  std::vector<uint8_t> bytes;
};

/// One entry of the catalogue: builds its datagram from the bases at send time.
struct HostileRecipe {
  std::string channel;
  std::string what;
  std::function<std::vector<uint8_t>(const Bases&, int64_t now_utime)> build;
};

/// A class of bad messages sent together (the log check measures HEARTBEAT growth per phase).
struct HostilePhase {
  std::string name;  ///< "length", "stamp", "twist", "nonfinite:<CHANNEL>"
  std::vector<HostileRecipe> recipes;
};

/// Lying array and string lengths with the right fingerprint, and every subscribed type's
/// encoding cut one byte short (the lie of the fixed-size types).
HostilePhase length_phase();
/// utime +1 h, INT64_MAX, -1 h and 0 on every stamped input type.
HostilePhase stamp_phase();
/// Finite but absurd twists (1e308 m/s, 1e6 rad/s) on CMD_VEL and ODOMETRY.
HostilePhase twist_phase();
/// NaN, +inf and a huge finite value (1e300; 3e38 in float fields) in every numeric field,
/// one phase per channel.
std::vector<HostilePhase> nonfinite_phases();

/// All phases in sending order.
std::vector<HostilePhase> hostile_plan();

/// The LCM encoding (fingerprint first) of a generated message.
template <class Message>
std::vector<uint8_t> encode_message(const Message& m) {
  std::vector<uint8_t> bytes(static_cast<size_t>(m.getEncodedSize()));
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

/// FNV-1a over the datagram: how the log check recognizes the peer's own messages.
inline uint64_t datagram_hash(const uint8_t* data, size_t size) {
  uint64_t h = 1469598103934665603ULL;
  for (size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ULL;
  return h;
}

}  // namespace refloc
