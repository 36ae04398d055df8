#pragma once
// Splits a CoLa-A byte stream (TCP) into telegram payloads.
//
// CoLa-A frames are STX (0x02) + ASCII + ETX (0x03) with no length and no
// checksum, so STX/ETX are the only sync points (docs/lms100-protocol.md §2.1-2.3).
// The splitter survives split reads, several telegrams per read, junk between
// telegrams, a frame cut short by a new STX, and frames that never end.

#include "common/cola_a_framing.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace refloc {

class ColaASplitter {
 public:
  /// max_frame_bytes: payload longer than this is dropped (a lost ETX must not grow memory).
  explicit ColaASplitter(size_t max_frame_bytes = cola::kMaxTelegramBytes);

  /// Appends received bytes.
  void feed(const uint8_t* data, size_t size);
  /// Pops the next complete telegram payload (without STX/ETX); false if none is complete.
  bool next(std::string& payload);

  uint64_t garbage_bytes() const { return garbage_bytes_; }        ///< bytes outside any frame
  uint64_t resyncs() const { return resyncs_; }                    ///< frames restarted by an STX inside them
  uint64_t oversized_frames() const { return oversized_frames_; }  ///< frames dropped as too long
  uint64_t frames() const { return frames_; }                      ///< complete frames popped

  /// Forgets buffered bytes and any open frame (e.g. after a reconnect); counters are kept.
  void reset();

 private:
  size_t max_frame_bytes_;
  std::string pending_;  ///< received bytes not yet scanned
  size_t scan_pos_ = 0;  ///< first byte of pending_ not yet examined
  std::string frame_;    ///< payload of the open frame
  bool in_frame_ = false;
  bool discarding_ = false;  ///< inside an oversized frame: drop until the next STX/ETX
  uint64_t garbage_bytes_ = 0;
  uint64_t resyncs_ = 0;
  uint64_t oversized_frames_ = 0;
  uint64_t frames_ = 0;
};

}  // namespace refloc
