#include "common/json_config.hpp"
#include "world_renderer/scan_renderer.hpp"
#include "world_renderer/world_loader.hpp"
#include "world_renderer/world_visibility.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace refloc::sim {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::AllOf;
using ::testing::HasSubstr;

constexpr double kDeg = M_PI / 180.0;
const std::string kConfigDir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";

/// Grid points of the drivable areas with room for the robot.
std::vector<Eigen::Vector2d> drivable_grid(const World& world, double step, double min_clearance) {
  std::vector<Eigen::Vector2d> points;
  for (const DrivableArea& a : world.drivable_areas) {
    for (double x = a.x_min; x <= a.x_max + 1e-9; x += step) {
      for (double y = a.y_min; y <= a.y_max + 1e-9; y += step) {
        if (clearance(world, {x, y}) >= min_clearance) points.emplace_back(x, y);
      }
    }
  }
  return points;
}

TEST(World, DemoWorldLoadsItsMapAndDistractors) {
  const World world = load_world(kConfigDir + "world_demo.json");
  const ReflectorMap map = load_reflector_map(kConfigDir + "map_demo.json");
  ASSERT_EQ(world.reflectors.reflectors.size(), map.reflectors.size());
  EXPECT_GE(map.reflectors.size(), 16u);
  EXPECT_LE(map.reflectors.size(), 24u);
  int tape = 0;
  int metal = 0;
  for (const WorldSegment& s : world.segments) {
    tape += s.surface == SurfaceKind::kReflectiveTape;
    metal += s.surface == SurfaceKind::kMetal;
  }
  EXPECT_GE(tape, 2);
  EXPECT_GE(metal, 2);
  EXPECT_EQ(world.map_file, std::filesystem::path(kConfigDir + "map_demo.json").lexically_normal().string());
}

TEST(World, DemoWorldShowsAtLeastFourReflectorsWithin15mEverywhereDrivable) {
  const World world = load_world(kConfigDir + "world_demo.json");
  const auto grid = drivable_grid(world, 0.25, 0.4);
  ASSERT_GT(grid.size(), 1000u);
  for (const Eigen::Vector2d& p : grid) {
    for (const double heading : {0.0, 0.5 * M_PI, M_PI, -0.5 * M_PI, 0.25 * M_PI}) {
      const auto ids = visible_reflector_ids(world, Pose2{p.x(), p.y(), heading}, 15.0, 135.0 * kDeg);
      EXPECT_GE(ids.size(), 4u) << "at (" << p.x() << ", " << p.y() << ") heading " << heading;
    }
  }
}

TEST(World, DemoWorldReflectorsAreDetectableInRenderedScans) {
  // Beyond line of sight: the renderer must show >= 4 reflectors with a beam over the
  // paper's energy threshold (8-bit 180) at sample poses. (Reflectors beyond ~8 m get a
  // single beam: 120 mm is less than two 0.5 deg steps there, as on the real sensor.)
  const World world = load_world(kConfigDir + "world_demo.json");
  ScanRenderer renderer;
  std::mt19937_64 rng(11);
  LaserScan scan;
  for (const Eigen::Vector2d& p : drivable_grid(world, 1.5, 0.5)) {
    renderer.render(world, Pose2{p.x(), p.y(), 0.3}, 0, rng, scan);
    std::map<int, int> bright_beams;
    for (size_t i = 0; i < scan.rssi.size(); ++i) {
      if (scan.rssi[i] > 180 * 257 && renderer.truth()[i].kind == HitKind::kReflector) {
        ++bright_beams[renderer.truth()[i].id];
      }
    }
    int detectable = 0;
    for (const auto& [id, count] : bright_beams) detectable += count >= 1;
    EXPECT_GE(detectable, 4) << "at (" << p.x() << ", " << p.y() << ")";
  }
}

TEST(World, PaperCellTable1PositionsSeeAtLeastFourReflectors) {
  const World world = load_world(kConfigDir + "paper_cell.json");
  const std::vector<Eigen::Vector2d> table1_mm = {{750, 1000},  {750, 2000},  {750, 3000},  {1500, 1000},
                                                  {1500, 2000}, {1500, 3000}, {2500, 1000}, {2500, 2000},
                                                  {2500, 3000}, {3000, 1000}};
  for (const Eigen::Vector2d& mm : table1_mm) {
    const Eigen::Vector2d p = mm / 1000.0;
    EXPECT_TRUE(world.is_drivable(p));
    for (const double heading : {0.0, 0.5 * M_PI, M_PI, -0.5 * M_PI}) {
      const auto ids = visible_reflector_ids(world, Pose2{p.x(), p.y(), heading}, 15.0, 135.0 * kDeg);
      EXPECT_GE(ids.size(), 4u) << "at " << mm.transpose() << " mm, heading " << heading;
    }
  }
}

