#pragma once
// The outcome of parsing a telegram: success, or one line saying what is wrong
// and where. Parsers never throw and never read past their input.

#include <string>
#include <utility>

namespace refloc {

struct ParseResult {
  std::string error;  ///< empty on success

  static ParseResult success() { return {}; }
  static ParseResult failure(std::string message) { return ParseResult{std::move(message)}; }
  bool ok() const { return error.empty(); }
  explicit operator bool() const { return ok(); }
};

}  // namespace refloc
