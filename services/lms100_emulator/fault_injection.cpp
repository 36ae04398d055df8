#include "lms100_emulator/fault_injection.hpp"

#include "common/cola_a_framing.hpp"
#include "lms100_emulator/cola_a_text.hpp"

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

bool FaultSettings::corrupts_scan_header() const {
  return dist_scale != 1.0F || dist_offset_mm != 0.0F || scan_frequency_1e2hz != 0 ||
         measurement_frequency_1e1khz != 0 || reserved_distance_codes || layer_angle_1e4deg != 0;
}

namespace {

// Token indices of an LMDscandata payload without encoders (LMS100_PROTOCOL.md §3.3).
constexpr size_t kScanFrequencyToken = 16;
constexpr size_t kMeasurementFrequencyToken = 17;
constexpr size_t kDistScaleToken = 21;
constexpr size_t kDistOffsetToken = 22;
constexpr size_t kFirstDistValueToken = 26;
constexpr uint32_t kFirstReservedCode = 2;
constexpr uint32_t kLastReservedCode = 15;

std::string hex(uint32_t v) {
  std::string s;
  append_cola_hex(s, v);
  return s;
}

std::string hex_float(float v) {
  std::string s;
  append_cola_hex_float(s, v);
  return s;
}

}  // namespace

void corrupt_scan_header(const FaultSettings& settings, std::string& payload) {
  if (!settings.corrupts_scan_header()) return;
  const size_t last_code_token = kFirstDistValueToken + (kLastReservedCode - kFirstReservedCode);
  std::vector<std::pair<size_t, size_t>> tokens;  // begin, length of the first tokens
  for (size_t pos = 0; pos < payload.size() && tokens.size() <= last_code_token;) {
    const size_t end = std::min(payload.find(' ', pos), payload.size());
    tokens.emplace_back(pos, end - pos);
    pos = end + 1;
  }
  std::vector<std::pair<size_t, std::string>> replacements;
  const auto replace = [&](size_t token, std::string text) {
    if (token < tokens.size()) replacements.emplace_back(token, std::move(text));
  };
  if (settings.scan_frequency_1e2hz != 0) replace(kScanFrequencyToken, hex(settings.scan_frequency_1e2hz));
  if (settings.measurement_frequency_1e1khz != 0)
    replace(kMeasurementFrequencyToken, hex(settings.measurement_frequency_1e1khz));
  if (settings.dist_scale != 1.0F) replace(kDistScaleToken, hex_float(settings.dist_scale));
  if (settings.dist_offset_mm != 0.0F) replace(kDistOffsetToken, hex_float(settings.dist_offset_mm));
  if (settings.reserved_distance_codes) {
    for (uint32_t code = kFirstReservedCode; code <= kLastReservedCode; ++code)
      replace(kFirstDistValueToken + code - kFirstReservedCode, hex(code));
  }
  // Back to front, so earlier token positions stay valid.
  for (auto it = replacements.rbegin(); it != replacements.rend(); ++it) {
    const auto [begin, length] = tokens[it->first];
    payload.replace(begin, length, it->second);
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
