#include "lms100_driver/cola_b_splitter.hpp"

#include "lms100_driver/cola_b_scandata_parser.hpp"

#include <string_view>

namespace refloc {

void ColaBSplitter::feed(const uint8_t* data, size_t size) {
  if (begin_ > 0) {
    pending_.erase(0, begin_);
    begin_ = 0;
  }
  pending_.append(reinterpret_cast<const char*>(data), size);
}

bool ColaBSplitter::next(std::string& payload) {
  for (;;) {
    const std::string_view rest = std::string_view(pending_).substr(begin_);
    const size_t magic = rest.find(cola::kColaBMagic);
    if (magic == std::string_view::npos) {
      // Keep a possible start of a magic split across reads; the rest is garbage.
      size_t keep = 0;
      while (keep < 3 && keep < rest.size() && rest[rest.size() - 1 - keep] == cola::kStx) ++keep;
      garbage_bytes_ += rest.size() - keep;
      begin_ += rest.size() - keep;
      return false;
    }
    garbage_bytes_ += magic;
    begin_ += magic;
    if (pending_.size() - begin_ < cola::kColaBHeaderBytes) return false;
    uint32_t length = 0;
    for (size_t i = 4; i < 8; ++i) length = (length << 8) | static_cast<uint8_t>(pending_[begin_ + i]);
    if (length > max_frame_bytes_) {
      ++oversized_frames_;
      ++begin_;  // not a frame start; look for the next magic
      ++garbage_bytes_;
      continue;
    }
    const size_t frame_bytes = length + cola::kColaBOverheadBytes;
    if (pending_.size() - begin_ < frame_bytes) return false;
    std::string_view checked;
    if (!unframe_cola_b(std::string_view(pending_).substr(begin_, frame_bytes), checked)) {
      ++resyncs_;
      ++begin_;
      ++garbage_bytes_;
      continue;
    }
    payload.assign(checked);
    begin_ += frame_bytes;
    ++frames_;
    return true;
  }
}

}  // namespace refloc
