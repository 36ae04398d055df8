// ColaBSplitter on hostile byte streams: a binary payload may hold the magic itself, so sync
// rests on magic, length and checksum together.
#include "lms100_driver/cola_b_splitter.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lms100_driver/cola_b_commands.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::vector<std::string> split(ColaBSplitter& splitter, const std::string& stream, size_t chunk) {
  std::vector<std::string> out;
  std::string payload;
  for (size_t i = 0; i < stream.size(); i += chunk) {
    const std::string piece = stream.substr(i, chunk);
    splitter.feed(reinterpret_cast<const uint8_t*>(piece.data()), piece.size());
    while (splitter.next(payload)) out.push_back(payload);
  }
  return out;
}

TEST(ColaBSplitter, FramesSplitAcrossReadsAndSeveralPerReadComeOutWhole) {
  const std::string a = std::string("sSN LMDscandata \x02\x02\x02\x02\x00\x01", 22);  // the magic inside
  const std::string b = "sAN Run \x01";
  const std::string stream = frame_cola_b(a) + frame_cola_b(b) + frame_cola_b(a);
  for (const size_t chunk : {size_t{1}, size_t{3}, size_t{5}, stream.size()}) {
    ColaBSplitter splitter;
    EXPECT_EQ(split(splitter, stream, chunk), (std::vector<std::string>{a, b, a})) << "chunk " << chunk;
    EXPECT_EQ(splitter.garbage_bytes(), 0u);
    EXPECT_EQ(splitter.resyncs(), 0u);
  }
}

TEST(ColaBSplitter, JunkBadChecksumsAndHugeLengthsAreSkippedAndCounted) {
  std::string corrupt = frame_cola_b("sAN Run \x01");
  corrupt.back() = static_cast<char>(corrupt.back() ^ 0x20);
  const std::string huge = std::string("\x02\x02\x02\x02\x7F\xFF\xFF\xFF", 8);
  const std::string stream = "junk" + corrupt + huge + frame_cola_b("sEA LMDscandata \x01");
  ColaBSplitter splitter(1000);
  EXPECT_EQ(split(splitter, stream, 4), (std::vector<std::string>{"sEA LMDscandata \x01"}));
  EXPECT_EQ(splitter.resyncs(), 1u);
  EXPECT_EQ(splitter.oversized_frames(), 1u);
  EXPECT_EQ(splitter.garbage_bytes(), 4u + corrupt.size() + huge.size());
}

TEST(ColaBSplitter, ResetForgetsAHalfFrame) {
  const std::string frame = frame_cola_b("sAN Run \x01");
  ColaBSplitter splitter;
  split(splitter, frame.substr(0, 10), 10);
  splitter.reset();
  EXPECT_EQ(split(splitter, frame, frame.size()), (std::vector<std::string>{"sAN Run \x01"}));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
