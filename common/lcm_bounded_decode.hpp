#pragma once
// Decoding LCM bytes from the bus or a log so that no datagram can crash or stall the reader:
// the bytes are walked by the type's generated schema first (declared lengths against the
// datagram and the limits in lcmtypes/*.lcm, see common/lcm_schema.hpp), and only then handed
// to lcm-gen's decoder, inside a try/catch. Every service (ServiceRuntime::subscribe) and
// every tool that decodes raw bytes goes through decode_lcm_bounded.

#include "common/lcm_schema.hpp"

#include <refloc_lcm_schemas.hpp>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <utility>

namespace refloc {

/// The outcome of one bounded decode; reason says why the bytes were refused.
struct LcmDecodeResult {
  bool ok = false;
  bool implausible_number = false;  ///< well-formed, refused for a number (LcmNumbers::kPlausibleOnly)
  std::string reason;
};

/// Check (numbers too with LcmNumbers::kPlausibleOnly, see check_lcm_datagram), then decode
/// data into message. Never throws and never lets a declared length allocate more than the
/// type's limits allow; message is unspecified when !ok.
template <class Message>
LcmDecodeResult decode_lcm_bounded(const void* data, size_t size, Message& message,
                                   LcmNumbers numbers = LcmNumbers::kAsSent) {
  LcmDecodeResult result;
  const auto* bytes = static_cast<const uint8_t*>(data);
  LcmDatagramVerdict verdict = check_lcm_datagram(lcm_schema_of<Message>(), bytes, size, numbers);
  if (!verdict.reason.empty()) {
    result.reason = std::move(verdict.reason);
    result.implausible_number = verdict.implausible_number;
    return result;
  }
  try {
    if (message.decode(data, 0, static_cast<int>(size)) < 0) {
      result.reason = "lcm-gen's decoder refused what the bounds check accepted";
      return result;
    }
  } catch (const std::exception& e) {
    result.reason = std::string("lcm-gen's decoder threw: ") + e.what();
    return result;
  }
  result.ok = true;
  return result;
}

/// Which decode errors of one subscription get a log line, so a hostile 50 Hz stream of lies
/// writes one line per kIntervalUs, not one per message: the first error is logged, later
/// ones at most once per interval, each line saying how many went unlogged since.
class DecodeErrorLogLimiter {
 public:
  static constexpr int64_t kIntervalUs = 5'000'000;

  /// Count one error at now_us (monotonic). Returns the errors the line to write now stands
  /// for (this one and the unlogged ones before it), or 0 when no line is due.
  int64_t on_error(int64_t now_us);

 private:
  bool logged_any_ = false;
  int64_t last_logged_us_ = 0;
  int64_t unlogged_ = 0;
};

}  // namespace refloc
