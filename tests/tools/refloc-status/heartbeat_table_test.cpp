// refloc-status model: rates from successive heartbeats, ages, missing and
// stale services, restarts, and the exit status.

#include "heartbeat_table.hpp"

#include <gtest/gtest.h>
#include <refloc/heartbeat_t.hpp>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

HeartbeatSample beat(const std::string& service, int32_t pid, double t_s, int64_t in, int64_t out) {
  HeartbeatSample s;
  s.service = service;
  s.pid = pid;
  s.state = heartbeat_t::STATE_OK;
  s.utime = 1'700'000'000'000'000 + static_cast<int64_t>(t_s * 1e6);
  s.messages_in = in;
  s.messages_out = out;
  return s;
}

TEST(HeartbeatTable, RatesAreCounterDifferencesOverSenderTime) {
  HeartbeatTable table;
  table.update(beat("pose_solver", 10, 0.0, 100, 90), 5.0);
  table.update(beat("pose_solver", 10, 1.0, 125, 115), 5.3);  // receive jitter must not matter
  const auto rows = table.rows({"pose_solver"}, 5.5);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_TRUE(rows[0].has_rates());
  EXPECT_DOUBLE_EQ(rows[0].rate_in_hz, 25.0);
  EXPECT_DOUBLE_EQ(rows[0].rate_out_hz, 25.0);
  EXPECT_NEAR(rows[0].age_s, 0.2, 1e-12);
}

TEST(HeartbeatTable, OneHeartbeatGivesNoRate) {
  HeartbeatTable table;
  table.update(beat("navigator", 10, 0.0, 5, 5), 1.0);
  const auto rows = table.rows({"navigator"}, 1.0);
  EXPECT_FALSE(rows[0].has_rates());
  EXPECT_TRUE(rows[0].seen);
  EXPECT_FALSE(rows[0].missing());
}

TEST(HeartbeatTable, ShortWindowKeepsPreviousRate) {
  HeartbeatTable table(3.0, 0.5);
  table.update(beat("a", 1, 0.0, 0, 0), 0.0);
  table.update(beat("a", 1, 1.0, 50, 10), 1.0);
  // The extra heartbeat a service sends when stopping comes 0.1 s later: too short to rate.
  table.update(beat("a", 1, 1.1, 60, 10), 1.1);
  auto rows = table.rows({}, 1.1);
  EXPECT_DOUBLE_EQ(rows[0].rate_in_hz, 50.0);
  // The next full window is measured from the heartbeat the last rate came from (t = 1.0).
  table.update(beat("a", 1, 2.0, 150, 30), 2.0);
  rows = table.rows({}, 2.0);
  EXPECT_DOUBLE_EQ(rows[0].rate_in_hz, 100.0);
  EXPECT_DOUBLE_EQ(rows[0].rate_out_hz, 20.0);
}

TEST(HeartbeatTable, SenderClockStepBackFallsBackToReceiveTime) {
  HeartbeatTable table;
  table.update(beat("a", 1, 10.0, 0, 0), 100.0);
  table.update(beat("a", 1, 5.0, 40, 0), 102.0);  // sender's wall clock jumped back 5 s
  const auto rows = table.rows({}, 102.0);
  EXPECT_DOUBLE_EQ(rows[0].rate_in_hz, 20.0);
}

TEST(HeartbeatTable, RestartResetsRatesAndCountsPidChange) {
  HeartbeatTable table;
  table.update(beat("a", 1, 0.0, 1000, 1000), 0.0);
  table.update(beat("a", 1, 1.0, 1010, 1010), 1.0);
  table.update(beat("a", 2, 2.0, 3, 3), 2.0);  // new process: counters start again
  auto rows = table.rows({}, 2.0);
  EXPECT_FALSE(rows[0].has_rates());
  EXPECT_EQ(rows[0].pid_changes, 1);
  EXPECT_EQ(rows[0].last.pid, 2);
  table.update(beat("a", 2, 3.0, 13, 8), 3.0);
  rows = table.rows({}, 3.0);
  EXPECT_DOUBLE_EQ(rows[0].rate_in_hz, 10.0);
  EXPECT_DOUBLE_EQ(rows[0].rate_out_hz, 5.0);
}

