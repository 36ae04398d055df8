#include "web_console/origin_rule.hpp"

#include <algorithm>
#include <cctype>

namespace refloc {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

/// "http://a:1/" and "http://a:1" name one origin.
std::string without_trailing_slash(std::string s) {
  while (!s.empty() && s.back() == '/') s.pop_back();
  return s;
}

}  // namespace

OriginVerdict judge_origin(const std::string& origin, const std::string& host,
                           const std::vector<std::string>& allowed_origins) {
  if (origin.empty()) return OriginVerdict::kAccepted;
  const std::string o = without_trailing_slash(lower(origin));
  const std::string h = lower(host);
  if (!h.empty() && (o == "http://" + h || o == "https://" + h)) return OriginVerdict::kAccepted;
  for (const std::string& allowed : allowed_origins) {
    if (o == without_trailing_slash(lower(allowed))) return OriginVerdict::kAccepted;
  }
  return OriginVerdict::kRefused;
}

}  // namespace refloc