TEST(World, SymmetricWorldShowsAtLeastFourReflectorsEverywhereDrivable) {
  const World world = load_world(kConfigDir + "world_symmetric.json");
  const auto grid = drivable_grid(world, 0.25, 0.4);
  ASSERT_GT(grid.size(), 400u);
  for (const Eigen::Vector2d& p : grid) {
    for (double heading = -M_PI; heading < M_PI; heading += M_PI / 4) {
      EXPECT_GE(visible_reflector_ids(world, Pose2{p.x(), p.y(), heading}, 15.0, 135.0 * kDeg).size(), 4u)
          << "at (" << p.x() << ", " << p.y() << ") heading " << heading;
    }
  }
}

TEST(World, SymmetricWorldLooksTheSameAfterAHalfTurn) {
  const World world = load_world(kConfigDir + "world_symmetric.json");
  const Eigen::Vector2d centre(5.0, 3.0);
  for (const MapReflector& r : world.reflectors.reflectors) {
    const Eigen::Vector2d turned = 2.0 * centre - r.map_p_center;
    int matches = 0;
    for (const MapReflector& s : world.reflectors.reflectors)
      matches += (s.map_p_center - turned).norm() < 1e-9;
    EXPECT_EQ(matches, 1) << "reflector " << r.id;
  }
  // And the renderer agrees: identical noise-free scans from the two poses.
  ScanRenderConfig config;
  config.sensor.range_sigma = 0.0;
  config.sensor.rssi_sigma = 0.0;
  std::mt19937_64 rng(1);
  LaserScan a;
  LaserScan b;
  render_scan(world, Pose2{3.0, 2.0, 0.4}, 0, config, rng, a);
  render_scan(world, Pose2{7.0, 4.0, 0.4 + M_PI}, 0, config, rng, b);
  ASSERT_EQ(a.ranges.size(), b.ranges.size());
  for (size_t i = 0; i < a.ranges.size(); ++i) {
    EXPECT_NEAR(a.ranges[i], b.ranges[i], 0.0015) << "beam " << i;
    EXPECT_NEAR(a.rssi[i], b.rssi[i], 2) << "beam " << i;
  }
}

TEST(World, VisibilityIsBlockedByWallsAndLimitedByFieldOfView) {
  World world;
  add_polyline(world, {{2.0, -1.0}, {2.0, 1.0}}, false, SurfaceKind::kDiffuse, 0.5);
  for (const auto& [id, x, y] :
       std::vector<std::tuple<int, double, double>>{{1, 4, 0}, {2, 1, 3}, {3, -3, 0}}) {
    MapReflector r;
    r.id = id;
    r.map_p_center = {x, y};
    world.reflectors.reflectors.push_back(r);
  }
  EXPECT_EQ(visible_reflector_ids(world, Pose2{}, 15.0, M_PI), (std::vector<int>{2, 3}));
  EXPECT_EQ(visible_reflector_ids(world, Pose2{}, 15.0, 135.0 * kDeg), (std::vector<int>{2}));
  EXPECT_EQ(visible_reflector_ids(world, Pose2{}, 2.9, M_PI), (std::vector<int>{}));
}

// ---- loader errors name the file and the JSON pointer ----

class WorldLoaderErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("refloc_world_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    write("map.json", R"({"reflectors": [{"id": 1, "x": 0, "y": 0}, {"id": 2, "x": 1, "y": 0},
                                        {"id": 3, "x": 0, "y": 1}]})");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  /// The ConfigError message of loading a world file with this text.
  std::string error_of(const std::string& world_text) {
    const std::string path = write("world.json", world_text);
    try {
      load_world(path);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "no error";
  }
  std::string world_path() const { return (dir_ / "world.json").string(); }

  std::filesystem::path dir_;
};

TEST_F(WorldLoaderErrors, AValidWorldLoads) {
  const std::string path = write("world.json", R"({"map_file": "map.json",
      "walls": [{"points": [[0, 0], [5, 0], [5, 5]], "closed": true}],
      "unmapped_reflectors": [{"id": 9, "x": 2, "y": 2}]})");
  const World world = load_world(path);
  EXPECT_EQ(world.segments.size(), 3u);
  EXPECT_EQ(world.reflectors.reflectors.size(), 4u);
  EXPECT_DOUBLE_EQ(world.segments[0].remission, 0.5);
}

