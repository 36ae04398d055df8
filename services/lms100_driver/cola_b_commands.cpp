#include "lms100_driver/cola_b_commands.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cstdint>
#include <vector>

#include "common/cola_a_framing.hpp"

namespace refloc {
namespace {

/// Width of one argument on the wire; kSigned32 is printed in two's complement.
enum class Arg { kU8, kU16, kU32, kSigned32 };

struct Layout {
  std::string_view type;
  std::string_view name;  ///< "" = any name of this type
  std::vector<Arg> args;
};

size_t width(Arg a) { return a == Arg::kU8 ? 1 : a == Arg::kU16 ? 2 : 4; }

// The requests of docs/lms100-protocol.md §4.1. LMDscandatacfg is 13 bytes as in the recorded
// LMS111/LMS511 sessions: eleven single bytes (the two encoder tokens included) and a uint16 interval.
const std::vector<Layout>& request_layouts() {
  using A = Arg;
  static const std::vector<Layout> layouts = {
      {"sEN", "LMDscandata", {A::kU8}},
      {"sMN", "SetAccessMode", {A::kU8, A::kU32}},
      {"sMN", "mLMPsetscancfg", {A::kU32, A::kU16, A::kU32, A::kSigned32, A::kSigned32}},
      {"sWN",
       "LMDscandatacfg",
       {A::kU8, A::kU8, A::kU8, A::kU8, A::kU8, A::kU8, A::kU8, A::kU8, A::kU8, A::kU8, A::kU8, A::kU16}},
      {"sMN", "LMCstartmeas", {}},
      {"sMN", "LMCstopmeas", {}},
      {"sMN", "Run", {}},
      {"sRN", "", {}},
  };
  return layouts;
}

// The replies the driver checks. Only the leading fields are read; STlms's first field is taken
// as uint16 (unverified on a device: the recorded sessions never read STlms).
const std::vector<Layout>& reply_layouts() {
  using A = Arg;
  static const std::vector<Layout> layouts = {
      {"sEA", "LMDscandata", {A::kU8}},
      {"sAN", "SetAccessMode", {A::kU8}},
      {"sRA", "LMPscancfg", {A::kU32, A::kU16, A::kU32, A::kSigned32, A::kSigned32}},
      {"sAN", "mLMPsetscancfg", {A::kU8, A::kU32, A::kU16, A::kU32, A::kSigned32, A::kSigned32}},
      {"sAN", "LMCstartmeas", {A::kU8}},
      {"sAN", "LMCstopmeas", {A::kU8}},
      {"sAN", "Run", {A::kU8}},
      {"sRA", "STlms", {A::kU16}},
      {"sRA", "SCdevicestate", {A::kU8}},
      {"sWA", "", {}},
      {"sMA", "", {}},
  };
  return layouts;
}

const Layout* find_layout(const std::vector<Layout>& layouts, std::string_view type, std::string_view name) {
  for (const Layout& l : layouts) {
    if (l.type == type && (l.name.empty() || l.name == name)) return &l;
  }
  return nullptr;
}

/// CoLa-A request number: "+5000"/"-450000" decimal, "F4724744"/"03" hex.
bool parse_request_number(std::string_view token, int64_t& value) {
  if (token.empty()) return false;
  const bool signed_decimal = token[0] == '+' || token[0] == '-';
  const std::string_view digits = signed_decimal ? token.substr(1) : token;
  uint64_t magnitude = 0;
  const auto [end, ec] =
      std::from_chars(digits.data(), digits.data() + digits.size(), magnitude, signed_decimal ? 10 : 16);
  if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty() ||
      magnitude > 0xFFFFFFFFull)
    return false;
  value = token[0] == '-' ? -static_cast<int64_t>(magnitude) : static_cast<int64_t>(magnitude);
  return true;
}

bool fits(Arg a, int64_t v) {
  switch (a) {
    case Arg::kU8:
      return v >= 0 && v <= 0xFF;
    case Arg::kU16:
      return v >= 0 && v <= 0xFFFF;
    case Arg::kU32:
      return v >= 0 && v <= 0xFFFFFFFFll;
    case Arg::kSigned32:
      return v >= INT32_MIN && v <= 0xFFFFFFFFll;  // hex tokens carry the two's complement
  }
  return false;
}

void append_big_endian(std::string& out, uint32_t value, size_t bytes) {
  for (size_t i = bytes; i-- > 0;) out.push_back(static_cast<char>((value >> (8 * i)) & 0xFFu));
}

}  // namespace

