// Longer than 300 lines because it holds one field-by-field fill and check per message type (12 types).
// Two real processes exchange every refloc message type over UDP multicast
// (run inside a private network namespace): this test publishes a sample of
// each type, lcm_echo_peer decodes and republishes it, and the echo is checked
// field by field. Also: a message that fails to decode is counted in the
// peer's HEARTBEAT and skipped, and SIGTERM ends the peer cleanly.

#include "tests/tools/child_process.hpp"

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/laser_scan_t.hpp>
#include <refloc/nav_goal_t.hpp>
#include <refloc/nav_status_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_match_t.hpp>
#include <refloc/reflector_matches_t.hpp>
#include <refloc/reflector_t.hpp>
#include <refloc/twist_t.hpp>
#include <refloc/wheel_encoders_t.hpp>

#include <chrono>
#include <map>

namespace refloc {
namespace {

const char* kUrl = "udpm://239.255.76.67:7667?ttl=0";

reflector_t sample_reflector(int k) {
  reflector_t r;
  r.x = 1.25 + k;
  r.y = -0.5 * k;
  for (int i = 0; i < 4; ++i) r.covariance[i] = 1e-5 * (i + 1) + k;
  r.range = 3.5 + k;
  r.bearing = -0.75 + 0.1 * k;
  r.utime = 1700000000123456 + k;
  r.first_beam = 100 + k;
  r.nbeams = 7 + k;
  r.mean_rssi = 61000.5f + k;
  r.roundness_m = 0.0031f;
  r.fitted_radius_m = 0.06f;
  return r;
}

void expect_eq(const reflector_t& a, const reflector_t& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(a.covariance[i], b.covariance[i]);
  EXPECT_EQ(a.range, b.range);
  EXPECT_EQ(a.bearing, b.bearing);
  EXPECT_EQ(a.utime, b.utime);
  EXPECT_EQ(a.first_beam, b.first_beam);
  EXPECT_EQ(a.nbeams, b.nbeams);
  EXPECT_EQ(a.mean_rssi, b.mean_rssi);
  EXPECT_EQ(a.roundness_m, b.roundness_m);
  EXPECT_EQ(a.fitted_radius_m, b.fitted_radius_m);
}

laser_scan_t sample_scan() {
  laser_scan_t m;
  m.utime = 1700000000000001;
  m.receive_utime = 1700000000020002;
  m.sensor_start_us = 4294967296LL + 5;  // past the uint32 wrap
  m.sensor_transmit_us = 4294967296LL + 3105;
  m.scan_counter = 65535;
  m.telegram_counter = 12;
  m.device_status = 0;
  m.serial_number = 0x8D4C04;
  m.start_angle = -2.35619449f;
  m.angle_increment = 0.00872664626f;
  m.time_increment = 2.7778e-05f;
  m.scan_period = 0.02f;
  m.range_min = 0.05f;
  m.range_max = 20.0f;
  for (int i = 0; i < 541; ++i) {
    m.ranges.push_back(0.001f * static_cast<float>(i * 7 % 20000));
    m.rssi.push_back(i * 121 % 65536);
  }
  m.nranges = static_cast<int32_t>(m.ranges.size());
  m.nrssi = static_cast<int32_t>(m.rssi.size());
  m.rssi_bits = 16;
  return m;
}

void expect_eq(const laser_scan_t& a, const laser_scan_t& b) {
  EXPECT_EQ(a.utime, b.utime);
  EXPECT_EQ(a.receive_utime, b.receive_utime);
  EXPECT_EQ(a.sensor_start_us, b.sensor_start_us);
  EXPECT_EQ(a.sensor_transmit_us, b.sensor_transmit_us);
  EXPECT_EQ(a.scan_counter, b.scan_counter);
  EXPECT_EQ(a.telegram_counter, b.telegram_counter);
  EXPECT_EQ(a.device_status, b.device_status);
  EXPECT_EQ(a.serial_number, b.serial_number);
  EXPECT_EQ(a.start_angle, b.start_angle);
  EXPECT_EQ(a.angle_increment, b.angle_increment);
  EXPECT_EQ(a.time_increment, b.time_increment);
  EXPECT_EQ(a.scan_period, b.scan_period);
  EXPECT_EQ(a.range_min, b.range_min);
  EXPECT_EQ(a.range_max, b.range_max);
  EXPECT_EQ(a.nranges, b.nranges);
  EXPECT_EQ(a.ranges, b.ranges);
  EXPECT_EQ(a.nrssi, b.nrssi);
  EXPECT_EQ(a.rssi, b.rssi);
  EXPECT_EQ(a.rssi_bits, b.rssi_bits);
}

reflector_detections_t sample_detections() {
  reflector_detections_t m;
  m.utime = 1700000000000002;
  m.scan_counter = 77;
  m.clusters_considered = 9;
  m.clusters_rejected = 3;
  for (int k = 0; k < 6; ++k) m.reflectors.push_back(sample_reflector(k));
  m.nreflectors = static_cast<int32_t>(m.reflectors.size());
  return m;
}

void expect_eq(const reflector_detections_t& a, const reflector_detections_t& b) {
  EXPECT_EQ(a.utime, b.utime);
  EXPECT_EQ(a.scan_counter, b.scan_counter);
  EXPECT_EQ(a.clusters_considered, b.clusters_considered);
  EXPECT_EQ(a.clusters_rejected, b.clusters_rejected);
  ASSERT_EQ(a.nreflectors, b.nreflectors);
  for (int k = 0; k < a.nreflectors; ++k) expect_eq(a.reflectors[k], b.reflectors[k]);
}

reflector_match_t sample_match(int k) {
  reflector_match_t m;
  m.detection = sample_reflector(k);
  m.map_id = 40 + k;
  m.map_x = 12.5 - k;
  m.map_y = 3.25 + k;
  m.map_radius = 0.06;
  return m;
}

void expect_eq(const reflector_match_t& a, const reflector_match_t& b) {
  expect_eq(a.detection, b.detection);
  EXPECT_EQ(a.map_id, b.map_id);
  EXPECT_EQ(a.map_x, b.map_x);
  EXPECT_EQ(a.map_y, b.map_y);
  EXPECT_EQ(a.map_radius, b.map_radius);
}

reflector_matches_t sample_matches() {
  reflector_matches_t m;
  m.utime = 1700000000000003;
  m.scan_counter = 78;
  m.status = reflector_matches_t::STATUS_AMBIGUOUS;
  m.mode = reflector_matches_t::MODE_GLOBAL;
  m.hypothesis_score = 6.5;
  m.runner_up_score = 6.25;
  m.hypothesis_x = 1.5;
  m.hypothesis_y = -2.5;
  m.hypothesis_theta = 3.0;
  m.ndetections = 7;
  for (int k = 0; k < 5; ++k) m.matches.push_back(sample_match(k));
  m.nmatches = static_cast<int32_t>(m.matches.size());
  return m;
}

void expect_eq(const reflector_matches_t& a, const reflector_matches_t& b) {
  EXPECT_EQ(a.utime, b.utime);
  EXPECT_EQ(a.scan_counter, b.scan_counter);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.mode, b.mode);
  EXPECT_EQ(a.hypothesis_score, b.hypothesis_score);
  EXPECT_EQ(a.runner_up_score, b.runner_up_score);
  EXPECT_EQ(a.hypothesis_x, b.hypothesis_x);
  EXPECT_EQ(a.hypothesis_y, b.hypothesis_y);
  EXPECT_EQ(a.hypothesis_theta, b.hypothesis_theta);
  EXPECT_EQ(a.ndetections, b.ndetections);
  ASSERT_EQ(a.nmatches, b.nmatches);
  for (int k = 0; k < a.nmatches; ++k) expect_eq(a.matches[k], b.matches[k]);
}

pose2d_t sample_pose() {
  pose2d_t m;
  m.utime = 1700000000000004;
  m.x = 10.125;
  m.y = -4.0625;
  m.theta = -3.1;
  for (int i = 0; i < 9; ++i) m.covariance[i] = 1e-6 * (i + 1);
  m.status = pose2d_t::STATUS_DEGRADED;
  m.reflectors_used = 5;
  m.residual = 0.0042;
  return m;
}

void expect_eq(const pose2d_t& a, const pose2d_t& b) {
  EXPECT_EQ(a.utime, b.utime);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.theta, b.theta);
  for (int i = 0; i < 9; ++i) EXPECT_EQ(a.covariance[i], b.covariance[i]);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.reflectors_used, b.reflectors_used);
  EXPECT_EQ(a.residual, b.residual);
}

