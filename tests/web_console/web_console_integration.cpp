// web_console as a real process over UDP multicast (run in a private network namespace), with a
// WebSocket client written with Boost.Beast: the map frame carries the map's reflectors, a POSE
// reaches the page; a foreign Origin, an oversized and a malformed message are refused and
// counted (HEARTBEAT) while the service keeps running; with control enabled a goal with the
// token becomes a NAV_GOAL at the sent coordinates, one without it is refused.

#include "common/reflector_map.hpp"
#include "tests/tools/child_process.hpp"

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <nlohmann/json.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/nav_goal_t.hpp>
#include <refloc/pose2d_t.hpp>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

#include <sys/socket.h>

#include <chrono>
#include <fstream>
#include <map>
#include <optional>

namespace refloc {
namespace {

namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;

const char* kUrl = "udpm://239.255.76.67:7667?ttl=0";
const std::string kSource = REFLOC_SOURCE_DIR;
const std::string kBin = std::string(REFLOC_BINARY_DIR) + "/bin/";
const std::string kToken = "integration-token";
constexpr int kPort = 18080;

/// A WebSocket client with a 1 s receive timeout (SO_RCVTIMEO: Beast's sync reads have none).
class Client {
 public:
  /// Connects and upgrades with the given Origin header; false when the server refuses.
  bool open(const std::string& origin) {
    try {
      tcp::resolver resolver(ioc_);
      net::connect(ws_.next_layer(), resolver.resolve("127.0.0.1", std::to_string(kPort)));
      const timeval timeout{1, 0};
      setsockopt(ws_.next_layer().native_handle(), SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
      ws_.set_option(websocket::stream_base::decorator(
          [origin](websocket::request_type& r) { r.set(beast::http::field::origin, origin); }));
      ws_.handshake("127.0.0.1:" + std::to_string(kPort), "/");
      return true;
    } catch (const std::exception&) {
      return false;
    }
  }
  /// The next frame, or nullopt after a timeout or when the server closed the connection.
  std::optional<nlohmann::json> read() {
    beast::flat_buffer buffer;
    beast::error_code ec;
    ws_.read(buffer, ec);
    if (ec) return std::nullopt;
    return nlohmann::json::parse(beast::buffers_to_string(buffer.data()));
  }
  /// Frames until one of this type (within deadline_s).
  std::optional<nlohmann::json> read_until(const std::string& type, double deadline_s = 5.0) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(deadline_s);
    while (std::chrono::steady_clock::now() < end) {
      const auto frame = read();
      if (frame && (*frame)["type"] == type) return frame;
    }
    return std::nullopt;
  }
  bool send(const std::string& text) {
    beast::error_code ec;
    ws_.text(true);
    ws_.write(net::buffer(text), ec);
    return !ec;
  }

 private:
  net::io_context ioc_;
  websocket::stream<tcp::socket> ws_{ioc_};
};

class WebConsoleIntegration : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(lcm_.good());
    lcm_.subscribe("HEARTBEAT", &WebConsoleIntegration::on_heartbeat, this);
    lcm_.subscribe("NAV_GOAL", &WebConsoleIntegration::on_goal, this);
    config_ = ::testing::TempDir() + "web_console_integration.json";
    std::ofstream(config_) << nlohmann::json{{"map_file", kSource + "/deploy/config/map_demo.json"},
                                             {"www_dir", kSource + "/services/web_console/www"},
                                             {"server", {{"port", kPort}, {"max_message_bytes", 1024}}},
                                             {"control", {{"enabled", true}, {"token", kToken}}}}
                                  .dump();
    ASSERT_TRUE(
        console_.start({kBin + "web_console", std::string("--lcm-url=") + kUrl, "--config", config_}));
    ASSERT_TRUE(wait_for([&] { return !counters_.empty(); }, 5.0)) << "no HEARTBEAT from web_console";
  }

