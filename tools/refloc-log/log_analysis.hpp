#pragma once
// The two passes of refloc-log over a log file: analysis (channel statistics,
// gaps, pipeline latency) and export of the selected channels.

#include "log_export.hpp"
#include "log_statistics.hpp"
#include "message_json.hpp"
#include "pipeline_latency.hpp"
#include "scan_continuity.hpp"

#include <optional>
#include <string>
#include <vector>

namespace refloc {

struct LogAnalysisOptions {
  double gap_threshold_s = 0.5;  ///< list gaps longer than this [s]
  size_t max_gaps = 100;         ///< list at most this many gaps
  bool latency = false;          ///< also measure the scan-to-pose pipeline
  std::vector<std::string> pipeline_channels = default_pipeline_channels();
  /// --then-next: a channel without the scan's utime ending the pipeline (PipelineLatency).
  std::string next_channel;
  std::string heartbeat_channel = "HEARTBEAT";
  bool scans = false;  ///< also check scan continuity (dropped scans) and service health
  std::string scan_channel = "LMS100_SCAN";
  std::vector<std::string> scan_stages = {"REFLECTORS", "REFLECTOR_MATCHES", "LASER_POSE"};
  double scan_tail_grace_s = 0.5;  ///< see StageCoverage::scans_missing
};

struct LogAnalysis {
  LogSummary summary;
  std::optional<LatencyReport> latency;
  std::optional<ScanContinuityReport> scans;
};

/// Read the whole log once. Throws ConfigError when it cannot be opened.
LogAnalysis analyze_log(const std::string& path, const LogAnalysisOptions& options,
                        const MessageDecoder& decoder);

struct LogExportRequest {
  std::vector<std::string> channel_patterns;  ///< see ChannelSelector; empty = all
  std::string jsonl_path;                     ///< empty = no JSON lines
  std::string csv_path;                       ///< empty = no CSV
};

struct LogExportResult {
  std::vector<std::string> channels;  ///< channels of the log that were selected
  ExportCounts jsonl;
  ExportCounts csv;
  std::map<std::string, std::string> csv_files;  ///< channel -> file
};

/// Export the selected channels; `summary` (from analyze_log) tells which channels
/// exist, so a single selected channel gets csv_path itself.
LogExportResult export_log(const std::string& path, const LogSummary& summary,
                           const LogExportRequest& request, const MessageDecoder& decoder);

/// What the export wrote (lines, files, rows skipped), and a warning when no channel matched.
std::string format_export_counts(const LogExportRequest& request, const LogExportResult& exported);

}  // namespace refloc
