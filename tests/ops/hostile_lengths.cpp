// Lying lengths: the right fingerprint, then a length field that promises more (or less) than
// the datagram holds. The lie is patched into a correct encoding at the length's byte offset,
// which is checked against the true length first, so a layout change fails loudly here.

#include "hostile_messages.hpp"

#include <unistd.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace refloc {
namespace {

int32_t read_be32(const std::vector<uint8_t>& b, size_t offset) {
  if (offset + 4 > b.size()) throw std::logic_error("hostile_lengths: offset past the datagram");
  const uint32_t u = (uint32_t{b[offset]} << 24) | (uint32_t{b[offset + 1]} << 16) |
                     (uint32_t{b[offset + 2]} << 8) | uint32_t{b[offset + 3]};
  return static_cast<int32_t>(u);
}

void write_be32(std::vector<uint8_t>& b, size_t offset, int32_t value) {
  const auto u = static_cast<uint32_t>(value);
  for (int i = 0; i < 4; ++i) b[offset + static_cast<size_t>(i)] = static_cast<uint8_t>(u >> (24 - 8 * i));
}

/// Which lie: -1, 2^31-1, 50,000,000 or one element more than the bytes after the field hold.
enum class Lie { kMinusOne, kInt32Max, kFiftyMillion, kOneMoreThanLeft };
const Lie kLies[] = {Lie::kMinusOne, Lie::kInt32Max, Lie::kFiftyMillion, Lie::kOneMoreThanLeft};

const char* lie_name(Lie lie) {
  switch (lie) {
    case Lie::kMinusOne:
      return "-1";
    case Lie::kInt32Max:
      return "2147483647";
    case Lie::kFiftyMillion:
      return "50000000";
    case Lie::kOneMoreThanLeft:
      return "left+1";
  }
  return "?";
}

/// The correct encoding with the int32 length at offset replaced by the lie. true_length is
/// what the field holds now (checked); element_size the smallest encoding of one element.
std::vector<uint8_t> lie_about(std::vector<uint8_t> bytes, size_t offset, int32_t true_length,
                               size_t element_size, Lie lie) {
  if (read_be32(bytes, offset) != true_length)
    throw std::logic_error("hostile_lengths: length not at its offset");
  const size_t left = bytes.size() - offset - 4;
  int32_t value = -1;
  if (lie == Lie::kInt32Max) value = std::numeric_limits<int32_t>::max();
  if (lie == Lie::kFiftyMillion) value = 50'000'000;
  if (lie == Lie::kOneMoreThanLeft) value = static_cast<int32_t>(left / element_size + 1);
  write_be32(bytes, offset, value);
  return bytes;
}

size_t string_field_size(const std::string& s) { return 4 + s.size() + 1; }

/// Offset of heartbeat_t.ncounters: hash, utime, service, pid, state, state_detail,
/// uptime_us, messages_in/out, decode_errors, p50, p99.
size_t heartbeat_ncounters_offset(const heartbeat_t& h) {
  return 8 + 8 + string_field_size(h.service) + 4 + 1 + string_field_size(h.state_detail) + 4 * 8 + 2 * 4;
}

template <class Message>
HostileRecipe truncated(const std::string& channel, Message Bases::*base) {
  return {channel, std::string(Message::getTypeName()) + " one byte short", [base](const Bases& b, int64_t) {
            auto bytes = encode_message(b.*base);
            bytes.pop_back();
            return bytes;
          }};
}

}  // namespace