TEST(HeartbeatTable, ExpectedServiceNeverHeardIsMissingAndExitIsOne) {
  HeartbeatTable table;
  table.update(beat("lms100_driver", 1, 0.0, 0, 0), 0.0);
  const auto rows = table.rows({"lms100_driver", "pose_fusion"}, 1.0);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].service, "pose_fusion");
  EXPECT_FALSE(rows[1].seen);
  EXPECT_TRUE(rows[1].missing());
  EXPECT_EQ(missing_services(rows), std::vector<std::string>{"pose_fusion"});
  EXPECT_EQ(status_exit_code(rows), 1);
}

TEST(HeartbeatTable, HeartbeatOlderThanThreeSecondsIsStale) {
  HeartbeatTable table(3.0);
  table.update(beat("a", 1, 0.0, 0, 0), 10.0);
  EXPECT_EQ(status_exit_code(table.rows({"a"}, 12.9)), 0);
  const auto rows = table.rows({"a"}, 13.1);
  EXPECT_TRUE(rows[0].stale);
  EXPECT_TRUE(rows[0].missing());
  EXPECT_NEAR(rows[0].age_s, 3.1, 1e-9);
  EXPECT_EQ(status_exit_code(rows), 1);
}

TEST(HeartbeatTable, UnexpectedServicesAreListedAfterExpectedOnesAndNeverFail) {
  HeartbeatTable table;
  table.update(beat("zeta", 1, 0.0, 0, 0), 0.0);
  table.update(beat("alpha", 2, 0.0, 0, 0), 0.0);
  table.update(beat("b", 3, 0.0, 0, 0), 0.0);
  const auto rows = table.rows({"b"}, 100.0);  // all stale
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].service, "b");
  EXPECT_EQ(rows[1].service, "alpha");
  EXPECT_EQ(rows[2].service, "zeta");
  EXPECT_TRUE(rows[1].stale);
  EXPECT_FALSE(rows[1].missing());
  EXPECT_EQ(missing_services(rows), std::vector<std::string>{"b"});
}

TEST(HeartbeatTable, AllExpectedAliveExitsZero) {
  HeartbeatTable table;
  for (const char* s : {"a", "b", "c"}) table.update(beat(s, 1, 0.0, 0, 0), 0.0);
  EXPECT_EQ(status_exit_code(table.rows({"a", "b", "c"}, 2.0)), 0);
  EXPECT_EQ(status_exit_code(table.rows({}, 2.0)), 0);
}

TEST(HeartbeatTable, AServiceInErrorFailsTheCheckExpectedOrNot) {
  HeartbeatTable table;
  HeartbeatSample driver = beat("lms100_driver", 1, 0.0, 0, 0);
  driver.state = heartbeat_t::STATE_ERROR;
  table.update(driver, 0.0);
  HeartbeatSample logger = beat("lcm_logger", 2, 0.0, 0, 0);
  table.update(logger, 0.0);
  EXPECT_EQ(services_in_error(table.rows({"lms100_driver"}, 1.0)), std::vector<std::string>{"lms100_driver"});
  EXPECT_EQ(status_exit_code(table.rows({"lms100_driver"}, 1.0)), 1);
  logger.state = heartbeat_t::STATE_ERROR;  // not expected, but saying it is broken (full disk)
  driver.state = heartbeat_t::STATE_OK;
  table.update(driver, 1.0);
  table.update(logger, 1.0);
  EXPECT_EQ(services_in_error(table.rows({"lms100_driver"}, 1.5)), std::vector<std::string>{"lcm_logger"});
  EXPECT_EQ(status_exit_code(table.rows({"lms100_driver"}, 1.5)), 1);
  logger.state = heartbeat_t::STATE_DEGRADED;
  table.update(logger, 2.0);
  EXPECT_EQ(status_exit_code(table.rows({"lms100_driver"}, 2.5)), 0) << "DEGRADED alone passes";
}

TEST(HeartbeatStateName, MatchesHeartbeatTypeConstants) {
  EXPECT_EQ(heartbeat_state_name(heartbeat_t::STATE_STARTING), "STARTING");
  EXPECT_EQ(heartbeat_state_name(heartbeat_t::STATE_OK), "OK");
  EXPECT_EQ(heartbeat_state_name(heartbeat_t::STATE_DEGRADED), "DEGRADED");
  EXPECT_EQ(heartbeat_state_name(heartbeat_t::STATE_ERROR), "ERROR");
  EXPECT_EQ(heartbeat_state_name(heartbeat_t::STATE_STOPPING), "STOPPING");
  EXPECT_EQ(heartbeat_state_name(9), "STATE_9");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
