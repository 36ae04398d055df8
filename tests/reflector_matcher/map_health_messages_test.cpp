// MAP_HEALTH's LCM edge: a report survives to_message -> encode -> decode -> from_message.

#include "reflector_matcher/map_health_messages.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

MapHealthReport sample_report() {
  MapHealthReport r;
  r.utime = 1'796'000'000'000'000;
  r.map_id = "demo_hall";
  r.map_version = 4;
  r.scans_used = 12345;
  r.reflectors.push_back({1, ReflectorHealth::kOk, {1.5, 0.1}, 240, 10, {0.001, -0.002}, {0.005, 0.006}});
  r.reflectors.push_back({3, ReflectorHealth::kMissing, {9.1, 0.1}, 0, 250, {0, 0}, {0, 0}});
  r.reflectors.push_back({4, ReflectorHealth::kMoved, {13.4, 0.1}, 30, 100, {0.3, -0.004}, {0.005, 0.005}});
  r.reflectors.push_back({5, ReflectorHealth::kUnconfirmed, {17.8, 0.1}, 2, 3, {0, 0}, {0, 0}});
  r.candidates.push_back({{13.7, 0.1}, {0.005, 0.006}, 68, 4.5, 4, 17});
  r.candidates.push_back({{15.6, 0.1}, {0.005, 0.005}, 90, 3.0, -1, 18});
  return r;
}

TEST(MapHealthMessages, ReportRoundTripsThroughTheEncodedMessage) {
  const MapHealthReport in = sample_report();
  map_health_t message;
  to_message(in, message);
  EXPECT_EQ(message.nreflectors, 4);
  EXPECT_EQ(message.ncandidates, 2);
  EXPECT_EQ(message.reflectors_ok, 1);
  EXPECT_EQ(message.reflectors_missing, 1);
  EXPECT_EQ(message.reflectors_moved, 1);
  EXPECT_EQ(message.reflectors_unconfirmed, 1);
  EXPECT_EQ(message.reflectors[2].state, map_reflector_health_t::STATE_MOVED);

  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
  ASSERT_GT(message.encode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  map_health_t decoded;
  ASSERT_GT(decoded.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  const MapHealthReport out = from_message(decoded);

  EXPECT_EQ(out.utime, in.utime);
  EXPECT_EQ(out.map_id, "demo_hall");
  EXPECT_EQ(out.map_version, 4);
  EXPECT_EQ(out.scans_used, 12345);
  ASSERT_EQ(out.reflectors.size(), 4u);
  for (size_t i = 0; i < in.reflectors.size(); ++i) {
    EXPECT_EQ(out.reflectors[i].id, in.reflectors[i].id);
    EXPECT_EQ(out.reflectors[i].state, in.reflectors[i].state);
    EXPECT_EQ(out.reflectors[i].map_p, in.reflectors[i].map_p);
    EXPECT_EQ(out.reflectors[i].seen, in.reflectors[i].seen);
    EXPECT_EQ(out.reflectors[i].expected_missing, in.reflectors[i].expected_missing);
    EXPECT_EQ(out.reflectors[i].offset, in.reflectors[i].offset);
    EXPECT_EQ(out.reflectors[i].offset_sigma, in.reflectors[i].offset_sigma);
  }
  ASSERT_EQ(out.candidates.size(), 2u);
  EXPECT_EQ(out.candidates[0].map_p, in.candidates[0].map_p);
  EXPECT_EQ(out.candidates[0].sigma, in.candidates[0].sigma);
  EXPECT_EQ(out.candidates[0].sightings, 68);
  EXPECT_EQ(out.candidates[0].viewpoint_spread, 4.5);
  EXPECT_EQ(out.candidates[0].moved_reflector_id, 4);
  EXPECT_EQ(out.candidates[1].moved_reflector_id, -1);
  EXPECT_EQ(out.new_candidates(), 1);
}

TEST(MapHealthMessages, UnknownStateReadsAsUnconfirmed) {
  map_health_t message;
  to_message(sample_report(), message);
  message.reflectors[0].state = 9;
  EXPECT_EQ(from_message(message).reflectors[0].state, ReflectorHealth::kUnconfirmed);
}

TEST(MapHealthMessages, CountersNameMissingMovedAndNewCandidates) {
  std::vector<std::pair<std::string, int64_t>> counters;
  sample_report().for_each_counter([&](const char* name, int64_t v) { counters.emplace_back(name, v); });
  const std::vector<std::pair<std::string, int64_t>> expected = {
      {"reflectors_missing", 1}, {"reflectors_moved", 1}, {"map_candidates", 1}};
  EXPECT_EQ(counters, expected);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