wheel_encoders_t sample_encoders() {
  wheel_encoders_t m;
  m.utime = 1700000000000005;
  m.ticks[0] = 2147483647;
  m.ticks[1] = -2147483647 - 1;
  m.ticks[2] = 12345;
  m.ticks[3] = -42;
  return m;
}

void expect_eq(const wheel_encoders_t& a, const wheel_encoders_t& b) {
  EXPECT_EQ(a.utime, b.utime);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(a.ticks[i], b.ticks[i]);
}

odometry_t sample_odometry() {
  odometry_t m;
  m.utime = 1700000000000006;
  m.x = 1.0;
  m.y = 2.0;
  m.theta = 0.3;
  m.vx = 0.9;
  m.vy = -0.1;
  m.wz = 0.25;
  for (int i = 0; i < 9; ++i) m.covariance[i] = 2e-6 * (i + 1);
  m.distance = 123.456;
  m.slip_indicator = 0.003;
  return m;
}

void expect_eq(const odometry_t& a, const odometry_t& b) {
  EXPECT_EQ(a.utime, b.utime);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.theta, b.theta);
  EXPECT_EQ(a.vx, b.vx);
  EXPECT_EQ(a.vy, b.vy);
  EXPECT_EQ(a.wz, b.wz);
  for (int i = 0; i < 9; ++i) EXPECT_EQ(a.covariance[i], b.covariance[i]);
  EXPECT_EQ(a.distance, b.distance);
  EXPECT_EQ(a.slip_indicator, b.slip_indicator);
}

