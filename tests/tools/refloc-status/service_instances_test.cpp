// refloc-status shows a service that runs twice as one ERROR row per process
// (tools/refloc-status/service_instances), and a restart as one row.

#include "service_instances.hpp"
#include "heartbeat_table.hpp"
#include "status_report.hpp"
#include "status_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

HeartbeatSample beat(int32_t pid, double t_s, int64_t start_utime, int8_t state = 1,
                     const std::string& detail = "") {
  HeartbeatSample s;
  s.service = "pose_solver";
  s.pid = pid;
  s.state = state;
  s.state_detail = detail;
  s.uptime_us = static_cast<int64_t>(t_s * 1e6);
  s.utime = start_utime + s.uptime_us;
  return s;
}

struct Fixture {
  HeartbeatTable table;
  ServiceInstances instances;
  void hear(const HeartbeatSample& s, double t_s) {
    table.update(s, t_s);
    instances.update(s, t_s);
  }
  std::vector<ServiceStatus> rows(double now_s) {
    auto rows = table.rows({"pose_solver"}, now_s);
    instances.split_duplicates(rows, now_s);
    return rows;
  }
};

TEST(ServiceInstancesRows, TwoProcessesOfOneServiceAreTwoErrorRowsNamingBothPids) {
  Fixture f;
  for (int i = 0; i < 3; ++i) {
    f.hear(beat(100, i, 1'000'000'000), i);
    f.hear(beat(200, i + 0.5, 2'000'000'000, 1, "tracking"), i + 0.5);
  }
  const auto rows = f.rows(2.6);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].last.pid, 100);
  EXPECT_EQ(rows[1].last.pid, 200);
  for (const auto& r : rows) {
    EXPECT_TRUE(r.duplicate);
    EXPECT_EQ(heartbeat_state_name(r.last.state), "ERROR");
    EXPECT_FALSE(r.has_rates());
  }
  EXPECT_EQ(rows[0].last.state_detail, "two instances: pid 100, pid 200");
  EXPECT_EQ(rows[1].last.state_detail, "two instances: pid 100, pid 200; tracking");
  EXPECT_NEAR(rows[0].age_s, 0.6, 1e-9);
  EXPECT_NEAR(rows[1].age_s, 0.1, 1e-9);
  EXPECT_EQ(status_exit_code(rows), 1);
  const std::string table = format_status_table(rows);
  EXPECT_NE(table.find("RUNNING MORE THAN ONCE: pose_solver"), std::string::npos) << table;
  EXPECT_EQ(status_to_json(rows)["ok"], false);
}

TEST(ServiceInstancesRows, ServiceSayingItRunsTwiceIsNotSaidTwice) {
  Fixture f;
  const std::string own = "two instances: pid 100, pid 200";
  for (int i = 0; i < 3; ++i) {
    f.hear(beat(100, i, 1'000'000'000, 3, own), i);
    f.hear(beat(200, i + 0.5, 2'000'000'000, 3, own), i + 0.5);
  }
  for (const auto& r : f.rows(2.6)) EXPECT_EQ(r.last.state_detail, own);
}

TEST(ServiceInstancesRows, RestartIsOneRowAndExitZero) {
  Fixture f;
  for (int i = 0; i < 4; ++i) f.hear(beat(100, i, 1'000'000'000), i);
  for (int i = 0; i < 4; ++i) f.hear(beat(300, i, 1'004'200'000), 3.2 + i);
  const auto rows = f.rows(6.3);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_FALSE(rows[0].duplicate);
  EXPECT_EQ(rows[0].last.pid, 300);
  EXPECT_EQ(rows[0].pid_changes, 1);
  EXPECT_EQ(status_exit_code(rows), 0);
}

TEST(ServiceInstancesRows, BackToOneRowWhenTheSecondStopsSending) {
  Fixture f;
  for (int i = 0; i < 3; ++i) {
    f.hear(beat(100, i, 1'000'000'000), i);
    f.hear(beat(200, i + 0.5, 2'000'000'000), i + 0.5);
  }
  for (int i = 3; i < 8; ++i) f.hear(beat(100, i, 1'000'000'000), i);
  const auto rows = f.rows(7.0);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].last.pid, 100);
  EXPECT_EQ(heartbeat_state_name(rows[0].last.state), "OK");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
