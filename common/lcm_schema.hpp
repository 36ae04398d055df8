#pragma once
// The wire layout of an LCM type as a table, and a bounds check that walks a datagram by it
// before lcm-gen's decoder sees it. lcm-gen 1.3.1's C++ decode resize()s every variable array
// to the length the datagram declares before it checks the bytes are there, so one datagram
// declaring -1 or 2^31-1 elements ends a service in std::bad_alloc. The tables are generated
// from lcmtypes/*.lcm by lcmtypes/lcm_schema_gen.py, with the per-array maxima written next to
// each array in the .lcm file ("// max N"). No LCM here: the walk only reads bytes.

#include <cstddef>
#include <cstdint>
#include <string>

namespace refloc {

enum class LcmFieldKind : uint8_t {
  kInt8,
  kByte,
  kBoolean,
  kInt16,
  kInt32,
  kInt64,
  kFloat,
  kDouble,
  kString,
  kStruct
};

struct LcmSchema;

/// One member of an LCM struct, in wire order.
struct LcmFieldSchema {
  const char* name;
  LcmFieldKind kind;
  const LcmSchema* nested;   ///< kStruct: the element type's table; otherwise nullptr
  int32_t fixed_count;       ///< 1 for a scalar, N for a fixed array [N], 0 for a variable array
  int32_t length_field;      ///< variable array: index of the integer member holding its length; else -1
  int64_t max_count;         ///< variable array: the most elements accepted; else fixed_count
  int64_t max_string_chars;  ///< kString: the most characters of one string, the NUL excluded
};

/// One LCM struct: its fingerprint (what getHash() returns, nested types included) and fields.
struct LcmSchema {
  const char* type_name;
  uint64_t fingerprint;
  const LcmFieldSchema* fields;
  size_t field_count;
  int64_t min_encoded_bytes;  ///< without fingerprint, every variable array empty, strings ""
};

/// The generated table of an lcm-gen type (refloc_lcm_schemas.hpp declares one per type).
template <class Message>
const LcmSchema& lcm_schema_of();

/// Why a datagram (fingerprint first, as LCM publishes it) cannot be a message of this schema
/// within its limits: a declared length < 0, over the maximum or needing more bytes than are
/// left, a string length < 1, over its maximum, without its final NUL or with one inside, a truncation, a
/// wrong fingerprint or bytes after the end. Empty when the datagram is exactly one valid message. Allocates
/// only for the reason; reads at most size bytes.
std::string check_lcm_datagram(const LcmSchema& schema, const uint8_t* data, size_t size);

/// kPlausibleOnly (NaN, inf and |v| > kMaxPlausibleLcmMagnitude refused as well): what a
/// service consumes (ServiceRuntime::subscribe); kAsSent: what a tool reading a log must show
/// as it was, NaN included.
enum class LcmNumbers { kAsSent, kPlausibleOnly };

/// check_lcm_datagram's verdict, with numbers judged too when asked: one walk of the bytes.
struct LcmDatagramVerdict {
  std::string reason;               ///< empty: one valid (and, if asked, plausible) message
  bool implausible_number = false;  ///< refused for a number, not for its structure
};
LcmDatagramVerdict check_lcm_datagram(const LcmSchema& schema, const uint8_t* data, size_t size,
                                      LcmNumbers numbers);

/// The largest magnitude a float/double of a refloc message may have. Every quantity we send
/// (positions [m], angles, variances [m^2], times [s], RSSI, scores) stays nine orders of
/// magnitude below it; a number beyond it (1e300, FLT_MAX) is an uninitialised or corrupted value.
constexpr double kMaxPlausibleLcmMagnitude = 1e15;

/// The first NaN, infinite or huge (|v| > kMaxPlausibleLcmMagnitude) float/double of a datagram
/// check_lcm_datagram accepted, as "covariance[3] is nan" or "range is 1e+300, beyond +-1e+15"
/// (nested: "reflectors[2].range is inf"); empty when every number is plausible. No refloc
/// message carries such a number on purpose (none is a sentinel), so a service refuses such a
/// message whole before any field of it is used.
std::string find_implausible_lcm_number(const LcmSchema& schema, const uint8_t* data, size_t size);

}  // namespace refloc
