#pragma once
// Reads a recorded LCM log in order and hands each message of a registered channel, decoded,
// to its handler: the one decode loop the replay tests share. A message that does not decode
// is counted, not skipped silently, so a test can assert there were none.

#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <map>
#include <string>

namespace refloc::test {

class RecordedLogReader {
 public:
  template <class Message>
  RecordedLogReader& on(const std::string& channel, std::function<void(const Message&)> handler) {
    handlers_[channel] = [this, handler = std::move(handler)](const lcm::LogEvent& e) {
      Message m{};
      if (m.decode(e.data, 0, e.datalen) < 0) {
        ++undecodable_;
        return;
      }
      handler(m);
    };
    return *this;
  }

  /// Reads the whole log; false when it cannot be opened.
  bool read(const std::string& path) {
    lcm::LogFile log(path, "r");
    if (!log.good()) return false;
    while (const lcm::LogEvent* e = log.readNextEvent()) {
      const auto it = handlers_.find(e->channel);
      if (it != handlers_.end()) it->second(*e);
    }
    return true;
  }

  int undecodable() const { return undecodable_; }

 private:
  std::map<std::string, std::function<void(const lcm::LogEvent&)>> handlers_;
  int undecodable_ = 0;
};

}  // namespace refloc::test
