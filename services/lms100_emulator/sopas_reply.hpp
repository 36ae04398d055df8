#pragma once
// The SOPAS reply vocabulary the emulated LMS100 answers with: the error codes of
// docs/lms100-protocol.md §2.4 and the argument checks every request handler starts with.
// Shared by the device's command handlers (lms100_device.cpp) and its variables
// (lms100_device_variables.cpp).

#include "lms100_emulator/cola_a_text.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace refloc::sopas {

// SOPAS error codes (docs/lms100-protocol.md §2.4).
constexpr uint32_t kErrAccessDenied = 0x1;
constexpr uint32_t kErrUnknownMethod = 0x2;
constexpr uint32_t kErrUnknownVariable = 0x3;
constexpr uint32_t kErrLocalCondition = 0x4;
constexpr uint32_t kErrInvalidData = 0x5;
constexpr uint32_t kErrTooManyParameters = 0x7;  // BUFFER_OVERFLOW; our reading, not seen from a device
constexpr uint32_t kErrTooFewParameters = 0x8;
constexpr uint32_t kErrWriteAccessDenied = 0xA;
constexpr uint32_t kErrUnknownCommand = 0xC;
constexpr uint32_t kErrUnknownEvent = 0xF;
constexpr uint32_t kErrInvalidCharacter = 0x11;

constexpr int kLevelAuthorizedClient = 3;

inline void error_reply(uint32_t code, std::string& reply) {
  reply = "sFA ";
  append_cola_hex(reply, code);
}

inline uint64_t period_us_for(uint32_t frequency_1e2hz) { return 100000000ULL / frequency_1e2hz; }

/// False (and an sFA reply) unless the request has exactly n arguments after its name.
inline bool expect_arguments(const std::vector<std::string_view>& t, size_t n, std::string& reply) {
  const size_t have = t.size() - 2;
  if (have < n) {
    error_reply(kErrTooFewParameters, reply);
    return false;
  }
  if (have > n) {
    error_reply(kErrTooManyParameters, reply);
    return false;
  }
  return true;
}

/// Reads arguments first..first+n-1 as numbers; sFA 5 on a bad one.
inline bool read_numbers(const std::vector<std::string_view>& t, size_t first, size_t n, int64_t* out,
                         std::string& reply) {
  for (size_t i = 0; i < n; ++i) {
    if (!parse_cola_request_number(t[first + i], out[i])) {
      error_reply(kErrInvalidData, reply);
      return false;
    }
  }
  return true;
}

inline bool is_flag(int64_t v) { return v == 0 || v == 1; }

}  // namespace refloc::sopas
