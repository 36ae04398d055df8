// Drives the motion services over real LCM: stands in for the laser pipeline by
// republishing GROUND_TRUTH as LASER_POSE 40 ms late (as a pose solver would
// deliver it), sends NAV_GOALs and checks where the simulated robot ends up.
// Run by motion_loop_test.sh, which starts robot_sim, mecanum_odometry,
// pose_fusion and navigator. Exit 0 when every check passes.

#include "common/clock.hpp"
#include "common/se2.hpp"

#include <lcm/lcm-cpp.hpp>
#include <refloc/nav_goal_t.hpp>
#include <refloc/nav_status_t.hpp>
#include <refloc/pose2d_t.hpp>

#include <cmath>
#include <cstdio>
#include <deque>
#include <functional>
#include <string>

namespace refloc {
namespace {

class Harness {
 public:
  explicit Harness(lcm::LCM& lcm) : lcm_(lcm) {
    lcm_.subscribe("GROUND_TRUTH", &Harness::on_truth, this);
    lcm_.subscribe("POSE", &Harness::on_pose, this);
    lcm_.subscribe("NAV_STATUS", &Harness::on_status, this);
  }

  bool fixes_enabled = true;
  pose2d_t fused{};
  nav_status_t status{};

  const pose2d_t* newest_truth() const { return truth_.empty() ? nullptr : &truth_.back(); }

  /// Handle LCM and publish fixes until done() or timeout_s; false on timeout.
  bool spin_until(double timeout_s, const std::function<bool()>& done) {
    const int64_t end = monotonic_us() + static_cast<int64_t>(timeout_s * 1e6);
    while (monotonic_us() < end) {
      lcm_.handleTimeout(5);
      publish_fix_if_due();
      if (done()) return true;
    }
    return false;
  }

  void send_goal(int64_t goal_id, const std::vector<Pose2>& waypoints) {
    nav_goal_t goal{};
    goal.utime = now_utime();
    goal.goal_id = goal_id;
    goal.max_speed = 1.0;
    goal.nwaypoints = static_cast<int32_t>(waypoints.size());
    for (const Pose2& w : waypoints) {
      goal.x.push_back(w.x);
      goal.y.push_back(w.y);
      goal.theta.push_back(w.theta);
    }
    lcm_.publish("NAV_GOAL", &goal);
  }

 private:
  void on_truth(const lcm::ReceiveBuffer*, const std::string&, const pose2d_t* msg) {
    truth_.push_back(*msg);
    if (truth_.size() > 200) truth_.pop_front();
  }
  void on_pose(const lcm::ReceiveBuffer*, const std::string&, const pose2d_t* msg) { fused = *msg; }
  void on_status(const lcm::ReceiveBuffer*, const std::string&, const nav_status_t* msg) { status = *msg; }

  void publish_fix_if_due() {
    const int64_t now = monotonic_us();
    if (!fixes_enabled || now < next_fix_us_ || truth_.empty()) return;
    next_fix_us_ = now + 40'000;  // 25 Hz scans
    const int64_t wanted = truth_.back().utime - 40'000;
    for (auto it = truth_.rbegin(); it != truth_.rend(); ++it) {
      if (it->utime <= wanted) {
        pose2d_t fix = *it;
        for (double& c : fix.covariance) c = 0.0;
        fix.covariance[0] = fix.covariance[4] = 1e-6;  // 1 mm
        fix.covariance[8] = 1e-6;                      // 1 mrad
        fix.status = pose2d_t::STATUS_OK;
        fix.reflectors_used = 5;
        lcm_.publish("LASER_POSE", &fix);
        return;
      }
    }
  }

  lcm::LCM& lcm_;
  std::deque<pose2d_t> truth_;
  int64_t next_fix_us_ = 0;
};

int fail(const std::string& what) {
  std::fprintf(stderr, "motion_loop_harness: FAIL: %s\n", what.c_str());
  return 1;
}

int run() {
  lcm::LCM lcm("udpm://239.255.76.67:7667?ttl=0");
  if (!lcm.good()) return fail("no LCM");
  Harness h(lcm);
  if (!h.spin_until(15.0, [&] { return h.fused.status == pose2d_t::STATUS_OK && h.fused.utime > 0; })) {
    return fail("POSE never became OK");
  }
  std::printf("fused pose OK\n");

  const std::vector<Pose2> mission{{1.0, 0.0, 0.0}, {1.0, 1.0, M_PI / 2}, {0.2, 0.4, M_PI}};
  int64_t next_send = 0;
  const bool arrived = h.spin_until(60.0, [&] {
    if (h.status.goal_id != 42 && monotonic_us() >= next_send) {  // until the navigator has it
      h.send_goal(42, mission);
      next_send = monotonic_us() + 1'000'000;
    }
    if (h.status.goal_id == 42 && h.status.state == nav_status_t::STATE_ABORTED) return true;
    return h.status.goal_id == 42 && h.status.state == nav_status_t::STATE_ARRIVED;
  });
  if (!arrived || h.status.state != nav_status_t::STATE_ARRIVED) {
    return fail("goal 42 not reached: state " + std::to_string(h.status.state) + " " + h.status.reason);
  }
  h.spin_until(0.3, [] { return false; });
  const pose2d_t* truth = h.newest_truth();
  const double xy_error = std::hypot(truth->x - mission.back().x, truth->y - mission.back().y);
  const double heading_error = std::abs(angle_diff(truth->theta, mission.back().theta));
  std::printf("arrived: true pose error %.1f mm, %.3f deg\n", xy_error * 1e3, heading_error * 180 / M_PI);
  // The fused pose tracks the truth through 40 ms-late fixes; allow 5 mm for that on top.
  if (xy_error > 0.015 || heading_error > 0.5 * M_PI / 180.0) return fail("arrival error too large");

  // Safety: without fixes the fused pose turns DEGRADED after 1 s and the navigator stops.
  h.send_goal(43, {{2.5, 0.4, M_PI}});
  if (!h.spin_until(
          5.0, [&] { return h.status.goal_id == 43 && h.status.state == nav_status_t::STATE_DRIVING; })) {
    return fail("goal 43 not driving");
  }
  h.spin_until(0.5, [] { return false; });
  h.fixes_enabled = false;
  const int64_t fixes_off = monotonic_us();
  if (!h.spin_until(3.0, [&] { return h.status.state == nav_status_t::STATE_STOPPED_NO_POSE; })) {
    return fail("navigator did not stop without fixes");
  }
  std::printf("stopped %.2f s after the last fix: %s\n", (monotonic_us() - fixes_off) * 1e-6,
              h.status.reason.c_str());
  h.spin_until(1.0, [] { return false; });  // let the wheels ramp down
  const double x_stopped = h.newest_truth()->x;
  h.spin_until(0.5, [] { return false; });
  if (std::abs(h.newest_truth()->x - x_stopped) > 1e-3) return fail("robot still moving after the stop");
  h.fixes_enabled = true;
  if (!h.spin_until(
          30.0, [&] { return h.status.goal_id == 43 && h.status.state == nav_status_t::STATE_ARRIVED; })) {
    return fail("goal 43 not reached after fixes resumed");
  }
  std::printf("resumed and arrived at goal 43\n");
  return 0;
}

}  // namespace
}  // namespace refloc

int main() { return refloc::run(); }
