#pragma once
// The emulated device's CoLa-B (docs/lms100-protocol.md §3): frames cut from the host's bytes,
// binary requests turned into the CoLa-A text Lms100Device answers, its text replies turned
// into binary. Written apart from the driver's CoLa-B code on purpose: the emulator is the
// driver's test oracle. It covers the dialogue of §4.1; other replies go out as their head only.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "common/cola_a_framing.hpp"

namespace refloc {

/// Cuts requests out of the byte stream: 02020202, uint32 length, payload, XOR. Bytes before
/// a magic, and frames whose length is too large or checksum wrong, are skipped.
class ColaBRequestReader {
 public:
  explicit ColaBRequestReader(size_t max_request_bytes = cola::kMaxTelegramBytes)
      : max_request_bytes_(max_request_bytes) {}
  void feed(const uint8_t* data, size_t size);
  /// Pops the next request payload; false if none is complete.
  bool next(std::string& payload);
  void reset() {
    received_.clear();
    read_pos_ = 0;
  }

 private:
  size_t max_request_bytes_;
  std::string received_;
  size_t read_pos_ = 0;
};

/// Appends the low `bytes` bytes of value, big-endian (CoLa-B's byte order).
void put_big_endian(std::string& out, uint32_t value, size_t bytes);

/// Wraps a payload: magic, big-endian length, payload, XOR checksum.
void frame_cola_b_telegram(std::string_view payload, std::string& out);

/// A binary request as CoLa-A text ("sMN SetAccessMode 3 F4724744"); false when its
/// arguments do not match the command's layout (the device then answers sFA).
bool cola_b_request_to_text(std::string_view payload, std::string& text);

/// A CoLa-A text reply of Lms100Device as the binary payload a CoLa-B device sends.
void cola_b_reply_from_text(std::string_view text, std::string& payload);

}  // namespace refloc
