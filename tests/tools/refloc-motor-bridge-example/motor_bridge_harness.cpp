// Sends CMD_VEL to refloc-motor-bridge-example over real LCM and judges what comes back:
// WHEEL_ENCODERS from the bridge (their tick rates through the Mecanum forward kinematics
// give the commanded twist; counts wrap), ODOMETRY from mecanum_odometry fed by them, and
// the stop once CMD_VEL ends (the bridge's command timeout). Run by motor_bridge_test.sh.
// Exit 0 when every check passes.

#include "common/clock.hpp"
#include "common/mecanum_kinematics.hpp"
#include "common/robot_config.hpp"

#include <lcm/lcm-cpp.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/twist_t.hpp>
#include <refloc/wheel_encoders_t.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace refloc {
namespace {

struct Sample {
  int64_t receive_mono_us;
  wheel_encoders_t msg;
};

class Harness {
 public:
  explicit Harness(lcm::LCM& lcm) : lcm_(lcm) {
    lcm_.subscribe("WHEEL_ENCODERS", &Harness::on_encoders, this);
    lcm_.subscribe("ODOMETRY", &Harness::on_odometry, this);
    lcm_.subscribe("HEARTBEAT", &Harness::on_heartbeat, this);
  }

  std::vector<Sample> encoders;
  odometry_t odometry{};
  std::map<std::string, heartbeat_t> heartbeats;
  twist_t command{};
  bool commanding = false;

  bool spin_until(double timeout_s, const std::function<bool()>& done) {
    const int64_t end = monotonic_us() + static_cast<int64_t>(timeout_s * 1e6);
    while (monotonic_us() < end) {
      lcm_.handleTimeout(2);
      if (commanding && monotonic_us() >= next_command_us_) {
        next_command_us_ = monotonic_us() + 20'000;  // the navigator's 50 Hz
        command.utime = now_utime();
        lcm_.publish("CMD_VEL", &command);
      }
      if (done()) return true;
    }
    return false;
  }

 private:
  void on_encoders(const lcm::ReceiveBuffer*, const std::string&, const wheel_encoders_t* msg) {
    encoders.push_back({monotonic_us(), *msg});
  }
  void on_odometry(const lcm::ReceiveBuffer*, const std::string&, const odometry_t* msg) { odometry = *msg; }
  void on_heartbeat(const lcm::ReceiveBuffer*, const std::string&, const heartbeat_t* msg) {
    heartbeats[msg->service] = *msg;
  }

  lcm::LCM& lcm_;
  int64_t next_command_us_ = 0;
};

bool same_ticks(const wheel_encoders_t& a, const wheel_encoders_t& b) {
  return std::equal(std::begin(a.ticks), std::end(a.ticks), std::begin(b.ticks));
}

int32_t tick_diff(int32_t now, int32_t before) {
  return static_cast<int32_t>(static_cast<uint32_t>(now) - static_cast<uint32_t>(before));
}

/// Body twist from the counts of two samples, through the kinematics mecanum_odometry uses.
BodyTwist twist_between(const wheel_encoders_t& a, const wheel_encoders_t& b, const RobotConfig& robot) {
  const double dt = 1e-6 * static_cast<double>(b.utime - a.utime);
  WheelArray speed{};
  for (size_t i = 0; i < 4; ++i) {
    speed[i] = tick_diff(b.ticks[i], a.ticks[i]) * 2.0 * M_PI / robot.encoder_ticks_per_rev / dt;
  }
  return MecanumKinematics(robot).forward(speed);
}

int fail(const std::string& what) {
  std::fprintf(stderr, "motor_bridge_harness: FAIL: %s\n", what.c_str());
  return 1;
}

bool near(double value, double wanted, double tolerance) { return std::abs(value - wanted) <= tolerance; }

int run(const std::string& robot_path) {
  const RobotConfig robot = load_robot_config(robot_path);
  lcm::LCM lcm("udpm://239.255.76.67:7667?ttl=0");
  if (!lcm.good()) return fail("no LCM");
  Harness h(lcm);
  if (!h.spin_until(15.0, [&] { return h.heartbeats.count("motor_bridge") && h.odometry.utime > 0; })) {
    return fail("no HEARTBEAT from motor_bridge or no ODOMETRY from mecanum_odometry");
  }
  h.command = twist_t{0, 0.5, 0.2, 0.3};
  h.commanding = true;
  const size_t first_driving = h.encoders.size();
  h.spin_until(1.5, [] { return false; });
  const size_t last_driving = h.encoders.size() - 1;
  if (last_driving < first_driving + 30) return fail("fewer than 30 WHEEL_ENCODERS in 1.5 s");
  // From 0.3 s in: the first command's way through the bus is not what is judged here.
  const BodyTwist seen =
      twist_between(h.encoders[first_driving + 30].msg, h.encoders[last_driving].msg, robot);
  std::printf("WHEEL_ENCODERS while driving: %zu samples, twist from counts (%.4f, %.4f, %.4f)\n",
              last_driving - first_driving + 1, seen.vx, seen.vy, seen.wz);
  if (!near(seen.vx, 0.5, 0.01) || !near(seen.vy, 0.2, 0.01) || !near(seen.wz, 0.3, 0.01)) {
    return fail("the counts do not give the commanded twist (0.5, 0.2, 0.3)");
  }
  std::printf("ODOMETRY twist (%.4f, %.4f, %.4f)\n", h.odometry.vx, h.odometry.vy, h.odometry.wz);
  if (!near(h.odometry.vx, 0.5, 0.02) || !near(h.odometry.vy, 0.2, 0.02) || !near(h.odometry.wz, 0.3, 0.02)) {
    return fail("mecanum_odometry's twist is not the commanded one");
  }

  h.commanding = false;
  const int64_t last_command_mono = monotonic_us();
  h.spin_until(1.0, [] { return false; });
  const Sample& end = h.encoders.back();
  int64_t stopped_mono = -1;  // receipt of the first sample from which the counts never change
  for (size_t i = h.encoders.size() - 1; i > last_driving; --i) {
    if (!same_ticks(h.encoders[i - 1].msg, end.msg)) break;
    stopped_mono = h.encoders[i - 1].receive_mono_us;
  }
  if (stopped_mono < 0 || end.receive_mono_us - stopped_mono < 300'000) {
    return fail("the wheels did not stop after CMD_VEL ended");
  }
  std::printf("wheels stopped %.0f ms after the last CMD_VEL was sent\n",
              1e-3 * (stopped_mono - last_command_mono));
  if (stopped_mono - last_command_mono > 600'000)
    return fail("stopped later than 0.6 s after the last CMD_VEL");
  if (h.odometry.vx != 0.0 || h.odometry.vy != 0.0 || h.odometry.wz != 0.0)
    return fail("ODOMETRY still moving");

  if (!h.spin_until(2.5, [&] {
        const heartbeat_t& hb = h.heartbeats["motor_bridge"];
        for (int i = 0; i < hb.ncounters; ++i) {
          if (hb.counter_names[i] == "command_timeouts" && hb.counter_values[i] == 1) return true;
        }
        return false;
      })) {
    return fail("motor_bridge's HEARTBEAT does not count command_timeouts = 1");
  }
  std::printf("motor_bridge HEARTBEAT: command_timeouts 1, \"%s\"\n",
              h.heartbeats["motor_bridge"].state_detail.c_str());
  return 0;
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: motor_bridge_harness ROBOT_JSON\n");
    return 64;
  }
  return refloc::run(argv[1]);
}
