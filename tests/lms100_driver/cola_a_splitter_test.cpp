#include "lms100_driver/cola_a_splitter.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lms100_driver/cola_a_format.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

void feed_string(ColaASplitter& splitter, const std::string& bytes) {
  splitter.feed(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}

std::vector<std::string> drain(ColaASplitter& splitter) {
  std::vector<std::string> out;
  std::string payload;
  while (splitter.next(payload)) out.push_back(payload);
  return out;
}

const std::vector<std::string> kTelegrams = {
    "sAN SetAccessMode 1", "sWA LMDscandatacfg", "sRA STlms 7 0 8 00:17:28 A 01.01.1970 0 0 0",
    "sSN LMDscandata 1 1 8D4C04 0 0 45FF 37 280F6 28A73 0 0 7 0 0 1388 168 0 0 0 0 0 0 0 0 0", "sFA 4"};

std::string stream_of(const std::vector<std::string>& telegrams) {
  std::string stream;
  for (const auto& t : telegrams) stream += frame_cola_a(t);
  return stream;
}

TEST(ColaASplitter, FrameColaAAddsStxAndEtx) {
  EXPECT_EQ(frame_cola_a("sRN STlms"), std::string("\x02sRN STlms\x03"));
}

TEST(ColaASplitter, SeveralFramesInOneReadAllComeOut) {
  ColaASplitter splitter;
  feed_string(splitter, stream_of(kTelegrams));
  EXPECT_EQ(drain(splitter), kTelegrams);
  EXPECT_EQ(splitter.frames(), 5u);
  EXPECT_EQ(splitter.garbage_bytes(), 0u);
  EXPECT_EQ(splitter.resyncs(), 0u);
}

TEST(ColaASplitter, StreamCutAtEveryByteBoundaryGivesSameTelegrams) {
  const std::string stream = stream_of(kTelegrams);
  for (size_t cut = 0; cut <= stream.size(); ++cut) {
    ColaASplitter splitter;
    std::vector<std::string> got;
    feed_string(splitter, stream.substr(0, cut));
    for (auto& t : drain(splitter)) got.push_back(t);
    feed_string(splitter, stream.substr(cut));
    for (auto& t : drain(splitter)) got.push_back(t);
    ASSERT_EQ(got, kTelegrams) << "cut at " << cut;
  }
}

TEST(ColaASplitter, ByteByByteFeedGivesSameTelegrams) {
  const std::string stream = stream_of(kTelegrams);
  ColaASplitter splitter;
  std::vector<std::string> got;
  for (char c : stream) {
    feed_string(splitter, std::string(1, c));
    for (auto& t : drain(splitter)) got.push_back(t);
  }
  EXPECT_EQ(got, kTelegrams);
}

TEST(ColaASplitter, GarbageBetweenTelegramsIsCountedAndSkipped) {
  ColaASplitter splitter;
  feed_string(splitter,
              "junk" + frame_cola_a("sFA 4") + "\r\nxx\x03" + frame_cola_a("sWA LMDscandatacfg") + "z");
  EXPECT_EQ(drain(splitter), (std::vector<std::string>{"sFA 4", "sWA LMDscandatacfg"}));
  EXPECT_EQ(splitter.garbage_bytes(), 4u + 5u + 1u);
}

TEST(ColaASplitter, StxInsideFrameRestartsFrameThere) {
  ColaASplitter splitter;
  feed_string(splitter, std::string("\x02sSN LMDscan") + frame_cola_a("sAN Run 1"));
  EXPECT_EQ(drain(splitter), (std::vector<std::string>{"sAN Run 1"}));
  EXPECT_EQ(splitter.resyncs(), 1u);
  EXPECT_EQ(splitter.frames(), 1u);
}

TEST(ColaASplitter, OversizedFrameIsDroppedAndNextFrameSurvives) {
  ColaASplitter splitter(16);
  feed_string(splitter, frame_cola_a(std::string(100, 'A')) + frame_cola_a("sAN Run 1"));
  EXPECT_EQ(drain(splitter), (std::vector<std::string>{"sAN Run 1"}));
  EXPECT_EQ(splitter.oversized_frames(), 1u);
  EXPECT_EQ(splitter.garbage_bytes(), 0u);
}

TEST(ColaASplitter, FrameOfExactlyMaxSizeIsKept) {
  ColaASplitter splitter(16);
  feed_string(splitter, frame_cola_a(std::string(16, 'A')));
  EXPECT_EQ(drain(splitter), (std::vector<std::string>{std::string(16, 'A')}));
  EXPECT_EQ(splitter.oversized_frames(), 0u);
}

TEST(ColaASplitter, ResetDropsOpenFrame) {
  ColaASplitter splitter;
  feed_string(splitter, "\x02sAN Set");
  std::string payload;
  EXPECT_FALSE(splitter.next(payload));
  splitter.reset();
  feed_string(splitter, "AccessMode 1\x03");
  EXPECT_FALSE(splitter.next(payload));
  EXPECT_EQ(splitter.garbage_bytes(), 13u);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
