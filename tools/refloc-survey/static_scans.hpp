#pragma once
// Where a static survey's scans come from: an LCM log or the live bus (the LCM edge of
// refloc-survey static; the survey itself is LCM-free, static_survey.hpp).

#include "common/laser_scan.hpp"

#include <functional>
#include <string>

namespace refloc {

/// Called with every decoded scan; returns whether the scan counts (the extractor accepted it).
using ScanSink = std::function<bool(const LaserScan&)>;

struct ScanReadCounts {
  int messages = 0;     ///< on the channel
  int undecodable = 0;  ///< refused by the bounded decoder
  int counted = 0;      ///< scans the sink counted
};

/// Feeds the channel's scans of the log at path to sink until it counted wanted of them or the
/// log ends. Throws ConfigError when the file is not an LCM log.
ScanReadCounts read_log_scans(const std::string& path, const std::string& channel, int wanted,
                              const ScanSink& sink);

/// The same from the bus at lcm_url (empty: $LCM_DEFAULT_URL or the default); gives up when no
/// scan came for timeout_s. Throws std::runtime_error when the bus cannot be opened.
ScanReadCounts read_live_scans(const std::string& lcm_url, const std::string& channel, int wanted,
                               double timeout_s, const ScanSink& sink);

}  // namespace refloc
