// refloc-map update: the next map version from the last MAP_HEALTH of the map in an LCM log
// (plan_map_update, and the binary: dry run, selection flags, refusals, exit codes).

#include "map_update.hpp"

#include "common/json_config.hpp"
#include "reflector_matcher/map_health_messages.hpp"
#include "tests/tools/run_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <unistd.h>

#include <filesystem>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

const std::string kTool = std::string(REFLOC_BINARY_DIR) + "/bin/refloc-map";

ReflectorMap hall(int version) {
  ReflectorMap map;
  map.info = {2, "hall_u", version, "2026-12-01T00:00:00Z", "typed"};
  const double xy[][2] = {{0, 0}, {5, 0}, {10, 0}, {0, 8}, {10, 8}};
  for (int i = 0; i < 5; ++i) map.reflectors.push_back({i + 1, {xy[i][0], xy[i][1]}, 0.06, "", std::nullopt});
  return map;
}

// 2 missing, 4 moved by (0.1, 0), a new reflector at (5, 8), and the candidate of 4's new place.
MapHealthReport evidence_for(const ReflectorMap& map) {
  MapHealthReport r;
  r.map_id = map.info.map_id;
  r.map_version = map.info.version;
  r.scans_used = 500;
  for (const MapReflector& m : map.reflectors) {
    ReflectorHealthEntry e{m.id, ReflectorHealth::kOk, m.map_p_center, 200, 5, {0, 0}, {0.005, 0.005}};
    if (m.id == 2) e.state = ReflectorHealth::kMissing, e.seen = 0, e.expected_missing = 250;
    if (m.id == 4) e.state = ReflectorHealth::kMoved, e.offset = {0.1, 0.0};
    r.reflectors.push_back(e);
  }
  r.candidates.push_back({{5.0, 8.0}, {0.004, 0.006}, 80, 3.0, -1, 0});
  r.candidates.push_back({{0.1, 8.0}, {0.005, 0.005}, 60, 2.0, 4, 0});
  return r;
}

TEST(MapUpdatePlan, RemovesMovesAndAddsWithTheNextVersion) {
  const ReflectorMap map = hall(3);
  const MapUpdatePlan plan = plan_map_update(map, evidence_for(map), {}, "2026-12-03T08:00:00Z");
  EXPECT_EQ(plan.next.info.version, 4);
  EXPECT_EQ(plan.next.info.source, "updated");
  EXPECT_EQ(plan.next.info.map_id, "hall_u");
  EXPECT_EQ(plan.next.info.created, "2026-12-03T08:00:00Z");
  EXPECT_EQ(plan.removed, 1);
  EXPECT_EQ(plan.moved, 1);
  EXPECT_EQ(plan.added, 1);  // 4's new place is no new reflector
  ASSERT_EQ(plan.next.reflectors.size(), 5u);
  EXPECT_EQ(plan.next.index_of(2), -1);
  const MapReflector& moved = plan.next.reflectors[static_cast<size_t>(plan.next.index_of(4))];
  EXPECT_EQ(moved.map_p_center, Eigen::Vector2d(0.1, 8.0));
  ASSERT_TRUE(moved.map_cov_center.has_value());
  EXPECT_NEAR((*moved.map_cov_center)(0, 0), 0.005 * 0.005, 1e-12);
  const MapReflector& added = plan.next.reflectors.back();
  EXPECT_EQ(added.id, 6);
  EXPECT_EQ(added.map_p_center, Eigen::Vector2d(5.0, 8.0));
  EXPECT_NEAR((*added.map_cov_center)(1, 1), 0.006 * 0.006, 1e-12);
}

TEST(MapUpdatePlan, OnlyTheSelectedKindsOfChange) {
  const ReflectorMap map = hall(3);
  MapUpdateSelection only_add{true, false, false};
  const MapUpdatePlan plan = plan_map_update(map, evidence_for(map), only_add, "2026-12-03T08:00:00Z");
  EXPECT_EQ(plan.added, 1);
  EXPECT_EQ(plan.removed + plan.moved, 0);
  EXPECT_EQ(plan.next.reflectors.size(), 6u);
  EXPECT_EQ(plan.next.reflectors[3].map_p_center, Eigen::Vector2d(0.0, 8.0));
}

TEST(MapUpdatePlan, EvidenceOfAnotherMapIsRefused) {
  const ReflectorMap map = hall(3);
  EXPECT_THROW(check_evidence_is_for(map, evidence_for(hall(2)), "log"), ConfigError);
  MapHealthReport other = evidence_for(map);
  other.reflectors[0].map_p = {0.5, 0.0};
  EXPECT_THROW(check_evidence_is_for(map, other, "log"), ConfigError);
  EXPECT_NO_THROW(check_evidence_is_for(map, evidence_for(map), "log"));
}

std::string fresh_dir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("refloc_map_update_" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

void write_log(const std::string& path, const std::vector<MapHealthReport>& reports) {
  lcm::LogFile log(path, "w");
  int64_t utime = 1'000'000;
  for (const MapHealthReport& r : reports) {
    map_health_t message;
    to_message(r, message);
    std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
    message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    lcm::LogEvent event;
    event.eventnum = 0;
    event.timestamp = utime += 1'000'000;
    event.channel = "MAP_HEALTH";
    event.datalen = static_cast<int32_t>(bytes.size());
    event.data = bytes.data();
    log.writeEvent(&event);
  }
}

TEST(ReflocMapUpdateCli, DryRunListsThenUpdateWritesTheNextVersionFromTheLastMessage) {
  const std::string dir = fresh_dir("update");
  const ReflectorMap map = hall(3);
  write_reflector_map(map, dir + "/map.json");
  MapHealthReport early = evidence_for(map);
  early.candidates.clear();
  write_log(dir + "/run.lcm", {evidence_for(hall(2)), early, evidence_for(map)});
  const std::string args = " update --map " + dir + "/map.json --evidence " + dir + "/run.lcm";
  auto r = testing::run_command(kTool + args + " --dry-run");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output,
              HasSubstr("remove reflector 2 at (5.000, 0.000): missing (seen 0, expected and unseen 250)"));
  EXPECT_THAT(r.output, HasSubstr("move reflector 4 from (0.000, 8.000) to (0.100, 8.000)"));
  EXPECT_THAT(r.output, HasSubstr("add reflector 6 at (5.000, 8.000)"));
  EXPECT_THAT(r.output, HasSubstr("dry run, nothing written: would be map hall_u version 4: 5 reflectors"));
  EXPECT_EQ(testing::run_command(kTool + args).exit_code, 64);  // neither --out nor --dry-run

  r = testing::run_command(kTool + args + " --remove-missing --out " + dir + "/next.json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("keep (no --move-moved) reflector 4"));
  const ReflectorMap next = load_reflector_map(dir + "/next.json");
  EXPECT_EQ(next.info.version, 4);
  EXPECT_EQ(next.info.source, "updated");
  EXPECT_EQ(next.reflectors.size(), 4u);

  r = testing::run_command(kTool + args + " --out " + dir + "/next.json");  // exists
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("exists; give --force"));
  r = testing::run_command(kTool + " update --map " + dir + "/next.json --evidence " + dir +
                           "/run.lcm --dry-run");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("none for \"hall_u\" version 4: refusing"));
  r = testing::run_command(kTool + args + " --dry-run --channel OTHER");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("no OTHER message"));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
