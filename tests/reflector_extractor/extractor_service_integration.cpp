// reflector_extractor as a real process over UDP multicast (run in a private network
// namespace): LMS100_SCAN, ODOMETRY and LASER_POSE in, REFLECTORS and REFLECTOR_CLUSTERS out. Checks the
// message fields, that the published centres are the library's, motion-compensated with the odometry twist
// and the laser mount, or without odometry with the twist of the LASER_POSE fixes, and that a bad config file
// exits with code 2.

#include "common/lcm_conversions.hpp"
#include "common/robot_config.hpp"
#include "reflector_extractor/extractor.hpp"
#include "reflector_extractor/motion_compensation.hpp"
#include "reflector_extractor/synthetic_scan.hpp"
#include "tests/tools/child_process.hpp"
#include "tests/tools/run_command.hpp"

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <refloc/laser_scan_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_clusters_t.hpp>
#include <refloc/reflector_detections_t.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <optional>

namespace refloc {
namespace {

const char* kUrl = "udpm://239.255.76.67:7667?ttl=0";
const std::string kSource = REFLOC_SOURCE_DIR;
const std::string kBin = std::string(REFLOC_BINARY_DIR) + "/bin/";

class ExtractorService : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(lcm_.good());
    lcm_.subscribe("REFLECTORS", &ExtractorService::on_reflectors, this);
    lcm_.subscribe("REFLECTOR_CLUSTERS", &ExtractorService::on_clusters, this);
    ASSERT_TRUE(service_.start({kBin + "reflector_extractor", std::string("--lcm-url=") + kUrl, "--config",
                                kSource + "/deploy/config/reflector_extractor.json", "--robot",
                                kSource + "/deploy/config/robot.json"}));
  }

  void on_reflectors(const lcm::ReceiveBuffer*, const std::string&, const reflector_detections_t* msg) {
    received_.push_back(*msg);
  }
  void on_clusters(const lcm::ReceiveBuffer*, const std::string&, const reflector_clusters_t* msg) {
    clusters_.push_back(*msg);
  }
  /// REFLECTOR_CLUSTERS of the scan at utime (published right after its REFLECTORS).
  std::optional<reflector_clusters_t> clusters_of(int64_t utime) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (std::chrono::steady_clock::now() < deadline) {
      for (const reflector_clusters_t& c : clusters_)
        if (c.utime == utime) return c;
      lcm_.handleTimeout(20);
    }
    return std::nullopt;
  }

  /// Publish msg on channel every 200 ms (the service may still be starting) until the
  /// REFLECTORS for utime is back.
  template <class Message>
  std::optional<reflector_detections_t> exchange(const std::string& channel, const Message& msg,
                                                 int64_t utime) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
    auto next_publish = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() < deadline) {
      if (std::chrono::steady_clock::now() >= next_publish) {
        lcm_.publish(channel, &msg);
        next_publish += std::chrono::milliseconds(200);
      }
      lcm_.handleTimeout(20);
      for (const reflector_detections_t& r : received_) {
        if (r.utime == utime) return r;
      }
    }
    return std::nullopt;
  }

  /// The scan's REFLECTORS, with odometry received by the service before the scan.
  std::optional<reflector_detections_t> exchange(const laser_scan_t& scan, const odometry_t& odometry) {
    // Until a first scan comes back the service may not be subscribed yet.
    laser_scan_t warmup = scan;
    warmup.utime -= 20'000;  // one scan period: the service judges stamps by the stream's clock
    if (!exchange("LMS100_SCAN", warmup, warmup.utime)) return std::nullopt;
    lcm_.publish("ODOMETRY", &odometry);
    return exchange("LMS100_SCAN", scan, scan.utime);
  }

  lcm::LCM lcm_{kUrl};
  testing::ChildProcess service_;
  std::vector<reflector_detections_t> received_;
  std::vector<reflector_clusters_t> clusters_;
};

