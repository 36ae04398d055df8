#pragma once
// The frames waiting for one WebSocket client. The LCM thread pushes, the server thread pops;
// the caller holds the lock (ConsoleServer's mutex). Bounded: a frame beyond capacity is dropped
// and counted, so a slow browser never makes the LCM loop wait or the process grow. A client
// whose write has been pending for the stall timeout has stopped reading and is to be dropped.

#include "web_console/console_frame.hpp"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>

namespace refloc {

class ClientQueue {
 public:
  explicit ClientQueue(size_t capacity_frames) : capacity_(capacity_frames) {}

  /// Queue a frame; false when the queue was full and the frame was dropped.
  bool push(std::shared_ptr<const std::string> frame) {
    if (frames_.size() >= capacity_) {
      ++dropped_;
      return false;
    }
    frames_.push_back(std::move(frame));
    return true;
  }
  /// The next frame to write (nullptr when empty); its write starts at now_us [us].
  std::shared_ptr<const std::string> start_write(int64_t now_us) {
    if (frames_.empty() || writing_) return nullptr;
    std::shared_ptr<const std::string> frame = std::move(frames_.front());
    frames_.pop_front();
    writing_ = true;
    write_started_us_ = now_us;
    return frame;
  }
  /// The write start_write handed out has completed.
  void write_done() { writing_ = false; }
  /// A write pending longer than timeout_us: the client stopped reading.
  bool stalled(int64_t now_us, int64_t timeout_us) const {
    return writing_ && now_us - write_started_us_ > timeout_us;
  }

  bool writing() const { return writing_; }
  size_t size() const { return frames_.size(); }
  int64_t dropped() const { return dropped_; }

 private:
  size_t capacity_;
  std::deque<std::shared_ptr<const std::string>> frames_;
  bool writing_ = false;
  int64_t write_started_us_ = 0;
  int64_t dropped_ = 0;
};

}  // namespace refloc
