// The parameter reference comes from the reader calls themselves: what a reader asked for, with
// its unit, meaning, range, default and effective value, printed as a commented config file
// that is valid input again, and as Markdown.

#include "common/config_reference.hpp"
#include "common/json_config.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

JsonConfig read_example(const std::string& text) {
  JsonConfig file = JsonConfig::parse_text(text, "example.json");
  file.number({"/radius_m", "m", "wheel radius"}, 0.05, 0.01, 1.0);
  file.integer({"/ticks", "count", "encoder ticks per revolution"}, 4096, 1, 1 << 20);
  file.choice({"/mode", "", "algorithm"}, "default", {"default", "paper"});
  const JsonConfig sub = file.child("/fix");
  sub.positive_number({"/max_age_s", "s", "oldest fix used"}, 0.5, 10.0, "no fix would be used");
  sub.boolean("/enabled", true);  // undocumented on purpose
  const size_t n = file.array_size({"/points", "", "list of points"}, false);
  for (size_t i = 0; i < n; ++i)
    file.number({"/points/" + std::to_string(i) + "/x", "m", "x of a point"}, 0.0);
  file.reject_unknown_keys();
  return file;
}

TEST(ConfigReference, RecordsEveryReadKeyWithItsDocumentationOnceEvenForArrays) {
  const JsonConfig file = read_example(R"({"radius_m": 0.07, "fix": {"enabled": false},
                                           "points": [{"x": 1}, {"x": 2}, {"x": 3}]})");
  const auto& keys = file.key_records();
  ASSERT_EQ(keys.size(), 7u);
  EXPECT_EQ(keys[0].pointer, "/radius_m");
  EXPECT_EQ(keys[0].unit, "m");
  EXPECT_EQ(keys[0].value, 0.07);
  EXPECT_EQ(keys[0].default_value, 0.05);
  EXPECT_EQ(keys[3].pointer, "/fix/max_age_s");
  EXPECT_EQ(keys[3].range, " in (0, 10]");
  EXPECT_EQ(keys[4].pointer, "/fix/enabled");
  EXPECT_EQ(keys[4].value, false);
  EXPECT_EQ(keys[6].pointer, "/points/*/x");
  EXPECT_EQ(undocumented_keys(keys), std::vector<std::string>{"/fix/enabled"});
}

TEST(ConfigReference, AnnotatedTextIsAValidConfigThatReadsBackTheSameValues) {
  const JsonConfig file = read_example(R"({"radius_m": 0.07, "mode": "paper", "points": [{"x": 1.5}]})");
  const std::string text = annotated_config_text(file.key_records(), "example\nsecond line");
  EXPECT_NE(text.find("// example\n// second line\n{"), std::string::npos) << text;
  EXPECT_NE(text.find("// wheel radius [m]; number in [0.01, 1]; default 0.05\n  \"radius_m\": 0.07"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\"fix\": {"), std::string::npos) << text;
  EXPECT_NE(text.find("/points/*/x: x of a point [m]"), std::string::npos) << text;
  const JsonConfig again = read_example(text);  // comments accepted, every key known
  ASSERT_EQ(again.key_records().size(), file.key_records().size());
  for (size_t i = 0; i < file.key_records().size(); ++i)
    EXPECT_EQ(again.key_records()[i].value, file.key_records()[i].value) << file.key_records()[i].pointer;
}

TEST(ConfigReference, MarkdownRows) {
  JsonConfig file = JsonConfig::parse_text("{}", "empty.json");
  file.string({"/channel", "", "LCM channel | input"}, "SCAN");
  file.number({"/rate_hz", "Hz", "publish rate"}, 50.0, 1.0, 100.0);
  const std::string md = config_reference_markdown(file.key_records());
  EXPECT_NE(md.find("| `/channel` | string |  | `\"SCAN\"` |  | LCM channel \\| input |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| `/rate_hz` | number | Hz | `50.0` | in [1, 100] | publish rate |"), std::string::npos)
      << md;
}

TEST(ConfigReference, CommentsInAConfigFileAreAccepted) {
  const JsonConfig file = JsonConfig::parse_text("// a comment\n{ /* inline */ \"a\": 1 // end\n}", "c.json");
  EXPECT_EQ(file.integer("/a", 0), 1);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
