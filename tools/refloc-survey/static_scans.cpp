#include "static_scans.hpp"

#include "common/json_config.hpp"
#include "common/lcm_bounded_decode.hpp"
#include "common/lcm_conversions.hpp"
#include "common/lcm_url.hpp"

#include <lcm/lcm-cpp.hpp>
#include <refloc/laser_scan_t.hpp>

#include <chrono>
#include <cstdlib>
#include <stdexcept>

namespace refloc {
namespace {

void feed(const void* data, size_t size, const ScanSink& sink, ScanReadCounts& counts, LaserScan& scan) {
  ++counts.messages;
  laser_scan_t message;
  if (!decode_lcm_bounded(data, size, message).ok) {
    ++counts.undecodable;
    return;
  }
  copy_from_lcm(message, scan);
  if (sink(scan)) ++counts.counted;
}

struct LiveListener {
  const ScanSink* sink;
  ScanReadCounts* counts;
  LaserScan scan;
  void on_scan(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/) {
    feed(buffer->data, buffer->data_size, *sink, *counts, scan);
  }
};

}  // namespace

ScanReadCounts read_log_scans(const std::string& path, const std::string& channel, int wanted,
                              const ScanSink& sink) {
  lcm::LogFile log(path, "r");
  if (!log.good()) throw ConfigError(path + ": cannot open as an LCM log");
  ScanReadCounts counts;
  LaserScan scan;
  for (const lcm::LogEvent* e = log.readNextEvent(); e != nullptr && counts.counted < wanted;
       e = log.readNextEvent()) {
    if (e->channel == channel) feed(e->data, static_cast<size_t>(e->datalen), sink, counts, scan);
  }
  return counts;
}

ScanReadCounts read_live_scans(const std::string& lcm_url, const std::string& channel, int wanted,
                               double timeout_s, const ScanSink& sink) {
  const LcmUrl url = resolve_lcm_url(lcm_url, std::getenv("LCM_DEFAULT_URL"));
  lcm::LCM bus(url.url);
  if (!bus.good())
    throw std::runtime_error("cannot open LCM at '" + url.url + "' (is there a multicast route?)");
  ScanReadCounts counts;
  LiveListener listener{&sink, &counts, {}};
  bus.subscribe(channel, &LiveListener::on_scan, &listener);
  using Clock = std::chrono::steady_clock;
  auto last_scan = Clock::now();
  int messages = 0;
  while (counts.counted < wanted) {
    bus.handleTimeout(100);
    if (counts.messages != messages) messages = counts.messages, last_scan = Clock::now();
    if (std::chrono::duration<double>(Clock::now() - last_scan).count() > timeout_s) break;
  }
  return counts;
}

}  // namespace refloc
