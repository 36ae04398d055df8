#include "log_reader.hpp"

#include "common/json_config.hpp"

#include <lcm/lcm-cpp.hpp>

#include <memory>

namespace refloc {

size_t for_each_log_event(const std::string& path, const std::function<void(const LogEventView&)>& on_event) {
  auto log = std::make_unique<lcm::LogFile>(path, "r");
  if (!log->good()) throw ConfigError(path + ": cannot open as an LCM log file");
  size_t count = 0;
  // readNextEvent returns null at the end and at a truncated last event (logger killed).
  while (const lcm::LogEvent* e = log->readNextEvent()) {
    LogEventView view;
    view.eventnum = e->eventnum;
    view.log_utime = e->timestamp;
    view.channel = &e->channel;
    view.data = static_cast<const uint8_t*>(e->data);
    view.size = e->datalen > 0 ? static_cast<size_t>(e->datalen) : 0;
    on_event(view);
    ++count;
  }
  return count;
}

}  // namespace refloc
