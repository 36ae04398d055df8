#include "lms100_emulator/cola_a_text.hpp"

#include <cstring>

namespace refloc {

namespace {
constexpr char kHexDigits[] = "0123456789ABCDEF";

int hex_digit_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}
}  // namespace

void append_cola_hex(std::string& out, uint32_t value) {
  char buffer[8];
  int n = 0;
  do {
    buffer[n++] = kHexDigits[value & 0xFu];
    value >>= 4;
  } while (value != 0);
  while (n > 0) out.push_back(buffer[--n]);
}

void append_cola_hex_i32(std::string& out, int32_t value) {
  append_cola_hex(out, static_cast<uint32_t>(value));
}

void append_cola_hex_float(std::string& out, float value) {
  uint32_t bits = 0;
  static_assert(sizeof(bits) == sizeof(value));
  std::memcpy(&bits, &value, sizeof(bits));
  for (int shift = 28; shift >= 0; shift -= 4) out.push_back(kHexDigits[(bits >> shift) & 0xFu]);
}

void append_cola_string(std::string& out, std::string_view text) {
  append_cola_hex(out, static_cast<uint32_t>(text.size()));
  out.push_back(' ');
  out.append(text.data(), text.size());
}

void split_cola_tokens(std::string_view payload, std::vector<std::string_view>& tokens) {
  tokens.clear();
  if (payload.empty()) return;
  size_t start = 0;
  while (true) {
    const size_t space = payload.find(' ', start);
    if (space == std::string_view::npos) {
      tokens.push_back(payload.substr(start));
      return;
    }
    tokens.push_back(payload.substr(start, space - start));
    start = space + 1;
  }
}

bool parse_cola_request_number(std::string_view token, int64_t& out) {
  if (token.empty()) return false;
  if (token[0] == '+' || token[0] == '-') {
    const bool negative = token[0] == '-';
    if (token.size() < 2 || token.size() > 11) return false;
    int64_t magnitude = 0;
    for (size_t i = 1; i < token.size(); ++i) {
      if (token[i] < '0' || token[i] > '9') return false;
      magnitude = magnitude * 10 + (token[i] - '0');
    }
    out = negative ? -magnitude : magnitude;
    return out >= INT32_MIN && out <= static_cast<int64_t>(UINT32_MAX);
  }
  if (token.size() > 8) return false;
  uint32_t value = 0;
  for (const char c : token) {
    const int digit = hex_digit_value(c);
    if (digit < 0) return false;
    value = (value << 4) | static_cast<uint32_t>(digit);
  }
  out = static_cast<int32_t>(value);
  return true;
}

bool is_printable_cola_text(std::string_view payload) {
  for (const char c : payload) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte > 0x7E) return false;
  }
  return true;
}

}  // namespace refloc
