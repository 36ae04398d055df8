// The extractor node fed what a hostile or broken peer can publish on LMS100_SCAN and
// ODOMETRY: nothing non-finite comes out, every rejection is counted under its reason,
// and good input afterwards is processed as before.

#include "reflector_extractor/extractor_node.hpp"

#include "scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 1'700'000'000'000'000;  // a 2023 wall clock [us]
constexpr int64_t kPeriod = 20'000;
constexpr int64_t kLatency = 3'000;  // host clock minus stamp of a good message
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

class ExtractorHostileInput : public ::testing::Test {
 protected:
  ExtractorHostileInput() : node_(ExtractorServiceConfig{}, Pose2{0.2, 0.0, 0.0}) {
    SyntheticScene scene;
    scene.cylinders = {test::cylinder_at(2.0, 0.3), test::cylinder_at(3.0, -0.5)};
    std::mt19937 rng(5);
    template_ = render_synthetic_scan(scene, SyntheticScanConfig{}, rng);
  }

  /// The next good scan, its odometry before it; returns the output, counters summed.
  const ExtractorOutput& good_scan() {
    ++k_;
    const int64_t utime = kT0 + k_ * kPeriod;
    OdometrySample odometry;
    odometry.utime = utime - 2'000;
    odometry.twist = {0.5, 0.1, 0.3};
    count(node_.on_odometry(odometry, odometry.utime + kLatency));
    LaserScan scan = template_;
    scan.utime = utime;
    scan.scan_counter = static_cast<uint32_t>(k_);
    return handle(scan, utime + kLatency);
  }
  const ExtractorOutput& handle(const LaserScan& scan, int64_t host_utime) {
    const ExtractorOutput& out = node_.on_scan(scan, host_utime);
    count(out.events);
    out.for_each_counter([&](const char* name, int64_t by) { counters_[name] += by; });
    return out;
  }
  void count(const std::vector<NodeEvent>& events) {
    for (const NodeEvent& e : events)
      if (e.counter != nullptr) ++counters_[e.counter];
  }
  /// A scan at the next slot, spoiled; the good stream goes on around it.
  void hostile_scan(const std::function<void(LaserScan&)>& spoil, int64_t host_shift_us = 0) {
    LaserScan scan = template_;
    scan.utime = kT0 + k_ * kPeriod + kPeriod / 2;
    scan.scan_counter = 60'000;
    spoil(scan);
    const ExtractorOutput& out = handle(scan, kT0 + k_ * kPeriod + kPeriod / 2 + kLatency + host_shift_us);
    EXPECT_FALSE(out.accepted);
  }
  void hostile_odometry(BodyTwist twist, int64_t stamp_shift_us = 0) {
    OdometrySample odometry;
    odometry.utime = kT0 + k_ * kPeriod + kPeriod / 2 + stamp_shift_us;
    odometry.twist = twist;
    const std::vector<NodeEvent>& events =
        node_.on_odometry(odometry, kT0 + k_ * kPeriod + kPeriod / 2 + kLatency);
    EXPECT_EQ(events.size(), 1u);
    count(events);
  }
  static void expect_finite(const ExtractorOutput& out) {
    for (const ReflectorDetection& d : out.detections) {
      EXPECT_TRUE(d.laser_p_center.allFinite());
      EXPECT_TRUE(d.covariance.allFinite());
      EXPECT_TRUE(std::isfinite(d.range) && std::isfinite(d.bearing));
    }
  }

  ExtractorNode node_;
  LaserScan template_;
  int64_t k_ = 0;
  std::map<std::string, int64_t> counters_;
};

TEST_F(ExtractorHostileInput, EveryBrokenScanIsRejectedAndCountedAndGoodScansGoOn) {
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(good_scan().accepted);
  const size_t expected_detections = good_scan().detections.size();
  ASSERT_EQ(expected_detections, 2u);

  const std::vector<std::function<void(LaserScan&)>> nonfinite = {
      [](LaserScan& s) { s.ranges[200] = std::nanf(""); },
      [](LaserScan& s) { s.ranges[0] = std::numeric_limits<float>::infinity(); },
      [](LaserScan& s) { s.angle_increment = kNan; },
      [](LaserScan& s) { s.start_angle = kInf; },
      [](LaserScan& s) { s.time_increment = kNan; },
      [](LaserScan& s) { s.scan_period = kInf; },
      [](LaserScan& s) { s.range_min = kNan; },
  };
  const std::vector<std::function<void(LaserScan&)>> out_of_bounds = {
      [](LaserScan& s) { s.range_max = 1e300; },
      [](LaserScan& s) { s.ranges[10] = 1e30f; },
      [](LaserScan& s) { s.ranges[10] = -2.0f; },
      [](LaserScan& s) { s.angle_increment = 1e300; },
      [](LaserScan& s) { s.angle_increment = 0.0; },
      [](LaserScan& s) { s.scan_period = 100.0; },
      [](LaserScan& s) { s.time_increment = 1.0; },
      [](LaserScan& s) { s.rssi_bits = 3; },
      [](LaserScan& s) { s.rssi[5] = std::numeric_limits<int32_t>::max(); },
      [](LaserScan& s) { s.rssi.resize(3); },
      [](LaserScan& s) {
        s.ranges.clear();
        s.rssi.clear();
      },
  };
  for (const auto& spoil : nonfinite) {
    hostile_scan(spoil);
    const ExtractorOutput& out = good_scan();
    ASSERT_TRUE(out.accepted);
    EXPECT_EQ(out.detections.size(), expected_detections);
    expect_finite(out);
  }
  for (const auto& spoil : out_of_bounds) {
    hostile_scan(spoil);
    const ExtractorOutput& out = good_scan();
    ASSERT_TRUE(out.accepted);
    EXPECT_EQ(out.detections.size(), expected_detections);
  }
  EXPECT_EQ(counters_["rejected_scan_nonfinite"], static_cast<int64_t>(nonfinite.size()));
  EXPECT_EQ(counters_["rejected_scan_out_of_bounds"], static_cast<int64_t>(out_of_bounds.size()));
  EXPECT_EQ(counters_["gap_scan_messages"], 0);  // the rejected scans were extra, none lost
}