TEST_F(WorldLoaderErrors, MapErrorsMoveRemoveAndAddReflectors) {
  const std::string path = write("world.json", R"({"map_file": "map.json",
      "moved_reflectors": [{"id": 2, "x": 1.25, "y": 0.5}], "missing_reflector_ids": [3],
      "unmapped_reflectors": [{"id": 9, "x": 2, "y": 2}]})");
  const World world = load_world(path);
  const ReflectorMap& r = world.reflectors;
  ASSERT_EQ(r.reflectors.size(), 3u);
  EXPECT_EQ(r.index_of(3), -1);
  ASSERT_GE(r.index_of(2), 0);
  EXPECT_EQ(r.reflectors[r.index_of(2)].map_p_center, Eigen::Vector2d(1.25, 0.5));
  EXPECT_GE(r.index_of(9), 0);
  EXPECT_THAT(error_of(R"({"map_file": "map.json", "missing_reflector_ids": [3, 3]})"),
              AllOf(HasSubstr(world_path()), HasSubstr("/missing_reflector_ids/1"), HasSubstr("id 3")));
  EXPECT_THAT(error_of(R"({"map_file": "map.json", "moved_reflectors": [{"id": 77, "x": 0, "y": 0}]})"),
              AllOf(HasSubstr(world_path()), HasSubstr("/moved_reflectors/0/id")));
}

TEST_F(WorldLoaderErrors, MissingMapFileKey) {
  EXPECT_THAT(error_of(R"({"walls": []})"), AllOf(HasSubstr(world_path()), HasSubstr("/map_file: missing")));
}

TEST_F(WorldLoaderErrors, MapFileThatDoesNotExist) {
  EXPECT_THAT(error_of(R"({"map_file": "nowhere.json"})"),
              AllOf(HasSubstr(world_path()), HasSubstr("/map_file"), HasSubstr("nowhere.json")));
}

TEST_F(WorldLoaderErrors, ErrorInsideTheMapFileNamesBothFiles) {
  write("bad_map.json", R"({"reflectors": [{"id": 1, "x": 0, "y": 0}, {"id": 2, "x": 1, "y": 0},
                                          {"id": 1, "x": 0, "y": 1}]})");
  EXPECT_THAT(error_of(R"({"map_file": "bad_map.json"})"),
              AllOf(HasSubstr(world_path()), HasSubstr("bad_map.json"), HasSubstr("/reflectors/2/id"),
                    HasSubstr("duplicate")));
}

TEST_F(WorldLoaderErrors, WrongTypeOfACoordinate) {
  EXPECT_THAT(
      error_of(R"({"map_file": "map.json", "walls": [{"points": [[0, 0], ["1", 0]]}]})"),
      AllOf(HasSubstr(world_path()), HasSubstr("/walls/0/points/1/0"), HasSubstr("expected a number")));
}

TEST_F(WorldLoaderErrors, OutOfRangeCoordinateAndRemission) {
  EXPECT_THAT(error_of(R"({"map_file": "map.json", "obstacles": [{"points": [[0, 0], [1e300, 0]]}]})"),
              AllOf(HasSubstr(world_path()), HasSubstr("/obstacles/0/points/1/0")));
  EXPECT_THAT(
      error_of(R"({"map_file": "map.json", "walls": [{"points": [[0, 0], [1, 0]], "remission": -1}]})"),
      AllOf(HasSubstr(world_path()), HasSubstr("/walls/0/remission")));
}

TEST_F(WorldLoaderErrors, DuplicateReflectorIdBetweenMapAndWorld) {
  EXPECT_THAT(error_of(R"({"map_file": "map.json", "unmapped_reflectors": [{"id": 2, "x": 3, "y": 3}]})"),
              AllOf(HasSubstr(world_path()), HasSubstr("/unmapped_reflectors/0/id"), HasSubstr("duplicate")));
}

TEST_F(WorldLoaderErrors, UnknownKeyAndUnknownSurface) {
  EXPECT_THAT(
      error_of(R"({"map_file": "map.json", "walls": [{"points": [[0, 0], [1, 0]], "colour": "red"}]})"),
      AllOf(HasSubstr(world_path()), HasSubstr("/walls/0/colour"), HasSubstr("unknown key")));
  EXPECT_THAT(
      error_of(
          R"({"map_file": "map.json", "distractors": [{"surface": "glass", "points": [[0, 0], [1, 0]]}]})"),
      AllOf(HasSubstr(world_path()), HasSubstr("/distractors/0/surface")));
}

TEST_F(WorldLoaderErrors, DegeneratePolylines) {
  EXPECT_THAT(error_of(R"({"map_file": "map.json", "walls": [{"points": [[0, 0]]}]})"),
              HasSubstr("/walls/0/points: expected at least 2 points"));
  EXPECT_THAT(error_of(R"({"map_file": "map.json", "walls": [{"points": [[0, 0], [0, 0]]}]})"),
              HasSubstr("/walls/0/points/1: repeats the previous point"));
}

TEST_F(WorldLoaderErrors, RenderConfigErrorsNameTheirPointer) {
  const JsonConfig config(nlohmann::json::parse(R"({"renderer": {"sensor": {"range_sigma": 5}}})"),
                          "emu.json");
  try {
    parse_scan_render_config(config, "/renderer");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("emu.json"), HasSubstr("/renderer/sensor/range_sigma")));
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc::sim
