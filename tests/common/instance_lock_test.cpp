// One instance per service and LCM bus: the abstract-socket lock (common/instance_lock).

#include "common/instance_lock.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <memory>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr const char* kBus = "udpm://239.255.76.67:7667?ttl=0";

// Names unique to this test process, so a parallel run of the suite never collides.
std::string unique_service(const std::string& base) { return base + "_" + std::to_string(getpid()); }

TEST(InstanceLockBusIdentity, UdpmGroupWithoutOptionsIsTheBus) {
  EXPECT_EQ(lcm_bus_identity("udpm://239.255.76.67:7667?ttl=0"), "udpm://239.255.76.67:7667");
  EXPECT_EQ(lcm_bus_identity("udpm://239.255.76.67:7667?ttl=1&recv_buf_size=4194304"),
            "udpm://239.255.76.67:7667");
  EXPECT_EQ(lcm_bus_identity("udpm://239.255.76.68:7700"), "udpm://239.255.76.68:7700");
  EXPECT_EQ(lcm_bus_identity("udpm://"), "udpm://239.255.76.67:7667");
}

TEST(InstanceLockBusIdentity, ProcessPrivateBusesHaveNone) {
  EXPECT_EQ(lcm_bus_identity("memq://"), "");
  EXPECT_EQ(lcm_bus_identity("file:///tmp/log.lcm?speed=0"), "");
}

TEST(InstanceLockName, NamesServiceAndBusAndFitsSunPath) {
  EXPECT_EQ(instance_lock_name("pose_solver", "udpm://239.255.76.67:7667"),
            "refloc/pose_solver/udpm://239.255.76.67:7667");
  EXPECT_LE(instance_lock_name(std::string(300, 'x'), "udpm://239.255.76.67:7667").size(), 107u);
}

TEST(InstanceLock, SecondLockOfOneServiceOnOneBusIsRefusedNamingTheHolderPid) {
  const std::string service = unique_service("lock_test_a");
  InstanceLock first(service, kBus);
  ASSERT_TRUE(first.held());
  try {
    InstanceLock second(service, "udpm://239.255.76.67:7667?ttl=1");  // same bus, other ttl
    FAIL() << "a second instance was allowed";
  } catch (const InstanceConflictError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("another " + service + " is already running"), std::string::npos) << what;
    EXPECT_NE(what.find("udpm://239.255.76.67:7667"), std::string::npos) << what;
    EXPECT_NE(what.find("pid " + std::to_string(getpid())), std::string::npos) << what;
  }
}

TEST(InstanceLock, ConflictIsAConfigErrorSoMainExitsTwo) {
  const std::string service = unique_service("lock_test_b");
  InstanceLock first(service, kBus);
  EXPECT_THROW(InstanceLock(service, kBus), ConfigError);
}

TEST(InstanceLock, OtherServiceOrOtherBusIsNotAConflict) {
  const std::string service = unique_service("lock_test_c");
  InstanceLock first(service, kBus);
  EXPECT_NO_THROW(InstanceLock(unique_service("lock_test_c_other"), kBus));
  EXPECT_NO_THROW(InstanceLock(service, "udpm://239.255.76.67:7668?ttl=0"));
}

TEST(InstanceLock, MemqAndFileUrlsTakeNoLock) {
  const std::string service = unique_service("lock_test_d");
  InstanceLock first(service, "memq://");
  EXPECT_FALSE(first.held());
  EXPECT_NO_THROW(InstanceLock(service, "memq://"));
}

TEST(InstanceLock, ReleasedWhenTheHolderIsDestroyed) {
  const std::string service = unique_service("lock_test_e");
  { InstanceLock first(service, kBus); }
  EXPECT_NO_THROW(InstanceLock(service, kBus));
}

TEST(InstanceLock, ReleasedByTheKernelWhenTheHolderIsKilled) {
  const std::string service = unique_service("lock_test_f");
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    InstanceLock held(service, kBus);
    const char byte = 1;
    (void)!write(ready[1], &byte, 1);
    pause();
    _exit(0);
  }
  char byte = 0;
  ASSERT_EQ(read(ready[0], &byte, 1), 1);
  try {
    InstanceLock refused(service, kBus);
    ADD_FAILURE() << "the child's lock was not seen";
  } catch (const InstanceConflictError& e) {
    EXPECT_NE(std::string(e.what()).find("pid " + std::to_string(child)), std::string::npos) << e.what();
  }
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  close(ready[0]);
  close(ready[1]);
  EXPECT_NO_THROW(InstanceLock(service, kBus));  // no stale lock after kill -9
}

TEST(InstanceLock, ManyRefusedStartersStillLearnThePidAfterDraining) {
  const std::string service = unique_service("lock_test_g");
  InstanceLock first(service, kBus);
  const std::string pid_text = "pid " + std::to_string(getpid());
  for (int round = 0; round < 3; ++round) {
    for (int attempt = 0; attempt < 40; ++attempt) {
      try {
        InstanceLock refused(service, kBus);
      } catch (const InstanceConflictError& e) {
        ASSERT_NE(std::string(e.what()).find(pid_text), std::string::npos)
            << "attempt " << attempt << ": " << e.what();
      }
    }
    first.drain_refused_starters();
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
