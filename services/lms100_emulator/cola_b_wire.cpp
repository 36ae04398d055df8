#include "lms100_emulator/cola_b_wire.hpp"

#include "lms100_emulator/cola_a_text.hpp"

#include <cstring>
#include <vector>

namespace refloc {
namespace {

// Argument codes: b byte, w uint16, d uint32, i int32 (decimal text), s uint16 length + chars.
struct Command {
  const char* head;  ///< "sMN SetAccessMode"; "sWA" matches any name of that type
  const char* args;
};

constexpr Command kRequests[] = {
    {"sMN SetAccessMode", "bd"}, {"sMN mLMPsetscancfg", "dwdii"}, {"sWN LMDscandatacfg", "bbbbbbbbbbbw"},
    {"sEN LMDscandata", "b"},    {"sWN LMPoutputRange", "wdii"},
};

constexpr Command kReplies[] = {
    {"sAN SetAccessMode", "b"},  {"sEA LMDscandata", "b"},
    {"sRA LMPscancfg", "dwdii"}, {"sAN mLMPsetscancfg", "bdwdii"},
    {"sAN LMCstartmeas", "b"},   {"sAN LMCstopmeas", "b"},
    {"sAN LMCstandby", "b"},     {"sAN Run", "b"},
    {"sAN mEEwriteall", "b"},    {"sRA STlms", "wbsswww"},
    {"sRA SCdevicestate", "b"},  {"sRA FirmwareVersion", "s"},
    {"sRA LocationName", "s"},   {"sRA LMPoutputRange", "wdii"},
};

const char* find_args(const Command* table, size_t n, std::string_view head) {
  for (size_t i = 0; i < n; ++i) {
    if (head == table[i].head) return table[i].args;
  }
  return nullptr;
}

size_t width(char code) { return code == 'b' ? 1 : code == 'w' ? 2 : 4; }

uint32_t get(std::string_view in, size_t at, size_t bytes) {
  uint32_t v = 0;
  for (size_t i = 0; i < bytes; ++i) v = (v << 8) | static_cast<uint8_t>(in[at + i]);
  return v;
}

}  // namespace

void put_big_endian(std::string& out, uint32_t value, size_t bytes) {
  for (size_t i = bytes; i-- > 0;) out.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
}

void ColaBRequestReader::feed(const uint8_t* data, size_t size) {
  received_.erase(0, read_pos_);
  read_pos_ = 0;
  received_.append(reinterpret_cast<const char*>(data), size);
}

bool ColaBRequestReader::next(std::string& payload) {
  for (;;) {
    const size_t magic = received_.find(cola::kColaBMagic, read_pos_);
    if (magic == std::string::npos) {
      read_pos_ = received_.size() >= 3 ? received_.size() - 3 : 0;  // a magic may straddle reads
      return false;
    }
    read_pos_ = magic;
    if (received_.size() - magic < cola::kColaBHeaderBytes) return false;
    const uint32_t length = get(received_, magic + 4, 4);
    if (length > max_request_bytes_) {
      ++read_pos_;
      continue;
    }
    if (received_.size() - magic < length + cola::kColaBOverheadBytes) return false;
    uint8_t x = 0;
    for (size_t i = 0; i < length; ++i) x ^= static_cast<uint8_t>(received_[magic + 8 + i]);
    if (x != static_cast<uint8_t>(received_[magic + 8 + length])) {
      ++read_pos_;
      continue;
    }
    payload.assign(received_, magic + 8, length);
    read_pos_ = magic + length + cola::kColaBOverheadBytes;
    return true;
  }
}

void frame_cola_b_telegram(std::string_view payload, std::string& out) {
  out.append(cola::kColaBMagic);
  put_big_endian(out, static_cast<uint32_t>(payload.size()), 4);
  out.append(payload);
  uint8_t x = 0;
  for (const char c : payload) x ^= static_cast<uint8_t>(c);
  out.push_back(static_cast<char>(x));
}

bool cola_b_request_to_text(std::string_view payload, std::string& text) {
  const size_t name_end = payload.find(' ', 4);
  const std::string_view head = payload.substr(0, name_end);
  text.assign(head);
  const char* args = find_args(kRequests, std::size(kRequests), head);
  if (args == nullptr) return name_end == std::string_view::npos || name_end + 1 == payload.size();
  size_t at = name_end + 1;
  if (name_end == std::string_view::npos) return std::strlen(args) == 0;
  for (const char* a = args; *a != '\0'; ++a) {
    if (at + width(*a) > payload.size()) return false;
    const uint32_t v = get(payload, at, width(*a));
    at += width(*a);
    text += ' ';
    if (*a == 'i') {
      const auto s = static_cast<int32_t>(v);
      text += (s < 0 ? "-" : "+") + std::to_string(s < 0 ? -static_cast<int64_t>(s) : s);
    } else {
      append_cola_hex(text, v);
    }
  }
  return at == payload.size();
}

void cola_b_reply_from_text(std::string_view text, std::string& payload) {
  std::vector<std::string_view> t;
  split_cola_tokens(text, t);
  payload.clear();
  if (!t.empty() && t[0] == "sFA") {  // "sFA" and a uint16 code, no space (recorded LMS511)
    int64_t code = 0;
    if (t.size() > 1) parse_cola_request_number(t[1], code);
    payload = "sFA";
    put_big_endian(payload, static_cast<uint32_t>(code), 2);
    return;
  }
  if (t.size() < 2) return;
  const std::string head = std::string(t[0]) + ' ' + std::string(t[1]);
  payload = head + ' ';
  const char* args = find_args(kReplies, std::size(kReplies), head);
  if (args == nullptr) return;
  size_t k = 2;
  for (const char* a = args; *a != '\0' && k < t.size(); ++a) {
    int64_t v = 0;
    if (*a == 's') {  // "<hex length> <chars>": the chars are one token in every reply we translate
      parse_cola_request_number(t[k++], v);
      const std::string_view chars = k < t.size() ? t[k++] : std::string_view{};
      put_big_endian(payload, static_cast<uint32_t>(chars.size()), 2);
      payload.append(chars);
      continue;
    }
    parse_cola_request_number(t[k++], v);
    put_big_endian(payload, static_cast<uint32_t>(v), width(*a));
  }
}

}  // namespace refloc