twist_t sample_twist() {
  twist_t m;
  m.utime = 1700000000000007;
  m.vx = 1.0;
  m.vy = -0.5;
  m.wz = 0.125;
  return m;
}

void expect_eq(const twist_t& a, const twist_t& b) {
  EXPECT_EQ(a.utime, b.utime);
  EXPECT_EQ(a.vx, b.vx);
  EXPECT_EQ(a.vy, b.vy);
  EXPECT_EQ(a.wz, b.wz);
}

nav_goal_t sample_goal() {
  nav_goal_t m;
  m.utime = 1700000000000008;
  m.goal_id = 99;
  m.xy_tolerance = 0.01;
  m.heading_tolerance = 0.0087;
  m.max_speed = 1.0;
  for (int k = 0; k < 6; ++k) {
    m.x.push_back(k * 1.5);
    m.y.push_back(-k * 0.5);
    m.theta.push_back(k * 0.25);
  }
  m.nwaypoints = static_cast<int32_t>(m.x.size());
  return m;
}

void expect_eq(const nav_goal_t& a, const nav_goal_t& b) {
  EXPECT_EQ(a.utime, b.utime);
  EXPECT_EQ(a.goal_id, b.goal_id);
  EXPECT_EQ(a.xy_tolerance, b.xy_tolerance);
  EXPECT_EQ(a.heading_tolerance, b.heading_tolerance);
  EXPECT_EQ(a.max_speed, b.max_speed);
  EXPECT_EQ(a.nwaypoints, b.nwaypoints);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.theta, b.theta);
}

nav_status_t sample_status() {
  nav_status_t m;
  m.utime = 1700000000000009;
  m.goal_id = 99;
  m.state = nav_status_t::STATE_ABORTED;
  m.waypoint_index = 3;
  m.waypoints_reached = 2;
  m.nwaypoints = 6;
  m.distance_to_waypoint = 1.75;
  m.heading_error = -0.01;
  m.reason = "pose lost for 5.0 s";
  return m;
}

