#include "lms100_emulator/cola_a_request_reader.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::vector<std::string> read_all(ColaARequestReader& reader, const std::string& bytes) {
  reader.feed(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  std::vector<std::string> requests;
  std::string request;
  while (reader.next(request)) requests.push_back(request);
  return requests;
}

TEST(ColaARequestReader, TwoRequestsInOneReadComeOutInOrder) {
  ColaARequestReader reader;
  EXPECT_EQ(read_all(reader, "\x02sRN STlms\x03\x02sMN Run\x03"),
            (std::vector<std::string>{"sRN STlms", "sMN Run"}));
}

TEST(ColaARequestReader, RequestSplitOverReadsIsJoined) {
  ColaARequestReader reader;
  EXPECT_TRUE(read_all(reader, "\x02sEN LMD").empty());
  EXPECT_EQ(read_all(reader, "scandata 1\x03"), (std::vector<std::string>{"sEN LMDscandata 1"}));
}

TEST(ColaARequestReader, BytesOutsideFramesAreIgnored) {
  ColaARequestReader reader;
  EXPECT_EQ(read_all(reader, "junk\x03\r\n\x02sRN STlms\x03tail"), (std::vector<std::string>{"sRN STlms"}));
}

TEST(ColaARequestReader, StxInsideRequestRestartsIt) {
  ColaARequestReader reader;
  EXPECT_EQ(read_all(reader, "\x02sRN ST\x02sMN Run\x03"), (std::vector<std::string>{"sMN Run"}));
}

TEST(ColaARequestReader, OverlongRequestIsDroppedAndTheNextSurvives) {
  ColaARequestReader reader(8);
  EXPECT_EQ(read_all(reader, "\x02" + std::string(9, 'A') + "\x03\x02" + std::string(8, 'B') + "\x03"),
            (std::vector<std::string>{std::string(8, 'B')}));
}

TEST(ColaARequestReader, ResetForgetsTheOpenRequest) {
  ColaARequestReader reader;
  EXPECT_TRUE(read_all(reader, "\x02sRN ST").empty());
  reader.reset();
  EXPECT_TRUE(read_all(reader, "lms\x03").empty());
  EXPECT_EQ(read_all(reader, "\x02sMN Run\x03"), (std::vector<std::string>{"sMN Run"}));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
