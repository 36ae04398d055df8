#include "lms100_emulator/fault_injection.hpp"

#include "common/cola_a_framing.hpp"

#include <algorithm>
#include <utility>

namespace refloc {

void plan_write_cuts(size_t size, const FaultSettings& settings, std::mt19937& rng,
                     std::vector<size_t>& cuts) {
  cuts.clear();
  if (size < 2) return;
  if (settings.split_mode == WriteSplitMode::boundaries) {
    // After the first byte (STX) and before the last (ETX) of the write.
    cuts.push_back(1);
    if (size - 1 > 1) cuts.push_back(size - 1);
    return;
  }
  if (settings.split_mode != WriteSplitMode::random) return;
  const size_t pieces = static_cast<size_t>(std::max(2, settings.split_pieces));
  std::uniform_int_distribution<size_t> position(1, size - 1);
  for (size_t i = 0; i + 1 < pieces; ++i) cuts.push_back(position(rng));
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
}

void append_junk_bytes(size_t count, std::mt19937& rng, std::string& out) {
  std::uniform_int_distribution<int> byte(0, 255);
  for (size_t i = 0; i < count; ++i) {
    int b = byte(rng);
    if (b == cola::kStx) b = cola::kEtx;  // a stray ETX is fine junk; a stray STX would open a frame
    out.push_back(static_cast<char>(b));
  }
}

FaultSettings FaultInjector::settings() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return settings_;
}

void FaultInjector::set_settings(const FaultSettings& settings) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    settings_ = settings;
  }
  notify();
}

void FaultInjector::drop_next_scans(int n) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    drops_pending_ += std::max(0, n);
  }
  notify();
}

void FaultInjector::stall_for_ms(int ms) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stall_ms_pending_ = std::max(stall_ms_pending_, ms);
  }
  notify();
}

void FaultInjector::close_connection_now() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    close_pending_ = true;
  }
  notify();
}

void FaultInjector::reset_mid_telegram() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    reset_pending_ = true;
  }
  notify();
}

void FaultInjector::refuse_next_write() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    refuse_write_pending_ = true;
  }
  notify();
}

bool FaultInjector::take_drop() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (drops_pending_ == 0) return false;
  --drops_pending_;
  return true;
}

int FaultInjector::take_stall_ms() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(stall_ms_pending_, 0);
}

bool FaultInjector::take_close_now() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(close_pending_, false);
}

bool FaultInjector::take_reset_mid_telegram() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(reset_pending_, false);
}

bool FaultInjector::take_refuse_next_write() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(refuse_write_pending_, false);
}

void FaultInjector::set_change_listener(std::function<void()> listener) {
  std::lock_guard<std::mutex> lock(mutex_);
  listener_ = std::move(listener);
}

void FaultInjector::notify() {
  std::function<void()> listener;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    listener = listener_;
  }
  if (listener) listener();
}

}  // namespace refloc
