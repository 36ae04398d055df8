#pragma once
// The LCM URL every refloc program opens, decided in one place: which URL
// (--lcm-url, else $LCM_DEFAULT_URL, else the default), whether it is valid
// (LCM 1.3.1 accepts ?ttl=-1 as ttl 255, ignores unknown options and bad
// numbers with a warning), the UDP receive buffer it asks the kernel for, and
// whether the kernel will grant that buffer (it silently caps SO_RCVBUF at
// net.core.rmem_max). No LCM in here: the runtime and the tools open the URL.

#include <cstdint>
#include <optional>
#include <string>

namespace refloc {

/// UDP receive buffer every udpm URL asks for [bytes]. udpm delivers every message of the
/// multicast group to every subscribing process, so one socket must hold the whole bus for
/// a stall: measured on the demo stack (50 Hz scans of 4.4 kB, about 620 small messages/s)
/// the kernel charges about 1.0 MB/s (skb truesize: 8448 B a scan, 832-1280 B a small
/// message), 1.4 MB/s with 9 kB scans. 2 MiB holds that bus for 1.5 s even before Linux
/// doubles the value for its bookkeeping (sk_rcvbuf = 2 x min(request, rmem_max)).
inline constexpr int64_t kLcmRecvBufSizeBytes = 2097152;

/// The bus when nothing else is said: ttl=0 keeps every datagram on this host.
inline constexpr const char* kLcmDefaultUrl = "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=2097152";

/// A validated LCM URL.
struct LcmUrl {
  std::string url;                ///< what to open: the input, with recv_buf_size added to udpm when missing
  std::string origin;             ///< where it came from: "--lcm-url", "$LCM_DEFAULT_URL" or "default"
  std::string provider;           ///< "udpm", "memq", "file" or "tcpq"
  std::string multicast_address;  ///< udpm only, dotted quad
  int port = 0;                   ///< udpm and tcpq
  int ttl = 0;                    ///< udpm only
  int64_t recv_buf_size_bytes = 0;   ///< what udpm asks the kernel for; 0 for other providers
  bool recv_buf_size_added = false;  ///< the URL had none and got kLcmRecvBufSizeBytes
};

/// Validate url and add recv_buf_size to a udpm URL without one. Throws ConfigError with
/// one line naming the URL, its origin and what is wrong: an unknown provider, a udpm
/// address that is not IPv4 multicast, a port outside 1..65535, ttl outside 0..255,
/// recv_buf_size <= 0 or above 2^31-1, an option that is not key=value, unknown or repeated.
LcmUrl parse_lcm_url(const std::string& url, const std::string& origin);

/// The URL a program opens: explicit_url if not empty, else env_url ($LCM_DEFAULT_URL) if
/// not null or empty, else kLcmDefaultUrl; validated by parse_lcm_url.
LcmUrl resolve_lcm_url(const std::string& explicit_url, const char* env_url);

/// What the kernel makes of a receive buffer request.
struct ReceiveBufferCheck {
  int64_t requested_bytes = 0;
  int64_t rmem_max_bytes = -1;  ///< net.core.rmem_max; < 0 when it could not be read
  int64_t granted_bytes = 0;    ///< what SO_RCVBUF becomes before the kernel doubles it
  bool clamped = false;         ///< granted_bytes < requested_bytes
  std::string warning;          ///< one line naming the sysctl and the value to set; empty unless clamped
};

/// Compare a receive buffer request with net.core.rmem_max (unknown: nothing is claimed).
ReceiveBufferCheck check_receive_buffer(int64_t requested_bytes, int64_t rmem_max_bytes);

/// net.core.rmem_max [bytes] from path; nullopt when it cannot be read or parsed. The
/// value is global: a network namespace (our tests) reads the host's and cannot change it.
std::optional<int64_t> read_rmem_max(const std::string& path = "/proc/sys/net/core/rmem_max");

}  // namespace refloc
