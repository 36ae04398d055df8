#include "common/heartbeat_peers.hpp"

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace refloc {
namespace {

bool overlap(const HeardInstance& a, const HeardInstance& b) {
  return std::max(a.first_heard_s, b.first_heard_s) < std::min(a.last_heard_s, b.last_heard_s);
}

}  // namespace

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
