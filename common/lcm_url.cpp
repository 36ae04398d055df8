#include "common/lcm_url.hpp"

#include "common/json_config.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <set>
#include <vector>

namespace refloc {
namespace {

constexpr const char* kDefaultUdpmNetwork = "239.255.76.67:7667";

[[noreturn]] void refuse(const std::string& url, const std::string& origin, const std::string& why) {
  throw ConfigError(fmt::format("LCM URL '{}' (from {}): {}", url, origin, why));
}

/// A whole decimal number in [min, max]; nullopt for anything else ("", "0x10", "1e3", " 5").
std::optional<int64_t> parse_decimal(const std::string& text, int64_t min, int64_t max) {
  if (text.empty() || text.size() > 19) return std::nullopt;
  size_t i = text[0] == '-' ? 1 : 0;
  if (i == text.size()) return std::nullopt;
  for (size_t k = i; k < text.size(); ++k) {
    if (text[k] < '0' || text[k] > '9') return std::nullopt;
  }
  errno = 0;
  const long long value = std::strtoll(text.c_str(), nullptr, 10);
  if (errno != 0 || value < min || value > max) return std::nullopt;
  return static_cast<int64_t>(value);
}

/// The four numbers of a dotted quad; nullopt unless exactly a.b.c.d with each 0..255.
std::optional<std::vector<int64_t>> parse_ipv4(const std::string& text) {
  std::vector<int64_t> parts;
  size_t start = 0;
  while (true) {
    const size_t dot = text.find('.', start);
    const auto part = parse_decimal(text.substr(start, dot - start), 0, 255);
    if (!part || text[start] == '-') return std::nullopt;
    parts.push_back(*part);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  if (parts.size() != 4) return std::nullopt;
  return parts;
}

struct Option {
  std::string key;
  std::string value;
};

std::vector<Option> split_options(const std::string& query, const std::string& url,
                                  const std::string& origin) {
  std::vector<Option> options;
  std::set<std::string> seen;
  if (query.empty()) return options;
  size_t start = 0;
  while (true) {
    const size_t amp = query.find('&', start);
    const std::string pair = query.substr(start, amp - start);
    const size_t eq = pair.find('=');
    if (eq == std::string::npos || eq == 0)
      refuse(url, origin, fmt::format("option '{}' is not key=value", pair));
    Option option{pair.substr(0, eq), pair.substr(eq + 1)};
    if (!seen.insert(option.key).second)
      refuse(url, origin, fmt::format("option '{}' given twice", option.key));
    options.push_back(std::move(option));
    if (amp == std::string::npos) break;
    start = amp + 1;
  }
  return options;
}

void parse_udpm(LcmUrl& out, const std::string& network, const std::vector<Option>& options) {
  const std::string where = network.empty() ? kDefaultUdpmNetwork : network;
  const size_t colon = where.find(':');
  const std::string address = where.substr(0, colon);
  const auto quad = parse_ipv4(address);
  if (!quad || (*quad)[0] < 224 || (*quad)[0] > 239)
    refuse(out.url, out.origin,
           fmt::format("'{}' is not an IPv4 multicast address (224.0.0.0-239.255.255.255)", address));
  out.multicast_address = address;
  out.port = 7667;
  if (colon != std::string::npos) {
    const auto port = parse_decimal(where.substr(colon + 1), 1, 65535);
    if (!port)
      refuse(out.url, out.origin,
             fmt::format("port '{}' is not a number in 1..65535", where.substr(colon + 1)));
    out.port = static_cast<int>(*port);
  }
  for (const auto& [key, value] : options) {
    if (key == "ttl") {
      const auto ttl = parse_decimal(value, 0, 255);
      if (!ttl)
        refuse(out.url, out.origin, fmt::format("ttl must be a whole number in 0..255, got '{}'", value));
      out.ttl = static_cast<int>(*ttl);
    } else if (key == "recv_buf_size") {
      // LCM stores it in an int; 0 would mean "kernel default", which is what we refuse to get silently.
      const auto size = parse_decimal(value, 1, std::numeric_limits<int32_t>::max());
      if (!size)
        refuse(
            out.url, out.origin,
            fmt::format("recv_buf_size must be a whole number of bytes in 1..2147483647, got '{}'", value));
      out.recv_buf_size_bytes = *size;
    } else {
      refuse(out.url, out.origin, fmt::format("unknown udpm option '{}' (known: ttl, recv_buf_size)", key));
    }
  }
  if (out.recv_buf_size_bytes == 0) {
    out.recv_buf_size_bytes = kLcmRecvBufSizeBytes;
    out.recv_buf_size_added = true;
    out.url += fmt::format("{}recv_buf_size={}", options.empty() ? "?" : "&", kLcmRecvBufSizeBytes);
  }
}

void check_known_options(const LcmUrl& out, const std::vector<Option>& options,
                         const std::set<std::string>& known) {
  for (const auto& option : options) {
    if (known.count(option.key) == 0)
      refuse(out.url, out.origin, fmt::format("unknown {} option '{}'", out.provider, option.key));
  }
}

}  // namespace

LcmUrl parse_lcm_url(const std::string& url, const std::string& origin) {
  LcmUrl out;
  out.url = url;
  out.origin = origin;
  const size_t scheme_end = url.find("://");
  if (scheme_end == std::string::npos || scheme_end == 0)
    refuse(url, origin, "expected provider://network?options, e.g. " + std::string(kLcmDefaultUrl));
  out.provider = url.substr(0, scheme_end);
  const std::string rest = url.substr(scheme_end + 3);
  const size_t question = rest.find('?');
  const std::string network = rest.substr(0, question);
  const std::string query = question == std::string::npos ? "" : rest.substr(question + 1);
  if (question != std::string::npos && query.empty()) refuse(url, origin, "empty option list after '?'");
  const std::vector<Option> options = split_options(query, url, origin);
  if (out.provider == "udpm") {
    parse_udpm(out, network, options);
  } else if (out.provider == "memq") {
    check_known_options(out, options, {});
  } else if (out.provider == "file") {
    if (network.empty()) refuse(url, origin, "file:// needs a path");
    check_known_options(out, options, {"speed", "mode", "start_timestamp"});
  } else if (out.provider == "tcpq") {
    check_known_options(out, options, {});
  } else {
    refuse(url, origin, fmt::format("unknown provider '{}' (known: udpm, memq, file, tcpq)", out.provider));
  }
  return out;
}

LcmUrl resolve_lcm_url(const std::string& explicit_url, const char* env_url) {
  if (!explicit_url.empty()) return parse_lcm_url(explicit_url, "--lcm-url");
  if (env_url != nullptr && *env_url != '\0') return parse_lcm_url(env_url, "$LCM_DEFAULT_URL");
  return parse_lcm_url(kLcmDefaultUrl, "default");
}

ReceiveBufferCheck check_receive_buffer(int64_t requested_bytes, int64_t rmem_max_bytes) {
  ReceiveBufferCheck check;
  check.requested_bytes = requested_bytes;
  check.rmem_max_bytes = rmem_max_bytes;
  check.granted_bytes = requested_bytes;
  if (rmem_max_bytes < 0 || requested_bytes <= rmem_max_bytes) return check;
  check.granted_bytes = rmem_max_bytes;
  check.clamped = true;
  check.warning = fmt::format(
      "the kernel caps the LCM receive buffer at net.core.rmem_max = {} bytes, below the {} the URL asks "
      "for: a stall of this process will lose messages; run `sysctl -w net.core.rmem_max={}` as root "
      "and keep it in /etc/sysctl.d/ (deploy/install-deps.sh writes 60-refloc.conf for the default URL)",
      rmem_max_bytes, requested_bytes, requested_bytes);
  return check;
}

std::optional<int64_t> read_rmem_max(const std::string& path) {
  std::ifstream in(path);
  std::string text;
  if (!in || !(in >> text)) return std::nullopt;
  return parse_decimal(text, 0, std::numeric_limits<int64_t>::max() / 4);
}

}  // namespace refloc
