#include "lms100_emulator/cola_a_request_reader.hpp"

namespace refloc {

void ColaARequestReader::feed(const uint8_t* data, size_t size) {
  received_.erase(0, read_pos_);
  read_pos_ = 0;
  received_.append(reinterpret_cast<const char*>(data), size);
}

bool ColaARequestReader::next(std::string& payload) {
  while (read_pos_ < received_.size()) {
    const char c = received_[read_pos_++];
    if (c == cola::kStx) {
      open_ = true;
      overflowed_ = false;
      request_.clear();
    } else if (!open_) {
      continue;  // noise between requests
    } else if (c == cola::kEtx) {
      open_ = false;
      if (overflowed_) continue;
      payload = request_;
      request_.clear();
      return true;
    } else if (request_.size() < max_request_bytes_) {
      request_.push_back(c);
    } else {
      overflowed_ = true;
    }
  }
  return false;
}

void ColaARequestReader::reset() {
  received_.clear();
  read_pos_ = 0;
  request_.clear();
  open_ = false;
  overflowed_ = false;
}

}  // namespace refloc