  template <typename Done>
  bool wait_for(Done done, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!done() && std::chrono::steady_clock::now() < end) lcm_.handleTimeout(20);
    return done();
  }
  int64_t counter(const std::string& name) { return counters_.count(name) ? counters_[name] : 0; }

  void on_heartbeat(const lcm::ReceiveBuffer*, const std::string&, const heartbeat_t* msg) {
    if (msg->service != "web_console") return;
    for (size_t i = 0; i < msg->counter_names.size(); ++i)
      counters_[msg->counter_names[i]] = msg->counter_values[i];
    counters_["heartbeats"] += 1;
  }
  void on_goal(const lcm::ReceiveBuffer*, const std::string&, const nav_goal_t* msg) {
    goals_.push_back(*msg);
  }

  void publish_pose(double x, double y) {
    pose2d_t pose{};
    pose_utime_ += 1'000'000;  // a new stamp each: poses reach the page at most pose_rate_hz by stamp
    pose.utime = pose_utime_;
    pose.x = x;
    pose.y = y;
    pose.covariance[0] = pose.covariance[4] = 1e-6;
    pose.status = pose2d_t::STATUS_OK;
    lcm_.publish("POSE", &pose);
  }

  lcm::LCM lcm_{kUrl};
  std::string config_;
  testing::ChildProcess console_;
  std::map<std::string, int64_t> counters_;
  std::vector<nav_goal_t> goals_;
  int64_t pose_utime_ = 0;
};

TEST_F(WebConsoleIntegration, ShowsTheMapAndPoseRefusesWhatItMustAndPublishesGoalsWithTheToken) {
  publish_pose(2.5, 3.5);
  Client page;
  ASSERT_TRUE(page.open("http://127.0.0.1:" + std::to_string(kPort)));
  const auto map = page.read_until("map");
  ASSERT_TRUE(map);
  EXPECT_EQ((*map)["reflectors"].size(),
            load_reflector_map(kSource + "/deploy/config/map_demo.json").reflectors.size());
  publish_pose(2.5, 3.5);
  const auto pose = page.read_until("pose");
  ASSERT_TRUE(pose);
  EXPECT_DOUBLE_EQ((*pose)["x"].get<double>(), 2.5);

  Client foreign;
  EXPECT_FALSE(foreign.open("http://evil.example"));
  Client oversized;
  ASSERT_TRUE(oversized.open("http://127.0.0.1:" + std::to_string(kPort)));
  oversized.send(std::string(2000, 'x'));
  ASSERT_TRUE(page.send("{\"type\": \"goal\", \"x\": "));
  ASSERT_TRUE(page.send(R"({"type": "goal", "token": "wrong-token", "x": 1.0, "y": 1.0, "theta": 0.0})"));
  ASSERT_TRUE(
      page.send(R"({"type": "goal", "token": ")" + kToken + R"(", "x": 3.25, "y": -1.5, "theta": 0.25})"));

  ASSERT_TRUE(wait_for([&] { return !goals_.empty(); }, 3.0)) << "no NAV_GOAL";
  ASSERT_EQ(goals_.size(), 1u) << "only the goal with the token is published";
  ASSERT_EQ(goals_[0].nwaypoints, 1);
  EXPECT_DOUBLE_EQ(goals_[0].x[0], 3.25);
  EXPECT_DOUBLE_EQ(goals_[0].y[0], -1.5);
  EXPECT_DOUBLE_EQ(goals_[0].theta[0], 0.25);

  const auto all_counted = [&] {
    return counter("clients_refused_origin") == 1 && counter("requests_refused_too_large") == 1 &&
           counter("requests_refused_not_json") == 1 && counter("requests_refused_bad_token") == 1;
  };
  EXPECT_TRUE(wait_for(all_counted, 3.0))
      << "origin " << counter("clients_refused_origin") << ", too large "
      << counter("requests_refused_too_large") << ", not json " << counter("requests_refused_not_json")
      << ", bad token " << counter("requests_refused_bad_token");
  EXPECT_EQ(counter("requests_accepted"), 1);
  EXPECT_TRUE(console_.running()) << "web_console ended";
  publish_pose(4.0, 1.0);
  std::optional<nlohmann::json> after;
  for (int i = 0; i < 5 && !(after && (*after)["x"] == 4.0); ++i) after = page.read_until("pose");
  ASSERT_TRUE(after) << "the page is still served after the refusals";
  EXPECT_DOUBLE_EQ((*after)["x"].get<double>(), 4.0);
  EXPECT_EQ(console_.stop(), 0);
}

}  // namespace
}  // namespace refloc
