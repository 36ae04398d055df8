#include "common/service_command_line.hpp"

#include "common/guarded_main.hpp"
#include "common/json_config.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

/// argv for CLI11 from literal arguments.
struct Argv {
  explicit Argv(std::vector<std::string> args) : storage(std::move(args)) {
    for (auto& s : storage) pointers.push_back(s.data());
  }
  int argc() const { return static_cast<int>(pointers.size()); }
  char** argv() { return pointers.data(); }
  std::vector<std::string> storage;
  std::vector<char*> pointers;
};

TEST(ServiceCommandLine, CommonOptionsReachTheBody) {
  ServiceCommandLine cli("test_service", "test", "deploy/config/test.json");
  cli.add_robot_option("robot file");
  Argv a({"test_service", "--lcm-url", "udpm://239.255.76.67:7667?ttl=0", "--robot", "r.json"});
  std::string seen_config, seen_url, seen_robot;
  const int rc = cli.run(a.argc(), a.argv(), [&] {
    seen_config = cli.config_path;
    seen_url = cli.lcm_url;
    seen_robot = cli.robot_path;
    return 0;
  });
  EXPECT_EQ(rc, 0);
  // The default names a shipped file under the refloc root, not the working directory.
  EXPECT_EQ(seen_config, std::string(REFLOC_SOURCE_DIR) + "/deploy/config/test.json");
  EXPECT_EQ(seen_url, "udpm://239.255.76.67:7667?ttl=0");
  EXPECT_EQ(seen_robot, "r.json");
}

TEST(ServiceCommandLine, UnknownOptionIsAUsageErrorAndTheBodyNeverRuns) {
  ServiceCommandLine cli("test_service", "test", "");
  Argv a({"test_service", "--no-such-option"});
  bool ran = false;
  const int rc = cli.run(a.argc(), a.argv(), [&] {
    ran = true;
    return 0;
  });
  EXPECT_NE(rc, 0);
  EXPECT_FALSE(ran);
}

TEST(ServiceCommandLine, HelpExitsZeroWithoutRunning) {
  ServiceCommandLine cli("test_service", "test", "");
  Argv a({"test_service", "--help"});
  bool ran = false;
  EXPECT_EQ(cli.run(a.argc(), a.argv(),
                    [&] {
                      ran = true;
                      return 0;
                    }),
            0);
  EXPECT_FALSE(ran);
}

TEST(ServiceCommandLine, ConfigErrorInTheBodyExitsWithTheConfigErrorCode) {
  ServiceCommandLine cli("test_service", "test", "");
  Argv a({"test_service", "--config", "/nonexistent/service.json"});
  const int rc = cli.run(a.argc(), a.argv(), [&] {
    JsonConfig::load_file(cli.config_path);
    return 0;
  });
  EXPECT_EQ(rc, kExitConfigError);
}

TEST(ServiceCommandLine, OtherExceptionsExitOne) {
  ServiceCommandLine cli("test_service", "test", "");
  Argv a({"test_service"});
  EXPECT_EQ(cli.run(a.argc(), a.argv(), []() -> int { throw std::runtime_error("boom"); }), 1);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
