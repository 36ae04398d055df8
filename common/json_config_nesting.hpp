#pragma once
// Helpers of json_config.cpp kept apart: a DOM builder that bounds nesting while parsing,
// and the escaping that keeps every message one printable line.

#include "common/json_config.hpp"

#include <fmt/format.h>

#include <string>
#include <vector>

namespace refloc::json_config_detail {

// Messages are one line whatever a key or file name holds: control characters are escaped
// and very long keys cut, so a hostile file cannot forge or flood the log.
inline std::string printable(const std::string& text, size_t max_chars = 160) {
  std::string out;
  for (const char ch : text) {
    if (out.size() >= max_chars) return out + "...";
    const auto c = static_cast<unsigned char>(ch);
    out += c < 0x20 || c == 0x7f ? fmt::format("\\x{:02x}", c) : std::string(1, ch);
  }
  return out;
}

/// RFC 6901 escaping, so messages name valid pointers.
inline std::string escape_key(std::string key) {
  for (size_t pos = 0; (pos = key.find('~', pos)) != std::string::npos; pos += 2) key.replace(pos, 1, "~0");
  for (size_t pos = 0; (pos = key.find('/', pos)) != std::string::npos; pos += 2) key.replace(pos, 1, "~1");
  return key;
}

// Builds the DOM through nlohmann's own SAX DOM builder (one pass) while bounding the
// nesting: nlohmann's parser is iterative, but everything that walks a DOM afterwards (dump,
// comparisons, our own code) may recurse, so a 100,000-deep file must never become a DOM.
// Parsing stops at the first container past kMaxConfigNestingDepth, naming its pointer.
class NestingLimitedDom {
 public:
  using json = nlohmann::json;
  explicit NestingLimitedDom(json& result) : dom_(result, /*allow_exceptions=*/false) {}

  bool null() { return value() && dom_.null(); }
  bool boolean(bool v) { return value() && dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) { return value() && dom_.number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) { return value() && dom_.number_unsigned(v); }
  bool number_float(json::number_float_t v, const json::string_t& s) {
    return value() && dom_.number_float(v, s);
  }
  bool string(json::string_t& v) { return value() && dom_.string(v); }
  bool binary(json::binary_t& v) { return value() && dom_.binary(v); }
  bool start_object(std::size_t n) { return open(false) && dom_.start_object(n); }
  bool start_array(std::size_t n) { return open(true) && dom_.start_array(n); }
  bool end_object() { return close() && dom_.end_object(); }
  bool end_array() { return close() && dom_.end_array(); }
  bool key(json::string_t& k) {
    frames_.back().key = k;
    return dom_.key(k);
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::json::exception& e) {
    error_ = fmt::format("not valid JSON: {}", printable(e.what(), 200));
    return false;
  }
  /// Empty when the text parsed; else "not valid JSON: ..." or "<pointer>: nested deeper ...".
  const std::string& error() const { return error_; }

 private:
  struct Frame {
    bool array = false;
    size_t elements = 0;  // of an array, counted to name the index in a message
    std::string key;      // of an object, the key being parsed
  };
  bool value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().elements;
    return true;
  }
  bool open(bool array) {
    value();
    if (frames_.size() >= static_cast<size_t>(kMaxConfigNestingDepth)) {
      std::string pointer;
      for (const Frame& f : frames_)
        pointer += "/" + (f.array ? std::to_string(f.elements - 1) : escape_key(f.key));
      error_ = fmt::format("{}: nested deeper than {} levels (objects and arrays)", printable(pointer),
                           kMaxConfigNestingDepth);
      return false;
    }
    frames_.push_back(Frame{array, 0, {}});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return true;
  }
  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::vector<Frame> frames_;
  std::string error_;
};

}  // namespace refloc::json_config_detail
