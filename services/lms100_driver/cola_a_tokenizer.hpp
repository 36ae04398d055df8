#pragma once
// Reads the space-separated tokens of one CoLa-A payload (docs/lms100-protocol.md §2.1-2.3):
// upper-case hex numbers without leading zeros, two's-complement negatives,
// IEEE-754 floats as 8 hex digits, and strings as "<hex length> <chars>" whose
// characters may contain spaces. Every reader checks bounds and digits and
// reports failure with the name of the field; it never reads past the payload.

#include <cstdint>
#include <string>
#include <string_view>

namespace refloc {

class ColaATokenizer {
 public:
  explicit ColaATokenizer(std::string_view payload) : text_(payload) {}

  /// Next raw token (up to the next space); false at the end of the payload or on an empty token.
  bool token(std::string_view& out);
  /// Unsigned hex number that fits in max_value.
  bool hex_u32(uint32_t& out, uint32_t max_value = 0xFFFFFFFFu);
  /// 32-bit two's-complement hex number (FFF92230 = -450000).
  bool hex_i32(int32_t& out);
  /// IEEE-754 single written as hex bits (3F800000 = 1.0).
  bool hex_float(float& out);
  /// "<hex length> <chars>": the characters may contain spaces.
  bool length_prefixed_string(std::string& out);
  /// True when every character has been consumed.
  bool at_end() const { return pos_ >= text_.size(); }
  /// Number of tokens consumed so far (for error messages).
  size_t tokens_read() const { return tokens_read_; }
  /// Characters not yet consumed.
  size_t remaining_chars() const { return pos_ >= text_.size() ? 0 : text_.size() - pos_; }
  /// Why the last reader failed.
  const std::string& error() const { return error_; }

  /// Parses a whole token as unsigned hex; false on an empty token, a non-hex digit or overflow.
  static bool parse_hex(std::string_view token, uint32_t& out);

 private:
  bool fail(std::string message);

  std::string_view text_;
  size_t pos_ = 0;
  size_t tokens_read_ = 0;
  std::string error_;
};

}  // namespace refloc
