// Test peer: decodes every refloc message type on RT_<TYPE> with the service
// runtime and republishes what it decoded on RT_<TYPE>_ECHO. Used by
// lcm_roundtrip_test to exchange every type between two real processes.

#include "common/guarded_main.hpp"
#include "common/service_runtime.hpp"

#include <CLI/CLI.hpp>
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

namespace {

template <class Message>
void echo(refloc::ServiceRuntime& runtime, const std::string& type) {
  const std::string out = "RT_" + type + "_ECHO";
  runtime.subscribe<Message>("RT_" + type, [&runtime, out](const Message& m) { runtime.publish(out, m); });
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Echo every refloc LCM type (test peer)"};
  std::string lcm_url;
  app.add_option("--lcm-url", lcm_url, "LCM URL (default: $LCM_DEFAULT_URL or udpm ttl=0)");
  CLI11_PARSE(app, argc, argv);
  return refloc::guarded_main("lcm_echo_peer", [&] {
    refloc::setup_logging("lcm_echo_peer");
    refloc::ServiceRuntime runtime("lcm_echo_peer", lcm_url);
    echo<refloc::laser_scan_t>(runtime, "LASER_SCAN_T");
    echo<refloc::reflector_t>(runtime, "REFLECTOR_T");
    echo<refloc::reflector_detections_t>(runtime, "REFLECTOR_DETECTIONS_T");
    echo<refloc::reflector_match_t>(runtime, "REFLECTOR_MATCH_T");
    echo<refloc::reflector_matches_t>(runtime, "REFLECTOR_MATCHES_T");
    echo<refloc::pose2d_t>(runtime, "POSE2D_T");
    echo<refloc::wheel_encoders_t>(runtime, "WHEEL_ENCODERS_T");
    echo<refloc::odometry_t>(runtime, "ODOMETRY_T");
    echo<refloc::twist_t>(runtime, "TWIST_T");
    echo<refloc::nav_goal_t>(runtime, "NAV_GOAL_T");
    echo<refloc::nav_status_t>(runtime, "NAV_STATUS_T");
    echo<refloc::heartbeat_t>(runtime, "HEARTBEAT_T");
    // Heartbeats every 200 ms so the test sees the decode-error count quickly.
    runtime.add_periodic(0.2, [&runtime] { runtime.publish_heartbeat(); });
    return runtime.run();
  });
}
