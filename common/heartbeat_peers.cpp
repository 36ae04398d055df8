#include "common/heartbeat_peers.hpp"

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace refloc {
namespace {

/// Big-endian reader that refuses to run past the end (LCM encodes big-endian).
class ByteReader {
 public:
  ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  bool read_int(int bytes, int64_t& value) {
    if (size_ - offset_ < static_cast<size_t>(bytes)) return false;
    uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v = (v << 8) | data_[offset_++];
    // Sign-extend the narrower types.
    if (bytes < 8 && (v >> (8 * bytes - 1)) != 0) v |= ~uint64_t{0} << (8 * bytes);
    value = static_cast<int64_t>(v);
    return true;
  }

  /// An LCM string: int32 length including the terminating NUL, then the bytes.
  bool read_string(std::string* out) {
    int64_t length = 0;
    if (!read_int(4, length) || length < 1 || static_cast<uint64_t>(length) > size_ - offset_) return false;
    if (out != nullptr)
      out->assign(reinterpret_cast<const char*>(data_ + offset_), static_cast<size_t>(length - 1));
    offset_ += static_cast<size_t>(length);
    return true;
  }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t offset_ = 0;
};

bool overlap(const HeardInstance& a, const HeardInstance& b) {
  return std::max(a.first_heard_s, b.first_heard_s) < std::min(a.last_heard_s, b.last_heard_s);
}

}  // namespace

std::optional<HeartbeatIdentity> peek_heartbeat_identity(const uint8_t* data, size_t size,
                                                         int64_t heartbeat_fingerprint,
                                                         int8_t stopping_state) {
  ByteReader reader(data, size);
  int64_t fingerprint = 0, utime = 0, pid = 0, state = 0, uptime_us = 0;
  HeartbeatIdentity id;
  if (!reader.read_int(8, fingerprint) || fingerprint != heartbeat_fingerprint) return std::nullopt;
  if (!reader.read_int(8, utime) || !reader.read_string(&id.service) || !reader.read_int(4, pid) ||
      !reader.read_int(1, state) || !reader.read_string(nullptr) || !reader.read_int(8, uptime_us))
    return std::nullopt;
  id.pid = static_cast<int32_t>(pid);
  id.start_utime = utime - uptime_us;
  id.stopping = state == stopping_state;
  return id;
}

DuplicateInstanceDetector::DuplicateInstanceDetector(double window_s) : window_s_(window_s) {}

void DuplicateInstanceDetector::observe(const HeartbeatIdentity& sender, double now_s) {
  auto& list = instances_[sender.service];
  list.erase(std::remove_if(list.begin(), list.end(),
                            [&](const HeardInstance& i) { return now_s - i.last_heard_s > window_s_; }),
             list.end());
  const auto same = std::find_if(list.begin(), list.end(), [&](const HeardInstance& i) {
    return i.pid == sender.pid && std::llabs(i.start_utime - sender.start_utime) <= kSameStartToleranceUs;
  });
  if (sender.stopping) {
    // Its last word: a successor that starts now is a restart, not a duplicate.
    if (same != list.end()) list.erase(same);
    return;
  }
  if (same == list.end()) {
    list.push_back({sender.pid, sender.start_utime, now_s, now_s});
  } else {
    same->last_heard_s = now_s;
    same->start_utime = sender.start_utime;
  }
}

std::vector<HeardInstance> DuplicateInstanceDetector::duplicates(const std::string& service,
                                                                 double now_s) const {
  std::vector<HeardInstance> out;
  const auto it = instances_.find(service);
  if (it == instances_.end()) return out;
  std::vector<HeardInstance> alive;
  for (const auto& i : it->second) {
    if (now_s - i.last_heard_s <= window_s_) alive.push_back(i);
  }
  for (size_t a = 0; a < alive.size(); ++a) {
    for (size_t b = 0; b < alive.size(); ++b) {
      if (a != b && overlap(alive[a], alive[b])) {
        out.push_back(alive[a]);
        break;
      }
    }
  }
  std::sort(out.begin(), out.end(),
            [](const HeardInstance& x, const HeardInstance& y) { return x.first_heard_s < y.first_heard_s; });
  return out;
}

std::vector<std::string> DuplicateInstanceDetector::duplicated_services(double now_s) const {
  std::vector<std::string> names;
  for (const auto& [service, list] : instances_) {
    if (!duplicates(service, now_s).empty()) names.push_back(service);
  }
  return names;
}

std::string describe_duplicates(const std::vector<HeardInstance>& instances) {
  if (instances.size() < 2) return "";
  std::string text =
      instances.size() == 2 ? "two instances:" : std::to_string(instances.size()) + " instances:";
  for (size_t i = 0; i < instances.size(); ++i)
    text += (i == 0 ? " pid " : ", pid ") + std::to_string(instances[i].pid);
  return text;
}

OwnNameMonitor::OwnNameMonitor(std::string service, int32_t pid) : service_(std::move(service)), pid_(pid) {}

bool OwnNameMonitor::observe(const HeartbeatIdentity& sender, double now_s) {
  if (sender.service != service_) return false;
  detector_.observe(sender, now_s);
  return sender.pid != pid_ ||
         std::llabs(sender.start_utime - own_start_utime_) > DuplicateInstanceDetector::kSameStartToleranceUs;
}

void OwnNameMonitor::observe_own(int64_t start_utime, double now_s) {
  own_start_utime_ = start_utime;
  detector_.observe({service_, pid_, start_utime, false}, now_s);
}

std::string OwnNameMonitor::conflict(double now_s) const {
  return describe_duplicates(detector_.duplicates(service_, now_s));
}

}  // namespace refloc
