// Every refloc LCM type mapped to JSON field by field, one to_json per type (17 types);
// longer than 300 lines because the mapping is one table that reads best in one place.
#include "message_json.hpp"

#include "common/lcm_bounded_decode.hpp"

#include <fmt/format.h>
#include <refloc/heartbeat_t.hpp>
#include <refloc/laser_scan_t.hpp>
#include <refloc/map_candidate_t.hpp>
#include <refloc/map_health_t.hpp>
#include <refloc/map_reflector_health_t.hpp>
#include <refloc/nav_goal_t.hpp>
#include <refloc/nav_status_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_cluster_t.hpp>
#include <refloc/reflector_clusters_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_match_t.hpp>
#include <refloc/reflector_matches_t.hpp>
#include <refloc/reflector_t.hpp>
#include <refloc/twist_t.hpp>
#include <refloc/wheel_encoders_t.hpp>

#include <string>

namespace refloc {
namespace {

/// The double nearest to the float's shortest decimal form, so JSON shows what was sent.
double f32(float value) { return std::stod(fmt::format("{}", value)); }

OrderedJson f32_array(const std::vector<float>& values) {
  OrderedJson a = OrderedJson::array();
  for (float v : values) a.push_back(f32(v));
  return a;
}

template <class T, size_t N>
OrderedJson fixed_array(const T (&values)[N]) {
  OrderedJson a = OrderedJson::array();
  for (const T& v : values) a.push_back(v);
  return a;
}

int64_t read_be_int64(const uint8_t* data) {
  uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v = (v << 8) | data[i];
  return static_cast<int64_t>(v);
}

OrderedJson to_json(const reflector_t& m) {
  return {{"x", m.x},
          {"y", m.y},
          {"covariance", fixed_array(m.covariance)},
          {"range", m.range},
          {"bearing", m.bearing},
          {"utime", m.utime},
          {"first_beam", m.first_beam},
          {"nbeams", m.nbeams},
          {"mean_rssi", f32(m.mean_rssi)},
          {"roundness_m", f32(m.roundness_m)},
          {"fitted_radius_m", f32(m.fitted_radius_m)}};
}

OrderedJson to_json(const reflector_match_t& m) {
  return {{"detection", to_json(m.detection)},
          {"map_id", m.map_id},
          {"map_x", m.map_x},
          {"map_y", m.map_y},
          {"map_radius", m.map_radius}};
}

OrderedJson to_json(const heartbeat_t& m) {
  return {{"utime", m.utime},
          {"service", m.service},
          {"pid", m.pid},
          {"state", static_cast<int>(m.state)},
          {"state_detail", m.state_detail},
          {"uptime_us", m.uptime_us},
          {"messages_in", m.messages_in},
          {"messages_out", m.messages_out},
          {"decode_errors", m.decode_errors},
          {"processing_p50_us", f32(m.processing_p50_us)},
          {"processing_p99_us", f32(m.processing_p99_us)},
          {"ncounters", m.ncounters},
          {"counter_names", m.counter_names},
          {"counter_values", m.counter_values}};
}

OrderedJson to_json(const laser_scan_t& m) {
  return {{"utime", m.utime},
          {"receive_utime", m.receive_utime},
          {"sensor_start_us", m.sensor_start_us},
          {"sensor_transmit_us", m.sensor_transmit_us},
          {"scan_counter", m.scan_counter},
          {"telegram_counter", m.telegram_counter},
          {"device_status", m.device_status},
          {"serial_number", m.serial_number},
          {"start_angle", f32(m.start_angle)},
          {"angle_increment", f32(m.angle_increment)},
          {"time_increment", f32(m.time_increment)},
          {"scan_period", f32(m.scan_period)},
          {"range_min", f32(m.range_min)},
          {"range_max", f32(m.range_max)},
          {"nranges", m.nranges},
          {"ranges", f32_array(m.ranges)},
          {"nrssi", m.nrssi},
          {"rssi", m.rssi},
          {"rssi_bits", static_cast<int>(m.rssi_bits)}};
}

OrderedJson to_json(const nav_goal_t& m) {
  return {{"utime", m.utime},
          {"goal_id", m.goal_id},
          {"xy_tolerance", m.xy_tolerance},
          {"heading_tolerance", m.heading_tolerance},
          {"max_speed", m.max_speed},
          {"nwaypoints", m.nwaypoints},
          {"x", m.x},
          {"y", m.y},
          {"theta", m.theta}};
}

OrderedJson to_json(const nav_status_t& m) {
  return {{"utime", m.utime},
          {"goal_id", m.goal_id},
          {"state", static_cast<int>(m.state)},
          {"waypoint_index", m.waypoint_index},
          {"waypoints_reached", m.waypoints_reached},
          {"nwaypoints", m.nwaypoints},
          {"distance_to_waypoint", m.distance_to_waypoint},
          {"heading_error", m.heading_error},
          {"reason", m.reason}};
}

OrderedJson to_json(const odometry_t& m) {
  return {{"utime", m.utime},
          {"x", m.x},
          {"y", m.y},
          {"theta", m.theta},
          {"vx", m.vx},
          {"vy", m.vy},
          {"wz", m.wz},
          {"covariance", fixed_array(m.covariance)},
          {"distance", m.distance},
          {"slip_indicator", m.slip_indicator}};
}

OrderedJson to_json(const pose2d_t& m) {
  return {{"utime", m.utime},
          {"x", m.x},
          {"y", m.y},
          {"theta", m.theta},
          {"covariance", fixed_array(m.covariance)},
          {"status", static_cast<int>(m.status)},
          {"reflectors_used", m.reflectors_used},
          {"residual", m.residual}};
}

OrderedJson to_json(const reflector_cluster_t& m) {
  return {{"first_beam", m.first_beam},
          {"last_beam", m.last_beam},
          {"nbeams", m.nbeams},
          {"outcome", m.outcome},
          {"range", m.range},
          {"bearing", m.bearing},
          {"max_rssi_8bit", m.max_rssi_8bit}};
}

OrderedJson to_json(const reflector_clusters_t& m) {
  OrderedJson clusters = OrderedJson::array();
  for (const auto& c : m.clusters) clusters.push_back(to_json(c));
  return {{"utime", m.utime},
          {"scan_counter", m.scan_counter},
          {"energy_threshold_8bit", m.energy_threshold_8bit},
          {"energy_threshold_raw", m.energy_threshold_raw},
          {"rssi_read_as_8bit", m.rssi_read_as_8bit != 0},
          {"nclusters", m.nclusters},
          {"clusters", std::move(clusters)}};
}

OrderedJson to_json(const reflector_detections_t& m) {
  OrderedJson reflectors = OrderedJson::array();
  for (const auto& r : m.reflectors) reflectors.push_back(to_json(r));
  return {{"utime", m.utime},
          {"scan_counter", m.scan_counter},
          {"clusters_considered", m.clusters_considered},
          {"clusters_rejected", m.clusters_rejected},
          {"nreflectors", m.nreflectors},
          {"reflectors", std::move(reflectors)}};
}

OrderedJson to_json(const reflector_matches_t& m) {
  OrderedJson matches = OrderedJson::array();
  for (const auto& r : m.matches) matches.push_back(to_json(r));
  return {{"utime", m.utime},
          {"scan_counter", m.scan_counter},
          {"status", static_cast<int>(m.status)},
          {"mode", static_cast<int>(m.mode)},
          {"hypothesis_score", m.hypothesis_score},
          {"runner_up_score", m.runner_up_score},
          {"hypothesis_x", m.hypothesis_x},
          {"hypothesis_y", m.hypothesis_y},
          {"hypothesis_theta", m.hypothesis_theta},
          {"ndetections", m.ndetections},
          {"nmatches", m.nmatches},
          {"matches", std::move(matches)}};
}

OrderedJson to_json(const map_reflector_health_t& m) {
  return {{"id", m.id},
          {"state", static_cast<int>(m.state)},
          {"map_x", m.map_x},
          {"map_y", m.map_y},
          {"seen", m.seen},
          {"expected_missing", m.expected_missing},
          {"offset_x", m.offset_x},
          {"offset_y", m.offset_y},
          {"offset_sigma_x", m.offset_sigma_x},
          {"offset_sigma_y", m.offset_sigma_y}};
}

OrderedJson to_json(const map_candidate_t& m) {
  return {{"x", m.x},
          {"y", m.y},
          {"sigma_x", m.sigma_x},
          {"sigma_y", m.sigma_y},
          {"sightings", m.sightings},
          {"viewpoint_spread", m.viewpoint_spread},
          {"moved_reflector_id", m.moved_reflector_id}};
}

OrderedJson to_json(const map_health_t& m) {
  OrderedJson reflectors = OrderedJson::array();
  for (const auto& r : m.reflectors) reflectors.push_back(to_json(r));
  OrderedJson candidates = OrderedJson::array();
  for (const auto& c : m.candidates) candidates.push_back(to_json(c));
  return {{"utime", m.utime},
          {"map_id", m.map_id},
          {"map_version", m.map_version},
          {"scans_used", m.scans_used},
          {"reflectors_ok", m.reflectors_ok},
          {"reflectors_missing", m.reflectors_missing},
          {"reflectors_moved", m.reflectors_moved},
          {"reflectors_unconfirmed", m.reflectors_unconfirmed},
          {"nreflectors", m.nreflectors},
          {"reflectors", std::move(reflectors)},
          {"ncandidates", m.ncandidates},
          {"candidates", std::move(candidates)}};
}

OrderedJson to_json(const twist_t& m) {
  return {{"utime", m.utime}, {"vx", m.vx}, {"vy", m.vy}, {"wz", m.wz}};
}

OrderedJson to_json(const wheel_encoders_t& m) {
  return {{"utime", m.utime}, {"ticks", fixed_array(m.ticks)}};
}

// Arrays of structs get one default element in the prototype (see prototype()).
template <class Message>
Message prototype_message() {
  return Message{};
}
template <>
reflector_detections_t prototype_message() {
  reflector_detections_t m{};
  m.reflectors.resize(1);
  return m;
}
template <>
reflector_matches_t prototype_message() {
  reflector_matches_t m{};
  m.matches.resize(1);
  return m;
}
template <>
reflector_clusters_t prototype_message() {
  reflector_clusters_t m{};
  m.clusters.resize(1);
  return m;
}
template <>
map_health_t prototype_message() {
  map_health_t m{};
  m.reflectors.resize(1);
  m.candidates.resize(1);
  return m;
}

}  // namespace

template <class Message>
void MessageDecoder::add(bool utime_first) {
  Type t;
  t.name = Message::getTypeName();
  t.utime_first = utime_first;
  t.decode = [](const uint8_t* data, size_t size, OrderedJson& out) {
    Message m;
    if (!decode_lcm_bounded(data, size, m).ok) return false;
    out = to_json(m);
    return true;
  };
  t.prototype = to_json(prototype_message<Message>());
  by_fingerprint_[Message::getHash()] = types_.size();
  types_.push_back(std::move(t));
}

MessageDecoder::MessageDecoder() {
  add<heartbeat_t>(true);
  add<map_candidate_t>(false);
  add<map_health_t>(true);
  add<map_reflector_health_t>(false);
  add<laser_scan_t>(true);
  add<nav_goal_t>(true);
  add<nav_status_t>(true);
  add<odometry_t>(true);
  add<pose2d_t>(true);
  add<reflector_cluster_t>(false);
  add<reflector_clusters_t>(true);
  add<reflector_detections_t>(true);
  add<reflector_match_t>(false);
  add<reflector_matches_t>(true);
  add<reflector_t>(false);
  add<twist_t>(true);
  add<wheel_encoders_t>(true);
}

const MessageDecoder::Type* MessageDecoder::find(const uint8_t* data, size_t size) const {
  if (size < 8) return nullptr;
  const auto it = by_fingerprint_.find(read_be_int64(data));
  return it == by_fingerprint_.end() ? nullptr : &types_[it->second];
}

const char* MessageDecoder::type_name(const uint8_t* data, size_t size) const {
  const Type* t = find(data, size);
  return t ? t->name.c_str() : nullptr;
}

std::optional<DecodedMessage> MessageDecoder::decode(const uint8_t* data, size_t size) const {
  const Type* t = find(data, size);
  if (t == nullptr || size > static_cast<size_t>(INT32_MAX)) return std::nullopt;
  DecodedMessage m{t->name, {}};
  if (!t->decode(data, size, m.fields)) return std::nullopt;
  return m;
}

std::optional<int64_t> MessageDecoder::utime(const uint8_t* data, size_t size) const {
  const Type* t = find(data, size);
  if (t == nullptr || !t->utime_first || size < 16) return std::nullopt;
  return read_be_int64(data + 8);
}

const OrderedJson* MessageDecoder::prototype(const std::string& type) const {
  for (const auto& t : types_) {
    if (t.name == type) return &t.prototype;
  }
  return nullptr;
}

std::vector<std::string> MessageDecoder::type_names() const {
  std::vector<std::string> names;
  for (const auto& t : types_) names.push_back(t.name);
  return names;
}

}  // namespace refloc
