#pragma once
// Text and JSON output of refloc-log: the channel summary with gaps, and the
// pipeline latency report.

#include "log_analysis.hpp"
#include "log_statistics.hpp"
#include "pipeline_latency.hpp"
#include "scan_continuity.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace refloc {

/// Channel table (count, rate, bytes, largest gap and where) and the listed gaps.
std::string format_log_summary(const LogSummary& summary);
nlohmann::ordered_json log_summary_to_json(const LogSummary& summary);

/// Per-stage and end-to-end p50/p99/max, scans reaching each stage, HEARTBEAT processing.
std::string format_latency_report(const LatencyReport& report);
nlohmann::ordered_json latency_report_to_json(const LatencyReport& report);

/// Scans and counter gaps, scans reaching each stage, dropped scans, and the
/// service table from HEARTBEAT (messages, decode errors, worst handler p99, restarts).
std::string format_scan_continuity(const ScanContinuityReport& report);
nlohmann::ordered_json scan_continuity_to_json(const ScanContinuityReport& report);

/// Everything analyze_log found: the summary, then latency and scans when asked; as
/// text, or as one JSON document (summary keys, "latency", "scans") when json.
std::string format_log_analysis(const LogAnalysis& analysis, bool json);

}  // namespace refloc
