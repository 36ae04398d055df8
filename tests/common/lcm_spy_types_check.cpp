// lcm-spy finds types by fingerprint among the classes on its class path. This
// test asks lcm-spy's own LCMTypeDatabase, loaded with `java -cp` from our jar,
// to resolve the fingerprint of every C++ type: a mismatch between the C++ and
// Java generated code, or a type missing from the jar, fails here.

#include "tests/tools/run_command.hpp"

#include <gtest/gtest.h>
#include <refloc/heartbeat_t.hpp>
#include <refloc/laser_scan_t.hpp>
#include <refloc/map_candidate_t.hpp>
#include <refloc/map_health_t.hpp>
#include <refloc/map_reflector_health_t.hpp>
#include <refloc/nav_goal_t.hpp>
#include <refloc/nav_status_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_cluster_t.hpp>
#include <refloc/reflector_clusters_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_match_t.hpp>
#include <refloc/reflector_matches_t.hpp>
#include <refloc/reflector_t.hpp>
#include <refloc/twist_t.hpp>
#include <refloc/wheel_encoders_t.hpp>

#include <map>
#include <sstream>

namespace refloc {
namespace {

template <class Message>
void add(std::map<int64_t, std::string>& types) {
  types[Message::getHash()] = std::string("refloc.") + Message::getTypeName();
}

TEST(LcmSpyTypes, EveryCppTypeResolvesToItsJavaClassInTheJar) {
  std::map<int64_t, std::string> expected;
  add<laser_scan_t>(expected);
  add<reflector_t>(expected);
  add<reflector_detections_t>(expected);
  add<reflector_match_t>(expected);
  add<reflector_matches_t>(expected);
  add<pose2d_t>(expected);
  add<wheel_encoders_t>(expected);
  add<odometry_t>(expected);
  add<twist_t>(expected);
  add<nav_goal_t>(expected);
  add<nav_status_t>(expected);
  add<heartbeat_t>(expected);
  add<map_health_t>(expected);
  add<map_reflector_health_t>(expected);
  add<map_candidate_t>(expected);
  add<reflector_cluster_t>(expected);
  add<reflector_clusters_t>(expected);
  ASSERT_EQ(expected.size(), 17u);

  // lcm-spy's class path: LCM, jchart2d (its plots), our types.
  std::string command = std::string("java -cp /usr/share/java/lcm.jar:/usr/share/java/jchart2d.jar:") +
                        REFLOC_LCMTYPES_JAR + ":" + REFLOC_JAVA_CHECK_DIR + " LcmSpyTypeCheck";
  for (const auto& [hash, name] : expected) command += " " + std::to_string(hash);
  const auto result = testing::run_command(command);
  ASSERT_EQ(result.exit_code, 0) << result.output;

  EXPECT_NE(result.output.find("Found 17 LCM types"), std::string::npos) << result.output;
  std::map<int64_t, std::string> resolved;
  std::istringstream lines(result.output);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    int64_t hash = 0;
    std::string name;
    if (fields >> hash >> name) resolved[hash] = name;
  }
  for (const auto& [h, n] : expected) {
    EXPECT_EQ(resolved[h], n) << "fingerprint " << h;
  }
}

}  // namespace
}  // namespace refloc
