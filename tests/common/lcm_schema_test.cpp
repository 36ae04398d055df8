// The generated bounds check of every LCM type: valid messages pass and decode to themselves,
// lying lengths, truncations and foreign fingerprints are refused with the reason.

#include "common/lcm_bounded_decode.hpp"

#include <gtest/gtest.h>
#include <refloc_lcm_samples.hpp>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

template <class Message>
std::vector<uint8_t> encode(const Message& m) {
  std::vector<uint8_t> bytes(static_cast<size_t>(m.getEncodedSize()));
  EXPECT_GE(m.encode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  return bytes;
}

template <class Message>
std::vector<uint8_t> sample_bytes(int32_t n) {
  Message m{};
  fill_lcm_sample(m, n);
  return encode(m);
}

int64_t fixed_bytes(LcmFieldKind kind) {
  switch (kind) {
    case LcmFieldKind::kInt16:
      return 2;
    case LcmFieldKind::kInt32:
    case LcmFieldKind::kFloat:
      return 4;
    case LcmFieldKind::kInt64:
    case LcmFieldKind::kDouble:
      return 8;
    default:
      return 1;
  }
}

int32_t read_int32(const std::vector<uint8_t>& b, size_t at) {
  return static_cast<int32_t>((uint32_t{b[at]} << 24) | (uint32_t{b[at + 1]} << 16) |
                              (uint32_t{b[at + 2]} << 8) | uint32_t{b[at + 3]});
}

void write_int32(std::vector<uint8_t>& b, size_t at, int64_t value) {
  const auto v = static_cast<uint32_t>(static_cast<int32_t>(value));
  for (int i = 0; i < 4; ++i) b[at + static_cast<size_t>(i)] = static_cast<uint8_t>(v >> (24 - 8 * i));
}

/// Byte offset of every top-level member of a valid datagram (index = member). Written for
/// our types: nested structs have no variable parts (the test says so when that changes).
std::vector<size_t> member_offsets(const LcmSchema& schema, const std::vector<uint8_t>& bytes) {
  std::vector<size_t> offsets;
  std::vector<int64_t> values(schema.field_count, 0);
  size_t pos = 8;
  for (size_t i = 0; i < schema.field_count; ++i) {
    const LcmFieldSchema& f = schema.fields[i];
    offsets.push_back(pos);
    const int64_t count = f.length_field >= 0 ? values[static_cast<size_t>(f.length_field)] : f.fixed_count;
    for (int64_t k = 0; k < count; ++k) {
      if (f.kind == LcmFieldKind::kString) {
        pos += 4 + static_cast<size_t>(read_int32(bytes, pos));
      } else if (f.kind == LcmFieldKind::kStruct) {
        for (size_t j = 0; j < f.nested->field_count; ++j)
          EXPECT_EQ(f.nested->fields[j].length_field, -1) << "member_offsets needs a nested walk now";
        pos += static_cast<size_t>(f.nested->min_encoded_bytes);
      } else {
        if (f.kind == LcmFieldKind::kInt32 && f.fixed_count == 1) values[i] = read_int32(bytes, pos);
        pos += static_cast<size_t>(fixed_bytes(f.kind));
      }
    }
  }
  EXPECT_EQ(pos, bytes.size());
  return offsets;
}

template <class Message>
std::string refusal(const std::vector<uint8_t>& bytes) {
  Message m{};
  const LcmDecodeResult r = decode_lcm_bounded(bytes.data(), bytes.size(), m);
  return r.ok ? std::string("(accepted)") : r.reason;
}

template <class Message>
class LcmSchemaCheck : public ::testing::Test {};
using AllLcmTypes = ::testing::Types<REFLOC_LCM_TYPE_LIST>;
TYPED_TEST_SUITE(LcmSchemaCheck, AllLcmTypes);

TYPED_TEST(LcmSchemaCheck, GeneratedFingerprintEqualsLcmGens) {
  EXPECT_EQ(lcm_schema_of<TypeParam>().fingerprint, static_cast<uint64_t>(TypeParam::getHash()));
  EXPECT_STREQ(lcm_schema_of<TypeParam>().type_name, TypeParam::getTypeName());
}

TYPED_TEST(LcmSchemaCheck, ValidMessagesPassAndDecodeToTheSameBytes) {
  for (int32_t n : {0, 1, 3, 17}) {
    const std::vector<uint8_t> bytes = sample_bytes<TypeParam>(n);
    TypeParam decoded{};
    const LcmDecodeResult r = decode_lcm_bounded(bytes.data(), bytes.size(), decoded);
    ASSERT_TRUE(r.ok) << "n = " << n << ": " << r.reason;
    EXPECT_EQ(encode(decoded), bytes) << "n = " << n;
  }
}

TYPED_TEST(LcmSchemaCheck, EveryTruncationAndAnyTrailingByteIsRefused) {
  std::vector<uint8_t> bytes = sample_bytes<TypeParam>(2);
  for (size_t size = 0; size < bytes.size(); ++size) {
    TypeParam m{};
    EXPECT_FALSE(decode_lcm_bounded(bytes.data(), size, m).ok) << size << " of " << bytes.size() << " bytes";
  }
  bytes.push_back(0);
  EXPECT_EQ(refusal<TypeParam>(bytes),
            std::string("1 bytes after the end of the ") + TypeParam::getTypeName());
}

TYPED_TEST(LcmSchemaCheck, ForeignFingerprintIsRefused) {
  std::vector<uint8_t> bytes = sample_bytes<TypeParam>(1);
  bytes[7] ^= 0x01;
  EXPECT_NE(refusal<TypeParam>(bytes).find(std::string("is not ") + TypeParam::getTypeName()),
            std::string::npos);
}

TYPED_TEST(LcmSchemaCheck, LyingArrayLengthsAreRefusedWithTheReason) {
  const LcmSchema& schema = lcm_schema_of<TypeParam>();
  const std::vector<uint8_t> valid = sample_bytes<TypeParam>(2);
  const std::vector<size_t> offsets = member_offsets(schema, valid);
  std::vector<int32_t> lengths_tested;
  for (size_t i = 0; i < schema.field_count; ++i) {
    const LcmFieldSchema& array = schema.fields[i];
    // The first array of a length is where a lie is caught (nav_goal_t: x, y, theta share one).
    if (array.length_field < 0 ||
        std::count(lengths_tested.begin(), lengths_tested.end(), array.length_field))
      continue;
    lengths_tested.push_back(array.length_field);
    const size_t at = offsets[static_cast<size_t>(array.length_field)];
    const std::string length_name = schema.fields[array.length_field].name;
    const int64_t left = static_cast<int64_t>(valid.size() - at - 4);
    const int64_t least = array.kind == LcmFieldKind::kStruct   ? array.nested->min_encoded_bytes
                          : array.kind == LcmFieldKind::kString ? 5
                                                                : fixed_bytes(array.kind);
    struct Lie {
      int64_t declared;
      std::string reason;
    };
    std::vector<Lie> lies = {
        {-1, length_name + " = -1 declared, " + std::to_string(left) + " bytes left"},
        {INT32_MIN, length_name + " = " + std::to_string(INT32_MIN) + " declared"},
        {INT32_MAX, length_name + " = 2147483647 declared, max " + std::to_string(array.max_count)},
        {array.max_count + 1, length_name + " = " + std::to_string(array.max_count + 1) + " declared, max " +
                                  std::to_string(array.max_count)}};
    const int64_t one_too_many = left / least + 1;  // one element more than the bytes left can hold
    if (one_too_many <= array.max_count)
      lies.push_back({one_too_many, length_name + " = " + std::to_string(one_too_many) + " declared, " +
                                        array.name + "[] needs at least " +
                                        std::to_string(one_too_many * least) + " bytes, " +
                                        std::to_string(left) + " left"});
    for (const Lie& lie : lies) {
      std::vector<uint8_t> bytes = valid;
      write_int32(bytes, at, lie.declared);
      EXPECT_EQ(refusal<TypeParam>(bytes).rfind(lie.reason, 0), 0u)
          << array.name << ": got '" << refusal<TypeParam>(bytes) << "', want '" << lie.reason << "'";
    }
  }
}

TYPED_TEST(LcmSchemaCheck, LyingStringLengthsAreRefusedWithTheReason) {
  const LcmSchema& schema = lcm_schema_of<TypeParam>();
  const std::vector<uint8_t> valid = sample_bytes<TypeParam>(2);
  const std::vector<size_t> offsets = member_offsets(schema, valid);
  for (size_t i = 0; i < schema.field_count; ++i) {
    const LcmFieldSchema& f = schema.fields[i];
    if (f.kind != LcmFieldKind::kString || f.fixed_count != 1) continue;
    const std::string name = f.name;
    const int64_t left = static_cast<int64_t>(valid.size() - offsets[i] - 4);
    const std::vector<std::pair<int64_t, std::string>> lies = {
        {0, name + ": string length 0 declared (at least 1, the NUL)"},
        {-1, name + ": string length -1 declared (at least 1, the NUL)"},
        {f.max_string_chars + 2, name + ": string of " + std::to_string(f.max_string_chars + 1) +
                                     " characters declared, max " + std::to_string(f.max_string_chars)},
        {left + 1, name + ": string of " + std::to_string(left + 1) + " bytes declared, " +
                       std::to_string(left) + " bytes left"}};
    for (const auto& [declared, reason] : lies) {
      std::vector<uint8_t> bytes = valid;
      write_int32(bytes, offsets[i], declared);
      EXPECT_EQ(refusal<TypeParam>(bytes), reason);
    }
    std::vector<uint8_t> no_nul = valid;
    no_nul[offsets[i] + 4 + static_cast<size_t>(read_int32(valid, offsets[i])) - 1] = 'x';
    EXPECT_EQ(refusal<TypeParam>(no_nul), name + ": string does not end in a NUL");
    std::vector<uint8_t> inner_nul = valid;  // "service" -> "s\0rvice": re-encoded it would shrink
    inner_nul[offsets[i] + 5] = 0;
    EXPECT_EQ(refusal<TypeParam>(inner_nul), name + ": string has a NUL before its end");
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