void expect_eq(const nav_status_t& a, const nav_status_t& b) {
  EXPECT_EQ(a.utime, b.utime);
  EXPECT_EQ(a.goal_id, b.goal_id);
  EXPECT_EQ(a.state, b.state);
  EXPECT_EQ(a.waypoint_index, b.waypoint_index);
  EXPECT_EQ(a.waypoints_reached, b.waypoints_reached);
  EXPECT_EQ(a.nwaypoints, b.nwaypoints);
  EXPECT_EQ(a.distance_to_waypoint, b.distance_to_waypoint);
  EXPECT_EQ(a.heading_error, b.heading_error);
  EXPECT_EQ(a.reason, b.reason);
}

heartbeat_t sample_heartbeat() {
  heartbeat_t m;
  m.utime = 1700000000000010;
  m.service = "reflector_matcher";
  m.pid = 4242;
  m.state = heartbeat_t::STATE_DEGRADED;
  m.state_detail = "no POSE prior: relocalizing";
  m.uptime_us = 123456789;
  m.messages_in = 1000;
  m.messages_out = 999;
  m.decode_errors = 1;
  m.processing_p50_us = 12.5f;
  m.processing_p99_us = 48.0f;
  m.counter_names = {"relocalizations", "ambiguous"};
  m.counter_values = {3, 1};
  m.ncounters = 2;
  return m;
}

void expect_eq(const heartbeat_t& a, const heartbeat_t& b) {
  EXPECT_EQ(a.utime, b.utime);
  EXPECT_EQ(a.service, b.service);
  EXPECT_EQ(a.pid, b.pid);
  EXPECT_EQ(a.state, b.state);
  EXPECT_EQ(a.state_detail, b.state_detail);
  EXPECT_EQ(a.uptime_us, b.uptime_us);
  EXPECT_EQ(a.messages_in, b.messages_in);
  EXPECT_EQ(a.messages_out, b.messages_out);
  EXPECT_EQ(a.decode_errors, b.decode_errors);
  EXPECT_EQ(a.processing_p50_us, b.processing_p50_us);
  EXPECT_EQ(a.processing_p99_us, b.processing_p99_us);
  EXPECT_EQ(a.ncounters, b.ncounters);
  EXPECT_EQ(a.counter_names, b.counter_names);
  EXPECT_EQ(a.counter_values, b.counter_values);
}

/// Collects raw messages by channel.
struct Inbox {
  std::map<std::string, std::vector<uint8_t>> latest;
  void on_message(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
    const auto* bytes = static_cast<const uint8_t*>(rbuf->data);
    latest[channel].assign(bytes, bytes + rbuf->data_size);
  }
};

template <class Message>
struct Sample {
  std::string type;
  Message message;
};

template <class Message>
std::vector<uint8_t> encode(const Message& m) {
  std::vector<uint8_t> bytes(static_cast<size_t>(m.getEncodedSize()));
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

template <class Message>
void check_echo(Inbox& inbox, const std::string& type, const Message& sent) {
  SCOPED_TRACE(type);
  const auto it = inbox.latest.find("RT_" + type + "_ECHO");
  ASSERT_NE(it, inbox.latest.end()) << "no echo for " << type;
  Message received;
  ASSERT_GE(received.decode(it->second.data(), 0, static_cast<int>(it->second.size())), 0);
  expect_eq(sent, received);
}

class LcmRoundTrip : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(lcm_.good()) << "no multicast route: run this test through tests/tools/run_in_netns.sh";
    lcm_.subscribe(".*_ECHO", &Inbox::on_message, &inbox_);
    lcm_.subscribe("HEARTBEAT", &LcmRoundTrip::on_heartbeat, this);
    ASSERT_TRUE(peer_.start(
        {std::string(REFLOC_BINARY_DIR) + "/bin/lcm_echo_peer", std::string("--lcm-url=") + kUrl}));
  }

  void on_heartbeat(const lcm::ReceiveBuffer*, const std::string&, const heartbeat_t* hb) {
    if (hb->service == "lcm_echo_peer") last_peer_heartbeat_ = *hb;
  }

  template <class Message>
  void publish(const std::string& type, const Message& m) {
    const auto bytes = encode(m);
    lcm_.publish("RT_" + type, bytes.data(), static_cast<unsigned>(bytes.size()));
  }

  lcm::LCM lcm_{kUrl};
  Inbox inbox_;
  heartbeat_t last_peer_heartbeat_;
  testing::ChildProcess peer_;
};