TEST_F(ExtractorHostileInput, StampsAnHourAheadOrBehindOrAtTheExtremesAreRejectedAndNeverStallTheStream) {
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(good_scan().accepted);
  const int64_t hour = 3'600'000'000;
  const std::vector<int64_t> stamps = {kT0 + hour, std::numeric_limits<int64_t>::max(), 0,
                                       kT0 - hour, std::numeric_limits<int64_t>::min(), -1};
  for (int64_t stamp : stamps) {
    hostile_scan([stamp](LaserScan& s) { s.utime = stamp; });
    ASSERT_TRUE(good_scan().accepted) << "after a scan stamped " << stamp;
  }
  EXPECT_EQ(counters_["rejected_scan_stamp_ahead"], 2);
  EXPECT_EQ(counters_["rejected_scan_stamp_behind"], 4);
  hostile_scan([this](LaserScan& s) { s.utime = kT0 + k_ * kPeriod; });  // a repeat of the last
  EXPECT_EQ(counters_["rejected_scan_stamp_not_increasing"], 1);
  EXPECT_TRUE(good_scan().accepted);
}

TEST_F(ExtractorHostileInput, ANanOrAbsurdOdometryTwistIsNeverUsedForCompensation) {
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(good_scan().accepted);
  const std::vector<BodyTwist> hostile = {
      {kNan, 0, 0}, {0, kInf, 0}, {0, 0, kNan}, {1e308, 0, 0}, {0, 0, 1e300}};
  for (const BodyTwist& twist : hostile) hostile_odometry(twist);
  hostile_odometry({0.5, 0.1, 0.3}, 3'600'000'000);  // a good twist stamped an hour ahead
  EXPECT_EQ(counters_["rejected_odometry_nonfinite"], 3);
  EXPECT_EQ(counters_["rejected_odometry_out_of_bounds"], 2);
  EXPECT_EQ(counters_["rejected_odometry_stamp_ahead"], 1);

  // The last accepted odometry (good_scan's) still compensates: a NaN never reaches a detection.
  LaserScan scan = template_;
  ++k_;
  scan.utime = kT0 + k_ * kPeriod;
  scan.scan_counter = static_cast<uint32_t>(k_);
  const ExtractorOutput& out = handle(scan, scan.utime + kLatency);
  ASSERT_TRUE(out.accepted);
  EXPECT_EQ(out.compensation, CompensationOutcome::kOdometry);
  ASSERT_EQ(out.detections.size(), 2u);
  expect_finite(out);
}

TEST_F(ExtractorHostileInput, OnlyRejectedScansForOverASecondDegradeTheService) {
  ASSERT_TRUE(good_scan().accepted);
  const int64_t start = kT0 + k_ * kPeriod;
  for (int i = 1; i <= 60; ++i) {
    LaserScan scan = template_;
    scan.utime = start + i * kPeriod;
    scan.ranges[0] = std::nanf("");
    node_.on_scan(scan, scan.utime + kLatency);
    if (i == 10) {
      EXPECT_EQ(node_.health(100, scan.utime + kLatency, "LMS100_SCAN").state, ExtractorHealth::State::kOk);
    }
  }
  const ExtractorHealth h = node_.health(100, start + 60 * kPeriod + kLatency, "LMS100_SCAN");
  EXPECT_EQ(h.state, ExtractorHealth::State::kDegraded);
  EXPECT_NE(h.detail.find("no usable scan"), std::string::npos) << h.detail;
  EXPECT_NE(h.detail.find("nonfinite"), std::string::npos) << h.detail;
}

TEST_F(ExtractorHostileInput, MissingScanCountersAreCountedAsGapsAndARestartIsAReset) {
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(good_scan().accepted);
  k_ += 4;  // four scans never arrive
  ASSERT_TRUE(good_scan().accepted);
  EXPECT_EQ(counters_["gap_scan_messages"], 4);

  LaserScan restarted = template_;
  ++k_;
  restarted.utime = kT0 + k_ * kPeriod;
  restarted.scan_counter = 0;  // the sensor restarted
  ASSERT_TRUE(handle(restarted, restarted.utime + kLatency).accepted);
  EXPECT_EQ(counters_["gap_scan_messages"], 4);
  EXPECT_EQ(counters_["counter_reset_scan"], 1);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
