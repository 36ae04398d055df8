#include "lms100_driver/cola_a_tokenizer.hpp"

#include <cstring>
#include <utility>

namespace refloc {

bool ColaATokenizer::fail(std::string message) {
  error_ = std::move(message);
  return false;
}

bool ColaATokenizer::token(std::string_view& out) {
  if (pos_ >= text_.size()) return fail("telegram ends early");
  const size_t space = text_.find(' ', pos_);
  const size_t end = space == std::string_view::npos ? text_.size() : space;
  out = text_.substr(pos_, end - pos_);
  // A trailing separator with nothing behind it leaves pos_ past the end: the next read fails.
  pos_ = space == std::string_view::npos ? text_.size() : space + 1;
  if (out.empty()) return fail("empty token (two spaces in a row or a trailing space)");
  ++tokens_read_;
  return true;
}

bool ColaATokenizer::parse_hex(std::string_view token, uint32_t& out) {
  if (token.empty()) return false;
  uint64_t value = 0;
  for (const char c : token) {
    unsigned digit = 0;
    if (c >= '0' && c <= '9') {
      digit = static_cast<unsigned>(c - '0');
    } else if (c >= 'A' && c <= 'F') {
      digit = static_cast<unsigned>(c - 'A' + 10);
    } else if (c >= 'a' && c <= 'f') {
      digit = static_cast<unsigned>(c - 'a' + 10);
    } else {
      return false;
    }
    value = value * 16 + digit;
    if (value > 0xFFFFFFFFull) return false;  // leading zeros are fine, overflow is not
  }
  out = static_cast<uint32_t>(value);
  return true;
}

bool ColaATokenizer::hex_u32(uint32_t& out, uint32_t max_value) {
  std::string_view t;
  if (!token(t)) return false;
  uint32_t value = 0;
  if (!parse_hex(t, value)) return fail("'" + std::string(t.substr(0, 16)) + "' is not a 32-bit hex number");
  if (value > max_value) return fail("value " + std::string(t) + " is out of range");
  out = value;
  return true;
}

bool ColaATokenizer::hex_i32(int32_t& out) {
  uint32_t bits = 0;
  if (!hex_u32(bits)) return false;
  std::memcpy(&out, &bits, sizeof out);
  return true;
}

bool ColaATokenizer::hex_float(float& out) {
  uint32_t bits = 0;
  if (!hex_u32(bits)) return false;
  static_assert(sizeof(float) == sizeof(uint32_t), "IEEE-754 single expected");
  std::memcpy(&out, &bits, sizeof out);
  return true;
}

bool ColaATokenizer::length_prefixed_string(std::string& out) {
  uint32_t length = 0;
  if (!hex_u32(length, 0xFFFF)) return false;
  if (length > remaining_chars())
    return fail("string length " + std::to_string(length) + " exceeds the telegram");
  out.assign(text_.substr(pos_, length));
  pos_ += length;
  if (pos_ < text_.size()) {
    if (text_[pos_] != ' ')
      return fail("string of length " + std::to_string(length) + " is not followed by a space");
    ++pos_;
  }
  ++tokens_read_;
  return true;
}

}  // namespace refloc