TEST_F(ExtractorService, PublishesMotionCompensatedDetectionsOfEachScan) {
  SyntheticScene scene;
  for (double bearing_deg : {-100.0, 0.0, 100.0}) {
    SyntheticCylinder c;
    c.laser_p_center =
        2.0 * Eigen::Vector2d(std::cos(bearing_deg * M_PI / 180.0), std::sin(bearing_deg * M_PI / 180.0));
    scene.cylinders.push_back(c);
  }
  std::mt19937 rng(4);
  SyntheticScanConfig scan_config;
  scan_config.utime = 5'000'000'000;
  const LaserScan scan = render_synthetic_scan(scene, scan_config, rng);

  odometry_t odometry{};
  odometry.utime = scan.utime;
  odometry.vx = 1.0;
  odometry.wz = 0.5;

  const laser_scan_t message = to_lcm(scan);
  const auto out = exchange(message, odometry);
  ASSERT_TRUE(out.has_value());
  ASSERT_EQ(out->nreflectors, 3);
  ASSERT_EQ(out->reflectors.size(), 3u);
  EXPECT_EQ(out->clusters_considered, 3);
  EXPECT_EQ(out->clusters_rejected, 0);

  // The same computation in-process on what went over the wire (angles are float there):
  // the service must publish exactly this.
  LaserScan received;
  ASSERT_TRUE(from_lcm(message, received));
  ReflectorExtractor extractor;
  std::vector<ReflectorDetection> expected = extractor.extract(received);
  const Pose2 robot_T_laser = load_robot_config(kSource + "/deploy/config/robot.json").robot_T_laser;
  compensate_motion(expected, scan.utime, BodyTwist{1.0, 0.0, 0.5}, robot_T_laser);
  ASSERT_EQ(expected.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    const reflector_t& r = out->reflectors[i];
    EXPECT_NEAR(r.x, expected[i].laser_p_center.x(), 1e-9);
    EXPECT_NEAR(r.y, expected[i].laser_p_center.y(), 1e-9);
    EXPECT_NEAR(r.covariance[1], expected[i].covariance(0, 1), 1e-15);
    EXPECT_EQ(r.utime, expected[i].utime);
    EXPECT_EQ(r.nbeams, expected[i].num_beams);
    EXPECT_GT(r.utime, scan.utime);
  }
  // The reflector straight ahead is seen 7.5 ms after the first beam, at 1 m/s and
  // 0.5 rad/s: it moved 7.5 mm closer and 7.5 mm to the left (about 1 cm).
  ReflectorExtractor raw_extractor;
  const std::vector<ReflectorDetection>& raw = raw_extractor.extract(received);
  EXPECT_NEAR((expected[1].laser_p_center - raw[1].laser_p_center).norm(), 0.0106, 0.001);

  // Every bright cluster of the scan, with its outcome, and the threshold on the scan's scale.
  const auto clusters = clusters_of(scan.utime);
  ASSERT_TRUE(clusters.has_value());
  EXPECT_EQ(clusters->scan_counter, out->scan_counter);
  EXPECT_EQ(clusters->energy_threshold_8bit, 180.0f);
  EXPECT_EQ(clusters->energy_threshold_raw, 180.0f * 257.0f);  // 16-bit RSSI
  EXPECT_FALSE(clusters->rssi_read_as_8bit);
  ASSERT_EQ(clusters->nclusters, 3);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(clusters->clusters[i].outcome, reflector_cluster_t::ACCEPTED);
    EXPECT_EQ(clusters->clusters[i].first_beam, out->reflectors[i].first_beam);
    EXPECT_NEAR(clusters->clusters[i].range, 2.0 - 0.06, 0.03);
  }
  EXPECT_EQ(service_.stop(), 0);
}

TEST_F(ExtractorService, WithoutOdometryCompensatesWithTheTwistOfTheLaserPoseFixes) {
  SyntheticScene scene;
  for (double bearing_deg : {-100.0, 0.0, 100.0}) {
    SyntheticCylinder c;
    c.laser_p_center =
        2.0 * Eigen::Vector2d(std::cos(bearing_deg * M_PI / 180.0), std::sin(bearing_deg * M_PI / 180.0));
    scene.cylinders.push_back(c);
  }
  std::mt19937 rng(5);
  SyntheticScanConfig scan_config;
  scan_config.utime = 5'000'000'000;
  const LaserScan scan = render_synthetic_scan(scene, scan_config, rng);
  const laser_scan_t message = to_lcm(scan);
  laser_scan_t warmup = message;
  warmup.utime -= 20'000;
  ASSERT_TRUE(exchange("LMS100_SCAN", warmup, warmup.utime));
  // 10 OK fixes of a robot driving straight ahead at 1 m/s, 50 Hz, the newest 20 ms before the scan.
  for (int k = 0; k < 10; ++k) {
    pose2d_t fix{};
    fix.utime = scan.utime - 20'000 * (10 - k);
    fix.x = 3.0 + 1.0 * 0.02 * k;
    fix.y = 2.0;
    fix.covariance[0] = fix.covariance[4] = 1e-5;
    fix.covariance[8] = 1e-6;
    fix.status = pose2d_t::STATUS_OK;
    lcm_.publish("LASER_POSE", &fix);
  }
  const auto out = exchange("LMS100_SCAN", message, message.utime);
  ASSERT_TRUE(out.has_value());
  ASSERT_EQ(out->reflectors.size(), 3u);

  LaserScan received;
  ASSERT_TRUE(from_lcm(message, received));
  ReflectorExtractor extractor;
  std::vector<ReflectorDetection> expected = extractor.extract(received);
  const std::vector<ReflectorDetection> raw = expected;
  const Pose2 robot_T_laser = load_robot_config(kSource + "/deploy/config/robot.json").robot_T_laser;
  compensate_motion(expected, scan.utime, BodyTwist{1.0, 0.0, 0.0}, robot_T_laser);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(out->reflectors[i].x, expected[i].laser_p_center.x(), 1e-9);
    EXPECT_NEAR(out->reflectors[i].y, expected[i].laser_p_center.y(), 1e-9);
  }
  // Straight ahead, seen ~7.5 ms after the first beam at 1 m/s: at the first beam the laser
  // was 7.5 mm further back, so the reflector 7.5 mm further ahead.
  EXPECT_NEAR(expected[1].laser_p_center.x() - raw[1].laser_p_center.x(), 0.0075, 0.001);
  EXPECT_EQ(service_.stop(), 0);
}

TEST(ExtractorServiceConfig, MisspeltKeyExitsWithCode2NamingTheKey) {
  const std::string path = std::string(REFLOC_BINARY_DIR) + "/reflector_extractor_bad_config.json";
  std::ofstream(path) << R"({"mode": "default", "reflector_radius": 0.06})";
  const auto result =
      testing::run_command(kBin + "reflector_extractor --lcm-url=" + kUrl + " --config " + path);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("/reflector_radius: unknown key"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace refloc