std::string frame_cola_b(std::string_view payload) {
  std::string frame(cola::kColaBMagic);
  append_big_endian(frame, static_cast<uint32_t>(payload.size()), 4);
  frame.append(payload);
  uint8_t checksum = 0;
  for (const char c : payload) checksum ^= static_cast<uint8_t>(c);
  frame.push_back(static_cast<char>(checksum));
  return frame;
}

ParseResult encode_cola_b_request(std::string_view request, std::string& payload) {
  std::vector<std::string_view> tokens;
  for (size_t pos = 0; pos <= request.size();) {
    const size_t space = std::min(request.find(' ', pos), request.size());
    tokens.push_back(request.substr(pos, space - pos));
    pos = space + 1;
  }
  if (tokens.size() < 2) return ParseResult::failure(fmt::format("CoLa-B request '{}': no name", request));
  const Layout* layout = find_layout(request_layouts(), tokens[0], tokens[1]);
  if (layout == nullptr)
    return ParseResult::failure(fmt::format("CoLa-B request '{}': argument widths unknown", request));
  if (tokens.size() - 2 != layout->args.size()) {
    return ParseResult::failure(fmt::format("CoLa-B request '{}': {} arguments, the layout has {}", request,
                                            tokens.size() - 2, layout->args.size()));
  }
  payload.assign(tokens[0]);
  payload += ' ';
  payload.append(tokens[1]);
  if (!layout->args.empty()) payload += ' ';
  for (size_t i = 0; i < layout->args.size(); ++i) {
    int64_t value = 0;
    if (!parse_request_number(tokens[i + 2], value) || !fits(layout->args[i], value))
      return ParseResult::failure(
          fmt::format("CoLa-B request '{}': argument {} '{}' does not fit", request, i + 1, tokens[i + 2]));
    append_big_endian(payload, static_cast<uint32_t>(value), width(layout->args[i]));
  }
  return ParseResult::success();
}

ParseResult decode_cola_b_reply(std::string_view payload, std::string& text) {
  if (payload.size() < 3) return ParseResult::failure("CoLa-B reply shorter than its command type");
  const std::string_view type = payload.substr(0, 3);
  auto read = [&](size_t at, size_t bytes) {
    uint32_t v = 0;
    for (size_t i = 0; i < bytes; ++i) v = (v << 8) | static_cast<uint8_t>(payload[at + i]);
    return v;
  };
  if (type == "sFA") {  // "sFA" and the code as uint16, no space (recorded LMS511 session)
    if (payload.size() != 5) return ParseResult::failure("CoLa-B sFA: expected a 2-byte error code");
    text = fmt::format("sFA {:X}", read(3, 2));
    return ParseResult::success();
  }
  if (payload.size() < 5 || payload[3] != ' ')
    return ParseResult::failure("CoLa-B reply: no 'type name' head");
  const size_t name_end = std::min(payload.find(' ', 4), payload.size());
  const std::string_view name = payload.substr(4, name_end - 4);
  text = fmt::format("{} {}", type, name);
  const Layout* layout = find_layout(reply_layouts(), type, name);
  if (layout == nullptr) return ParseResult::success();
  size_t at = name_end + 1;
  for (const Arg a : layout->args) {
    if (at + width(a) > payload.size())
      return ParseResult::failure(fmt::format("CoLa-B '{} {}': reply ends before its arguments", type, name));
    fmt::format_to(std::back_inserter(text), " {:X}", read(at, width(a)));
    at += width(a);
  }
  return ParseResult::success();
}

}  // namespace refloc
