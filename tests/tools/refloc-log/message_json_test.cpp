// Decoding of every refloc type by fingerprint into JSON, and the CSV
// flattening rules for nested structs and arrays of structs.

#include "message_json.hpp"
#include "csv_flatten.hpp"

#include <gtest/gtest.h>
#include <algorithm>
#include <filesystem>
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

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

template <class Message>
std::vector<uint8_t> encode(const Message& m) {
  std::vector<uint8_t> bytes(static_cast<size_t>(m.getEncodedSize()));
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

template <class Message>
void expect_type_decodes(const MessageDecoder& decoder, const std::string& name) {
  Message m{};
  const auto bytes = encode(m);
  const auto decoded = decoder.decode(bytes.data(), bytes.size());
  ASSERT_TRUE(decoded.has_value()) << name;
  EXPECT_EQ(decoded->type, name);
  EXPECT_TRUE(decoded->fields.is_object());
  EXPECT_STREQ(decoder.type_name(bytes.data(), bytes.size()), name.c_str());
}

TEST(MessageDecoder, KnowsEveryRefLocType) {
  const MessageDecoder d;
  // One per .lcm file: MAP_HEALTH was logged for a while before refloc-log could decode it.
  size_t lcm_files = 0;
  for (const auto& e : std::filesystem::directory_iterator(REFLOC_SOURCE_DIR "/lcmtypes"))
    lcm_files += e.path().extension() == ".lcm";
  EXPECT_EQ(d.type_names().size(), lcm_files);
  expect_type_decodes<heartbeat_t>(d, "heartbeat_t");
  expect_type_decodes<map_candidate_t>(d, "map_candidate_t");
  expect_type_decodes<map_health_t>(d, "map_health_t");
  expect_type_decodes<map_reflector_health_t>(d, "map_reflector_health_t");
  expect_type_decodes<laser_scan_t>(d, "laser_scan_t");
  expect_type_decodes<nav_goal_t>(d, "nav_goal_t");
  expect_type_decodes<nav_status_t>(d, "nav_status_t");
  expect_type_decodes<odometry_t>(d, "odometry_t");
  expect_type_decodes<pose2d_t>(d, "pose2d_t");
  expect_type_decodes<reflector_cluster_t>(d, "reflector_cluster_t");
  expect_type_decodes<reflector_clusters_t>(d, "reflector_clusters_t");
  expect_type_decodes<reflector_detections_t>(d, "reflector_detections_t");
  expect_type_decodes<reflector_match_t>(d, "reflector_match_t");
  expect_type_decodes<reflector_matches_t>(d, "reflector_matches_t");
  expect_type_decodes<reflector_t>(d, "reflector_t");
  expect_type_decodes<twist_t>(d, "twist_t");
  expect_type_decodes<wheel_encoders_t>(d, "wheel_encoders_t");
}

TEST(MessageDecoder, TruncatedOrForeignBytesDoNotDecode) {
  const MessageDecoder d;
  pose2d_t p{};
  auto bytes = encode(p);
  bytes.resize(bytes.size() - 1);
  EXPECT_FALSE(d.decode(bytes.data(), bytes.size()).has_value());
  const std::vector<uint8_t> foreign{0, 1, 2, 3, 4, 5, 6, 7, 8};
  EXPECT_FALSE(d.decode(foreign.data(), foreign.size()).has_value());
  EXPECT_EQ(d.type_name(foreign.data(), 3), nullptr);
}

TEST(MessageDecoder, LeadingUtimeWithoutFullDecode) {
  const MessageDecoder d;
  twist_t t{};
  t.utime = 1'234'567'890'123;
  const auto bytes = encode(t);
  EXPECT_EQ(d.utime(bytes.data(), bytes.size()), 1'234'567'890'123);
  reflector_t r{};  // starts with x, not utime
  const auto rb = encode(r);
  EXPECT_FALSE(d.utime(rb.data(), rb.size()).has_value());
}

TEST(MessageDecoder, NestedStructsAndFloatsAsSent) {
  const MessageDecoder d;
  reflector_matches_t m{};
  m.utime = 42;
  m.matches.resize(2);
  m.matches[0].map_id = 7;
  m.matches[0].detection.range = 3.5;
  m.matches[0].detection.mean_rssi = 0.1f;
  m.matches[1].map_id = 9;
  m.nmatches = 2;
  const auto bytes = encode(m);
  const auto j = d.decode(bytes.data(), bytes.size())->fields;
  EXPECT_EQ(j["matches"][0]["map_id"].get<int>(), 7);
  EXPECT_EQ(j["matches"][1]["map_id"].get<int>(), 9);
  EXPECT_DOUBLE_EQ(j["matches"][0]["detection"]["range"].get<double>(), 3.5);
  EXPECT_EQ(j["matches"][0]["detection"]["mean_rssi"].dump(), "0.1");
}

TEST(CsvFlatten, ArraysOfStructsGetOneColumnPerFieldAndNestedArraysAreOmitted) {
  const MessageDecoder d;
  const auto columns = csv_columns(*d.prototype("reflector_detections_t"));
  const std::vector<std::string> expected{"utime",
                                          "scan_counter",
                                          "clusters_considered",
                                          "clusters_rejected",
                                          "nreflectors",
                                          "reflectors.x",
                                          "reflectors.y",
                                          "reflectors.range",
                                          "reflectors.bearing",
                                          "reflectors.utime",
                                          "reflectors.first_beam",
                                          "reflectors.nbeams",
                                          "reflectors.mean_rssi",
                                          "reflectors.roundness_m",
                                          "reflectors.fitted_radius_m"};
  EXPECT_EQ(columns, expected);
  const auto match_columns = csv_columns(*d.prototype("reflector_matches_t"));
  EXPECT_NE(std::find(match_columns.begin(), match_columns.end(), "matches.detection.x"),
            match_columns.end());
  EXPECT_NE(std::find(match_columns.begin(), match_columns.end(), "matches.map_id"), match_columns.end());
}

TEST(CsvFlatten, ElementValuesAreJoinedPerColumn) {
  const MessageDecoder d;
  reflector_detections_t m{};
  m.reflectors.resize(3);
  for (int i = 0; i < 3; ++i) m.reflectors[i].range = 1.0 + i;
  m.nreflectors = 3;
  const auto bytes = encode(m);
  const auto columns = csv_columns(*d.prototype("reflector_detections_t"));
  const auto cells = csv_cells(d.decode(bytes.data(), bytes.size())->fields, columns);
  EXPECT_EQ(cells[4], "3");
  EXPECT_EQ(cells[7], "1.0;2.0;3.0");  // reflectors.range
  // No reflectors: the columns stay, empty.
  reflector_detections_t none{};
  const auto nb = encode(none);
  const auto empty_cells = csv_cells(d.decode(nb.data(), nb.size())->fields, columns);
  EXPECT_EQ(empty_cells.size(), columns.size());
  EXPECT_EQ(empty_cells[7], "");
}

TEST(CsvFlatten, QuotesCellsWithCommasQuotesAndNewlines) {
  EXPECT_EQ(csv_line({"a", "b,c", "say \"hi\"", "x\ny", ""}), "a,\"b,c\",\"say \"\"hi\"\"\",\"x\ny\",");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