TEST_F(LcmRoundTrip, EveryTypeCrossesBetweenTwoProcessesFieldByField) {
  const auto scan = sample_scan();
  const auto reflector = sample_reflector(3);
  const auto detections = sample_detections();
  const auto match = sample_match(2);
  const auto matches = sample_matches();
  const auto pose = sample_pose();
  const auto encoders = sample_encoders();
  const auto odometry = sample_odometry();
  const auto twist = sample_twist();
  const auto goal = sample_goal();
  const auto status = sample_status();
  const auto heartbeat = sample_heartbeat();
  constexpr size_t kTypes = 12;

  // The peer subscribes some time after it starts: publish until every echo is back.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
  while (inbox_.latest.size() < kTypes && std::chrono::steady_clock::now() < deadline) {
    publish("LASER_SCAN_T", scan);
    publish("REFLECTOR_T", reflector);
    publish("REFLECTOR_DETECTIONS_T", detections);
    publish("REFLECTOR_MATCH_T", match);
    publish("REFLECTOR_MATCHES_T", matches);
    publish("POSE2D_T", pose);
    publish("WHEEL_ENCODERS_T", encoders);
    publish("ODOMETRY_T", odometry);
    publish("TWIST_T", twist);
    publish("NAV_GOAL_T", goal);
    publish("NAV_STATUS_T", status);
    publish("HEARTBEAT_T", heartbeat);
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
    while (std::chrono::steady_clock::now() < until) lcm_.handleTimeout(20);
  }
  ASSERT_EQ(inbox_.latest.size(), kTypes);
  check_echo(inbox_, "LASER_SCAN_T", scan);
  check_echo(inbox_, "REFLECTOR_T", reflector);
  check_echo(inbox_, "REFLECTOR_DETECTIONS_T", detections);
  check_echo(inbox_, "REFLECTOR_MATCH_T", match);
  check_echo(inbox_, "REFLECTOR_MATCHES_T", matches);
  check_echo(inbox_, "POSE2D_T", pose);
  check_echo(inbox_, "WHEEL_ENCODERS_T", encoders);
  check_echo(inbox_, "ODOMETRY_T", odometry);
  check_echo(inbox_, "TWIST_T", twist);
  check_echo(inbox_, "NAV_GOAL_T", goal);
  check_echo(inbox_, "NAV_STATUS_T", status);
  check_echo(inbox_, "HEARTBEAT_T", heartbeat);
}

TEST_F(LcmRoundTrip, UndecodableMessageIsCountedInHeartbeatAndSkipped) {
  const std::vector<uint8_t> garbage = {0xde, 0xad, 0xbe, 0xef, 1, 2, 3};
  const auto pose = sample_pose();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
  // Wait for the peer to be subscribed (its echo of a good pose comes back) ...
  while (!inbox_.latest.count("RT_POSE2D_T_ECHO") && std::chrono::steady_clock::now() < deadline) {
    publish("POSE2D_T", pose);
    lcm_.handleTimeout(100);
  }
  ASSERT_TRUE(inbox_.latest.count("RT_POSE2D_T_ECHO"));
  inbox_.latest.clear();
  // ... then send bytes that are not a pose2d_t, followed by a good pose.
  lcm_.publish("RT_POSE2D_T", garbage.data(), static_cast<unsigned>(garbage.size()));
  publish("POSE2D_T", pose);
  while ((last_peer_heartbeat_.decode_errors < 1 || !inbox_.latest.count("RT_POSE2D_T_ECHO")) &&
         std::chrono::steady_clock::now() < deadline) {
    lcm_.handleTimeout(50);
  }
  EXPECT_EQ(last_peer_heartbeat_.decode_errors, 1);
  EXPECT_EQ(last_peer_heartbeat_.service, "lcm_echo_peer");
  EXPECT_EQ(last_peer_heartbeat_.pid, peer_.pid());
  check_echo(inbox_, "POSE2D_T", pose);  // the good message after the bad one still arrives
  EXPECT_TRUE(peer_.running()) << "a bad message must not kill the service";
  EXPECT_EQ(peer_.stop(), 0) << "SIGTERM must end the service cleanly with exit code 0";
}

}  // namespace
}  // namespace refloc
