// Hostile files at the library level: nesting bombs, FIFOs, devices, directories, huge
// files and unknown keys hidden behind {} or []. Each must be one ConfigError naming the
// file (and the key where there is one), never a crash, a hang or an allocation spree.

#include "common/json_config.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <functional>
#include <future>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;
using ::testing::Not;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

std::string temp_path(const std::string& name) { return ::testing::TempDir() + "/hostile_" + name; }

std::string nested_arrays(int depth) { return std::string(depth, '[') + std::string(depth, ']'); }

std::string nested_objects(int depth) {
  std::string text;
  for (int i = 0; i < depth; ++i) text += "{\"a\":";
  text += "1";
  return text + std::string(depth, '}');
}

TEST(JsonConfigHostile, HundredThousandNestedArraysAreRefusedWithThePointer) {
  const std::string msg =
      error_of([] { JsonConfig::parse_text("{\"x\":" + nested_arrays(100000) + "}", "deep.json"); });
  EXPECT_THAT(msg, HasSubstr("deep.json: /x/0/0/0"));
  EXPECT_THAT(msg, HasSubstr("nested deeper than 32 levels"));
  EXPECT_THAT(msg, Not(HasSubstr("\n")));
}

TEST(JsonConfigHostile, NestedObjectsAreRefusedNamingTheKeys) {
  const std::string msg = error_of([] { JsonConfig::parse_text(nested_objects(100000), "deep.json"); });
  EXPECT_THAT(msg, HasSubstr("deep.json: /a/a/a/a"));
  EXPECT_THAT(msg, HasSubstr("nested deeper than 32 levels"));
}

TEST(JsonConfigHostile, NestingUpToTheLimitIsAccepted) {
  const JsonConfig ok = JsonConfig::parse_text(nested_objects(kMaxConfigNestingDepth), "ok.json");
  EXPECT_TRUE(ok.has("/a/a"));
  EXPECT_THAT(error_of([] { JsonConfig::parse_text(nested_objects(kMaxConfigNestingDepth + 1), "x.json"); }),
              HasSubstr("nested deeper than 32 levels"));
}

TEST(JsonConfigHostile, DeepDocumentBuiltInMemoryIsWalkedWithoutRecursion) {
  // Documents handed to the constructor skip the parser's limit; the unknown-key walk must
  // still not recurse on their depth.
  nlohmann::json deep = 1;
  for (int i = 0; i < 10000; ++i) deep = nlohmann::json{{"a", std::move(deep)}};
  const JsonConfig c(std::move(deep), "memory");
  const std::string msg = error_of([&] { c.reject_unknown_keys(); });
  EXPECT_THAT(msg, HasSubstr("memory: /a/a/a"));
  EXPECT_THAT(msg, HasSubstr("unknown key"));
  EXPECT_LT(msg.size(), 400u) << "a 20,000-character pointer is cut in the message";
}

TEST(JsonConfigHostile, FifoIsRefusedWithoutWaitingForAWriter) {
  const std::string path = temp_path("fifo.json");
  ::unlink(path.c_str());
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  auto result =
      std::async(std::launch::async, [&] { return error_of([&] { JsonConfig::load_file(path); }); });
  if (result.wait_for(std::chrono::seconds(5)) != std::future_status::ready) {
    // Unblock the reader so a failing test ends instead of hanging ctest.
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
    ADD_FAILURE() << "load_file blocked on a FIFO";
  }
  EXPECT_THAT(result.get(), HasSubstr(path + ": is a FIFO; config and map files must be regular files"));
  ::unlink(path.c_str());
}

TEST(JsonConfigHostile, DevZeroAndDirectoriesAreRefused) {
  EXPECT_THAT(error_of([] { JsonConfig::load_file("/dev/zero"); }),
              HasSubstr("/dev/zero: is a character device; config and map files must be regular files"));
  EXPECT_THAT(error_of([] { JsonConfig::load_file(::testing::TempDir()); }), HasSubstr(": is a directory"));
}

TEST(JsonConfigHostile, FileLargerThanTheLimitIsRefusedBeforeReading) {
  const std::string path = temp_path("huge.json");
  std::ofstream(path) << "{}";
  ASSERT_EQ(::truncate(path.c_str(), 1LL << 32), 0);  // 4 GiB, sparse: nothing is written
  EXPECT_THAT(error_of([&] { JsonConfig::load_file(path); }),
              HasSubstr(path + ": larger than 4194304 bytes"));
  ::unlink(path.c_str());
}

TEST(JsonConfigHostile, FileAtTheLimitIsRead) {
  const std::string path = temp_path("padded.json");
  std::ofstream(path) << "{\"a\": 1}" << std::string(kMaxConfigFileBytes - 8, ' ');
  EXPECT_TRUE(JsonConfig::load_file(path).has("/a"));
  ::unlink(path.c_str());
}

TEST(JsonConfigHostile, UnknownKeyHoldingAnEmptyObjectOrArrayIsRefused) {
  for (const char* value : {"{}", "[]", "[{}]", "{\"b\": []}"}) {
    const JsonConfig c =
        JsonConfig::parse_text(std::string("{\"known\": 1, \"extra\": ") + value + "}", "t.json");
    c.number("/known", 0.0);
    EXPECT_THAT(error_of([&] { c.reject_unknown_keys(); }), HasSubstr("t.json: /extra")) << value;
  }
}

TEST(JsonConfigHostile, KnownSectionMayBeEmpty) {
  // "clustering": {} leaves every clustering key at its default; that is not a typo.
  const JsonConfig c = JsonConfig::parse_text(R"({"clustering": {}, "list": []})", "t.json");
  c.number("/clustering/range_sigma_m", 0.01);
  c.array_size("/list");
  EXPECT_EQ(error_of([&] { c.reject_unknown_keys(); }), "");
}

TEST(JsonConfigHostile, ControlCharactersInAKeyStayOnOneLine) {
  const JsonConfig c = JsonConfig::parse_text(R"({"bad\nkey": 1})", "t.json");
  const std::string msg = error_of([&] { c.reject_unknown_keys(); });
  EXPECT_THAT(msg, HasSubstr("t.json: /bad\\x0akey: unknown key"));
  EXPECT_THAT(msg, Not(HasSubstr("\n")));
}

TEST(JsonConfigHostile, NumberOverflowIsNotValidJson) {
  EXPECT_THAT(error_of([] { JsonConfig::parse_text(R"({"x": 1e999})", "t.json"); }),
              HasSubstr("t.json: not valid JSON"));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
