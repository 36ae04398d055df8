#include "common/lcm_schema.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

namespace refloc {
namespace {

/// No refloc type has more members; the generator's tables are checked against it on use.
constexpr size_t kMaxFields = 64;

int64_t element_bytes(LcmFieldKind kind) {
  switch (kind) {
    case LcmFieldKind::kInt8:
    case LcmFieldKind::kByte:
    case LcmFieldKind::kBoolean:
      return 1;
    case LcmFieldKind::kInt16:
      return 2;
    case LcmFieldKind::kInt32:
    case LcmFieldKind::kFloat:
      return 4;
    case LcmFieldKind::kInt64:
    case LcmFieldKind::kDouble:
      return 8;
    case LcmFieldKind::kString:
      return 5;  // int32 length + the NUL of an empty string: the least one string takes
    case LcmFieldKind::kStruct:
      return 0;
  }
  return 0;
}

/// LCM integers are big-endian two's complement.
int64_t read_signed(const uint8_t* p, int64_t bytes) {
  uint64_t v = 0;
  for (int64_t i = 0; i < bytes; ++i) v = (v << 8) | p[i];
  const int shift = static_cast<int>(64 - 8 * bytes);
  return static_cast<int64_t>(v << shift) >> shift;
}

/// An LCM float/double (big-endian IEEE-754) as a double. memcpy of the bits: a signalling
/// NaN raises nothing.
double read_real(const uint8_t* p, LcmFieldKind kind) {
  if (kind == LcmFieldKind::kFloat) {
    const auto bits = static_cast<uint32_t>(read_signed(p, 4));
    float f = 0.0F;
    std::memcpy(&f, &bits, sizeof f);
    return f;
  }
  const auto bits = static_cast<uint64_t>(read_signed(p, 8));
  double d = 0.0;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}

class DatagramWalk {
 public:
  /// plausible_only: a NaN, infinite or huge float/double is a lie too (reason "<field> is nan").
  DatagramWalk(const uint8_t* data, size_t size, bool plausible_only)
      : data_(data), size_(static_cast<int64_t>(size)), plausible_only_(plausible_only) {}

  int64_t left() const { return size_ - pos_; }
  int64_t pos() const { return pos_; }
  const uint8_t* here() const { return data_ + pos_; }
  void skip(int64_t bytes) { pos_ += bytes; }

  /// The struct's members from the current position; false with reason set on the first lie.
  bool walk_struct(const LcmSchema& schema, std::string& reason) {
    if (schema.field_count > kMaxFields) {
      reason = fmt::format("{} has {} members, the checker handles {}", schema.type_name, schema.field_count,
                           kMaxFields);
      return false;
    }
    std::array<int64_t, kMaxFields> integer_values{};
    for (size_t i = 0; i < schema.field_count; ++i) {
      const LcmFieldSchema& field = schema.fields[i];
      int64_t count = field.fixed_count;
      if (field.length_field >= 0 && !variable_count(schema, field, integer_values, count, reason))
        return false;
      if (field.kind == LcmFieldKind::kStruct) {
        if (!walk_structs(field, count, reason)) return false;
      } else if (field.kind == LcmFieldKind::kString) {
        if (!walk_strings(field, count, reason)) return false;
      } else {
        const int64_t bytes = element_bytes(field.kind);
        if (count * bytes > left()) {
          reason = field.length_field >= 0 ? fmt::format("{}[] of {} needs {} bytes, {} left", field.name,
                                                         count, count * bytes, left())
                                           : fmt::format("truncated at {}: needs {} bytes, {} left",
                                                         field.name, count * bytes, left());
          return false;
        }
        const bool is_real = field.kind == LcmFieldKind::kFloat || field.kind == LcmFieldKind::kDouble;
        if (field.fixed_count == 1 && !is_real) integer_values[i] = read_signed(here(), bytes);
        if (is_real && plausible_only_ && !all_plausible(field, count, reason)) return false;
        skip(count * bytes);
      }
    }
    return true;
  }

  /// Whether the walk stopped at an implausible number (plausible_only).
  bool found_implausible() const { return found_implausible_; }

 private:
  bool variable_count(const LcmSchema& schema, const LcmFieldSchema& field,
                      const std::array<int64_t, kMaxFields>& integer_values, int64_t& count,
                      std::string& reason) {
    const auto length_index = static_cast<size_t>(field.length_field);
    const char* length_name = length_index < schema.field_count ? schema.fields[length_index].name : "?";
    count = length_index < kMaxFields ? integer_values[length_index] : -1;
    if (count < 0) {
      reason = fmt::format("{} = {} declared, {} bytes left", length_name, count, left());
      return false;
    }
    if (count > field.max_count) {
      reason =
          fmt::format("{} = {} declared, max {} ({}[])", length_name, count, field.max_count, field.name);
      return false;
    }
    const int64_t least =
        field.kind == LcmFieldKind::kStruct ? field.nested->min_encoded_bytes : element_bytes(field.kind);
    if (count * least > left()) {
      reason = fmt::format("{} = {} declared, {}[] needs at least {} bytes, {} left", length_name, count,
                           field.name, count * least, left());
      return false;
    }
    return true;
  }