HostilePhase length_phase() {
  HostilePhase phase{"length", {}};
  auto& r = phase.recipes;
  for (const Lie lie : kLies) {
    const std::string v = lie_name(lie);
    r.push_back({"LMS100_SCAN", "laser_scan_t.nranges=" + v, [lie](const Bases& b, int64_t) {
                   return lie_about(encode_message(b.scan), 80, b.scan.nranges, 4, lie);
                 }});
    r.push_back({"LMS100_SCAN", "laser_scan_t.nrssi=" + v, [lie](const Bases& b, int64_t) {
                   const size_t offset = 84 + 4 * static_cast<size_t>(b.scan.nranges);
                   return lie_about(encode_message(b.scan), offset, b.scan.nrssi, 4, lie);
                 }});
    r.push_back({"REFLECTORS", "reflector_detections_t.nreflectors=" + v, [lie](const Bases& b, int64_t) {
                   const size_t element = static_cast<size_t>(reflector_t{}._getEncodedSizeNoHash());
                   return lie_about(encode_message(b.detections), 28, b.detections.nreflectors, element, lie);
                 }});
    r.push_back({"REFLECTOR_MATCHES", "reflector_matches_t.nmatches=" + v, [lie](const Bases& b, int64_t) {
                   const size_t element = static_cast<size_t>(reflector_match_t{}._getEncodedSizeNoHash());
                   return lie_about(encode_message(b.matches), 66, b.matches.nmatches, element, lie);
                 }});
    r.push_back({"NAV_GOAL", "nav_goal_t.nwaypoints=" + v, [lie](const Bases& b, int64_t) {
                   return lie_about(encode_message(b.goal), 48, b.goal.nwaypoints, 3 * 8, lie);
                 }});
    r.push_back({"HEARTBEAT", "heartbeat_t.ncounters=" + v, [lie](const Bases& b, int64_t) {
                   const size_t offset = heartbeat_ncounters_offset(b.heartbeat);
                   return lie_about(encode_message(b.heartbeat), offset, b.heartbeat.ncounters, 4 + 1 + 8,
                                    lie);
                 }});
    // A string's length counts its NUL: 0 and -1 make the generated decoder copy size_t(-1 or -2).
    r.push_back({"HEARTBEAT", "heartbeat_t.service(string length)=" + v, [lie](const Bases& b, int64_t) {
                   const auto length = static_cast<int32_t>(b.heartbeat.service.size() + 1);
                   return lie_about(encode_message(b.heartbeat), 16, length, 1, lie);
                 }});
  }
  r.push_back({"HEARTBEAT", "heartbeat_t.service(string length)=0", [](const Bases& b, int64_t) {
                 auto bytes = encode_message(b.heartbeat);
                 write_be32(bytes, 16, 0);
                 return bytes;
               }});
  r.push_back(truncated("LMS100_SCAN", &Bases::scan));
  r.push_back(truncated("REFLECTORS", &Bases::detections));
  r.push_back(truncated("REFLECTOR_MATCHES", &Bases::matches));
  r.push_back(truncated("LASER_POSE", &Bases::laser_pose));
  r.push_back(truncated("POSE", &Bases::pose));
  r.push_back(truncated("ODOMETRY", &Bases::odometry));
  r.push_back(truncated("WHEEL_ENCODERS", &Bases::encoders));
  r.push_back(truncated("CMD_VEL", &Bases::command));
  r.push_back(truncated("NAV_GOAL", &Bases::goal));
  r.push_back(truncated("HEARTBEAT", &Bases::heartbeat));
  return phase;
}

Bases synthetic_bases(int64_t now_utime) {
  Bases b{};
  b.scan.utime = b.scan.receive_utime = now_utime;
  b.scan.start_angle = static_cast<float>(-135.0 * M_PI / 180.0);
  b.scan.angle_increment = static_cast<float>(0.5 * M_PI / 180.0);
  b.scan.scan_period = 0.02F;
  b.scan.time_increment = 0.02F / 720.0F;
  b.scan.range_min = 0.05F;
  b.scan.range_max = 20.0F;
  b.scan.nranges = b.scan.nrssi = 541;
  b.scan.ranges.assign(541, 5.0F);
  b.scan.rssi.assign(541, 100);
  b.scan.rssi_bits = 8;
  reflector_t d{};
  d.x = d.range = 3.0;
  d.covariance[0] = d.covariance[3] = 1e-5;
  d.utime = now_utime;
  d.nbeams = 5;
  d.mean_rssi = 200.0F;
  d.roundness_m = 0.002F;
  d.fitted_radius_m = 0.06F;
  b.detections.utime = now_utime;
  b.detections.nreflectors = 1;
  b.detections.reflectors = {d};
  reflector_match_t match{};
  match.detection = d;
  match.map_x = 11.0;
  match.map_y = 2.0;
  match.map_radius = 0.06;
  b.matches.utime = now_utime;
  b.matches.hypothesis_x = 8.0;
  b.matches.hypothesis_y = 2.0;
  b.matches.hypothesis_score = 5.0;
  b.matches.ndetections = b.matches.nmatches = 1;
  b.matches.matches = {match};
  pose2d_t pose{};
  pose.utime = now_utime;
  pose.x = 8.0;
  pose.y = 2.0;
  pose.covariance[0] = pose.covariance[4] = 1e-4;
  pose.covariance[8] = 1e-5;
  pose.reflectors_used = 4;
  pose.residual = 0.005;
  b.laser_pose = b.pose = pose;
  b.odometry.utime = now_utime;
  b.odometry.covariance[0] = b.odometry.covariance[4] = b.odometry.covariance[8] = 1e-6;
  b.encoders.utime = b.command.utime = now_utime;
  b.goal.utime = now_utime;
  b.goal.goal_id = 990001;
  b.goal.xy_tolerance = 0.01;
  b.goal.heading_tolerance = 0.0087;
  b.goal.max_speed = 1.0;
  b.goal.nwaypoints = 1;
  b.goal.x = {8.0};
  b.goal.y = {2.0};
  b.goal.theta = {0.0};
  b.heartbeat.utime = now_utime;
  b.heartbeat.service = "hostile_peer";
  b.heartbeat.pid = static_cast<int32_t>(getpid());
  b.heartbeat.state = heartbeat_t::STATE_OK;
  b.heartbeat.ncounters = 1;
  b.heartbeat.counter_names = {"sent"};
  b.heartbeat.counter_values = {0};
  return b;
}

}  // namespace refloc
