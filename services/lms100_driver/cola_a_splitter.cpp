#include "lms100_driver/cola_a_splitter.hpp"

namespace refloc {

ColaASplitter::ColaASplitter(size_t max_frame_bytes) : max_frame_bytes_(max_frame_bytes) {
  frame_.reserve(max_frame_bytes_ < 8192 ? max_frame_bytes_ : 8192);
}

void ColaASplitter::feed(const uint8_t* data, size_t size) {
  if (size == 0) return;
  // Drop what has already been scanned so pending_ stays small between reads.
  if (scan_pos_ > 0) {
    pending_.erase(0, scan_pos_);
    scan_pos_ = 0;
  }
  pending_.append(reinterpret_cast<const char*>(data), size);
}

bool ColaASplitter::next(std::string& payload) {
  while (scan_pos_ < pending_.size()) {
    const auto byte = static_cast<uint8_t>(pending_[scan_pos_++]);
    if (byte == static_cast<uint8_t>(cola::kStx)) {
      if (in_frame_ || discarding_) {
        // The previous frame lost its ETX; the STX is the only trustworthy sync point.
        if (in_frame_) ++resyncs_;
      }
      in_frame_ = true;
      discarding_ = false;
      frame_.clear();
      continue;
    }
    if (discarding_) {
      if (byte == static_cast<uint8_t>(cola::kEtx)) discarding_ = false;
      continue;
    }
    if (!in_frame_) {
      ++garbage_bytes_;
      continue;
    }
    if (byte == static_cast<uint8_t>(cola::kEtx)) {
      in_frame_ = false;
      payload.swap(frame_);
      frame_.clear();
      ++frames_;
      return true;
    }
    if (frame_.size() >= max_frame_bytes_) {
      ++oversized_frames_;
      in_frame_ = false;
      discarding_ = true;
      frame_.clear();
      continue;
    }
    frame_.push_back(static_cast<char>(byte));
  }
  pending_.clear();
  scan_pos_ = 0;
  return false;
}

void ColaASplitter::reset() {
  pending_.clear();
  scan_pos_ = 0;
  frame_.clear();
  in_frame_ = false;
  discarding_ = false;
}

}  // namespace refloc
