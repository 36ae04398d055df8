#pragma once
// Splits a CoLa-B byte stream (TCP) into checked frame payloads (docs/lms100-protocol.md §3).
//
// A frame is 02020202, a big-endian uint32 length, the payload and an XOR checksum. Unlike
// CoLa-A the magic can occur inside a binary payload, so sync rests on all three: bytes before
// a magic are garbage, a length over the limit or a wrong checksum means the magic was not a
// frame start, and the search restarts one byte after it. The frame check itself is
// unframe_cola_b, the one the recorded-capture tests use.

#include "common/cola_a_framing.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace refloc {

class ColaBSplitter {
 public:
  /// max_frame_bytes: a length field above this is not believed [bytes].
  explicit ColaBSplitter(size_t max_frame_bytes = cola::kMaxTelegramBytes)
      : max_frame_bytes_(max_frame_bytes) {}

  void feed(const uint8_t* data, size_t size);
  /// Pops the next complete, checked payload; false if none is complete.
  bool next(std::string& payload);

  uint64_t garbage_bytes() const { return garbage_bytes_; }  ///< bytes outside any frame
  uint64_t resyncs() const { return resyncs_; }              ///< magics dropped for a wrong checksum
  uint64_t oversized_frames() const {
    return oversized_frames_;
  }  ///< magics dropped for a length over the limit
  uint64_t frames() const { return frames_; }

  /// Forgets buffered bytes (a reconnect); counters are kept.
  void reset() {
    pending_.clear();
    begin_ = 0;
  }

 private:
  size_t max_frame_bytes_;
  std::string pending_;
  size_t begin_ = 0;  ///< first byte of pending_ not yet consumed
  uint64_t garbage_bytes_ = 0;
  uint64_t resyncs_ = 0;
  uint64_t oversized_frames_ = 0;
  uint64_t frames_ = 0;
};

}  // namespace refloc
