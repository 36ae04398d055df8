#include "common/json_config.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

JsonConfig make(const char* text) { return JsonConfig(nlohmann::json::parse(text), "test.json"); }

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(JsonConfig, ReturnsDefaultsForAbsentKeys) {
  const JsonConfig c = make(R"({"a": {"b": 2.5}})");
  EXPECT_DOUBLE_EQ(c.number("/a/b", 1.0, 0.0, 10.0), 2.5);
  EXPECT_DOUBLE_EQ(c.number("/a/c", 1.0), 1.0);
  EXPECT_EQ(c.integer("/n", 7), 7);
  EXPECT_TRUE(c.boolean("/flag", true));
  EXPECT_EQ(c.string("/s", "x"), "x");
}

TEST(JsonConfig, OutOfRangeNamesFilePointerAndRange) {
  const JsonConfig c = make(R"({"noise": {"sigma_m": -1}})");
  const std::string msg = error_of([&] { c.number("/noise/sigma_m", 0.012, 0.0, 1.0); });
  EXPECT_THAT(msg, HasSubstr("test.json: /noise/sigma_m:"));
  EXPECT_THAT(msg, HasSubstr("[0, 1]"));
  EXPECT_THAT(msg, HasSubstr("-1"));
}

TEST(JsonConfig, WrongTypeNamesTheTypeFound) {
  const JsonConfig c = make(R"({"rate_hz": "fast", "n": 1.5, "on": 1})");
  EXPECT_THAT(error_of([&] { c.number("/rate_hz", 50.0); }),
              HasSubstr("expected a number, got string \"fast\""));
  EXPECT_THAT(error_of([&] { c.integer("/n", 1); }), HasSubstr("/n: expected an integer"));
  EXPECT_THAT(error_of([&] { c.boolean("/on", false); }), HasSubstr("/on: expected true or false"));
}

TEST(JsonConfig, MissingRequiredKeyIsAnError) {
  const JsonConfig c = make(R"({})");
  EXPECT_THAT(error_of([&] { c.required_number("/x"); }), HasSubstr("test.json: /x: missing"));
}

TEST(JsonConfig, NonFiniteNumberIsRejected) {
  // Documents built in memory (not parsed) can hold NaN and infinity.
  const JsonConfig c(nlohmann::json{{"x", std::numeric_limits<double>::infinity()}, {"y", std::nan("")}},
                     "test.json");
  EXPECT_THAT(error_of([&] { c.number("/y", 0.0); }), HasSubstr("/y: expected a finite number"));
  EXPECT_THAT(error_of([&] { c.number("/x", 0.0); }), HasSubstr("/x: expected a finite number"));
}

TEST(JsonConfig, UnknownKeyIsReportedWithItsPointer) {
  const JsonConfig c = make(R"({"good": 1, "nested": {"typo_m": 2}})");
  c.number("/good", 0.0);
  EXPECT_THAT(error_of([&] { c.reject_unknown_keys(); }),
              HasSubstr("test.json: /nested/typo_m: unknown key"));
}

TEST(JsonConfig, ChoiceListsAllowedValues) {
  const JsonConfig c = make(R"({"mode": "fancy"})");
  EXPECT_THAT(error_of([&] {
                c.choice("/mode", "default", {"default", "paper"});
              }),
              HasSubstr("expected one of \"default\", \"paper\", got \"fancy\""));
}

TEST(JsonConfig, UnreadableAndMalformedFilesAreConfigErrors) {
  EXPECT_THAT(error_of([] { JsonConfig::load_file("/nonexistent/x.json"); }), HasSubstr("cannot open"));
  const std::string path = ::testing::TempDir() + "/malformed.json";
  FILE* f = std::fopen(path.c_str(), "w");
  std::fputs("{\"a\": ", f);
  std::fclose(f);
  EXPECT_THAT(error_of([&] { JsonConfig::load_file(path); }), HasSubstr("not valid JSON"));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