  bool all_plausible(const LcmFieldSchema& field, int64_t count, std::string& reason) {
    const int64_t bytes = element_bytes(field.kind);
    for (int64_t k = 0; k < count; ++k) {
      const double value = read_real(here() + k * bytes, field.kind);
      if (std::fabs(value) <= kMaxPlausibleLcmMagnitude) continue;  // NaN fails too
      const bool scalar = field.fixed_count == 1 && field.length_field < 0;
      const std::string what = std::isfinite(value)
                                   ? fmt::format("{:g}, beyond +-{:g}", value, kMaxPlausibleLcmMagnitude)
                                   : fmt::format("{}", value);
      reason = scalar ? fmt::format("{} is {}", field.name, what)
                      : fmt::format("{}[{}] is {}", field.name, k, what);
      found_implausible_ = true;
      return false;
    }
    return true;
  }

  bool walk_strings(const LcmFieldSchema& field, int64_t count, std::string& reason) {
    for (int64_t k = 0; k < count; ++k) {
      const std::string name =
          field.length_field >= 0 ? fmt::format("{}[{}]", field.name, k) : std::string(field.name);
      if (left() < 4) {
        reason = fmt::format("truncated at {}: needs 4 bytes for its length, {} left", name, left());
        return false;
      }
      const int64_t declared = read_signed(here(), 4);  // characters + the NUL
      skip(4);
      if (declared < 1) {
        reason = fmt::format("{}: string length {} declared (at least 1, the NUL)", name, declared);
        return false;
      }
      if (declared - 1 > field.max_string_chars) {
        reason = fmt::format("{}: string of {} characters declared, max {}", name, declared - 1,
                             field.max_string_chars);
        return false;
      }
      if (declared > left()) {
        reason = fmt::format("{}: string of {} bytes declared, {} bytes left", name, declared, left());
        return false;
      }
      if (here()[declared - 1] != 0) {
        reason = fmt::format("{}: string does not end in a NUL", name);
        return false;
      }
      // LCM strings are C strings: lcm-gen encodes with strlen(), so a NUL inside would
      // decode to one string and be republished as a shorter one.
      if (std::memchr(here(), 0, static_cast<size_t>(declared - 1)) != nullptr) {
        reason = fmt::format("{}: string has a NUL before its end", name);
        return false;
      }
      skip(declared);
    }
    return true;
  }

  bool walk_structs(const LcmFieldSchema& field, int64_t count, std::string& reason) {
    for (int64_t k = 0; k < count; ++k) {
      if (!walk_struct(*field.nested, reason)) {
        reason = (field.fixed_count == 1 ? fmt::format("{}.", field.name)
                                         : fmt::format("{}[{}].", field.name, k)) +
                 reason;
        return false;
      }
    }
    return true;
  }

  const uint8_t* data_;
  int64_t size_;
  bool plausible_only_;
  bool found_implausible_ = false;
  int64_t pos_ = 0;
};

}  // namespace

std::string find_implausible_lcm_number(const LcmSchema& schema, const uint8_t* data, size_t size) {
  LcmDatagramVerdict verdict = check_lcm_datagram(schema, data, size, LcmNumbers::kPlausibleOnly);
  // A structural lie is check_lcm_datagram's to report; only a number's is returned here.
  return verdict.implausible_number ? std::move(verdict.reason) : std::string();
}

std::string check_lcm_datagram(const LcmSchema& schema, const uint8_t* data, size_t size) {
  return check_lcm_datagram(schema, data, size, LcmNumbers::kAsSent).reason;
}

LcmDatagramVerdict check_lcm_datagram(const LcmSchema& schema, const uint8_t* data, size_t size,
                                      LcmNumbers numbers) {
  constexpr size_t kFingerprintBytes = 8;
  LcmDatagramVerdict verdict;
  if (size < kFingerprintBytes) {
    verdict.reason =
        fmt::format("{} bytes, shorter than the 8-byte fingerprint of {}", size, schema.type_name);
    return verdict;
  }
  if (size > static_cast<size_t>(INT32_MAX)) {
    verdict.reason = fmt::format("{} bytes, more than LCM can carry", size);
    return verdict;
  }
  const auto fingerprint = static_cast<uint64_t>(read_signed(data, 8));
  if (fingerprint != schema.fingerprint) {
    verdict.reason = fmt::format("fingerprint {:016x} is not {}'s {:016x}", fingerprint, schema.type_name,
                                 schema.fingerprint);
    return verdict;
  }
  DatagramWalk walk(data + kFingerprintBytes, size - kFingerprintBytes,
                    numbers == LcmNumbers::kPlausibleOnly);
  if (!walk.walk_struct(schema, verdict.reason)) {
    verdict.implausible_number = walk.found_implausible();
    return verdict;
  }
  if (walk.left() != 0)
    verdict.reason = fmt::format("{} bytes after the end of the {}", walk.left(), schema.type_name);
  return verdict;
}

}  // namespace refloc
