#include "reflector_extractor/rssi_scale.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace refloc {

RssiScaleDetector::RssiScaleDetector(RssiScaleConfig config) : config_(config) {
  if (config_.mode == RssiScaleConfig::Mode::k8bitIn16bit) scale_ = RssiScale::k8bitIn16bit;
}

void RssiScaleDetector::observe(const LaserScan& scan, std::vector<NodeEvent>& events) {
  if (config_.mode != RssiScaleConfig::Mode::kAuto) return;
  if (scan.rssi_bits != 16 || scan.rssi.size() != scan.ranges.size()) return;
  int64_t echoes = 0;
  int32_t max_raw = 0;
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    const double range = static_cast<double>(scan.ranges[i]);
    if (range < scan.range_min || range > scan.range_max) continue;
    ++echoes;
    max_raw = std::max(max_raw, scan.rssi[i]);
  }
  if (echoes == 0) return;
  if (max_raw > 255) {
    if (scale_ == RssiScale::k8bitIn16bit) {
      events.push_back({"rssi_scale_changes", NodeEvent::Level::kWarn,
                        fmt::format("RSSI back on the 16-bit scale (/257): an echo of raw RSSI {} > 255 "
                                    "after {} scans on the 8-bit scale",
                                    max_raw, scans_)});
      scale_ = RssiScale::kNative;
    }
    scans_ = 0;
    echoes_ = 0;
    max_raw_ = 0;
    return;
  }
  ++scans_;
  echoes_ += echoes;
  max_raw_ = std::max(max_raw_, max_raw);
  if (scale_ == RssiScale::kNative && scans_ >= config_.min_scans && echoes_ >= config_.min_echoes) {
    scale_ = RssiScale::k8bitIn16bit;
    events.push_back({"rssi_scale_changes", NodeEvent::Level::kWarn,
                      fmt::format("RSSI read on the 8-bit scale (no /257): {} echoes of {} 16-bit scans "
                                  "never exceeded raw {}",
                                  echoes_, scans_, max_raw_)});
  }
}

std::string RssiScaleDetector::detail() const {
  if (scale_ != RssiScale::k8bitIn16bit) return "";
  if (config_.mode == RssiScaleConfig::Mode::k8bitIn16bit) return "RSSI 8-bit in the 16-bit channel (config)";
  return fmt::format("RSSI 8-bit in the 16-bit channel (max raw {} over {} echoes)", max_raw_, echoes_);
}

}  // namespace refloc
