#include "log_analysis.hpp"

#include "log_reader.hpp"

#include <memory>
#include <string_view>

namespace refloc {

LogAnalysis analyze_log(const std::string& path, const LogAnalysisOptions& options,
                        const MessageDecoder& decoder) {
  LogStatistics statistics(options.gap_threshold_s, options.max_gaps);
  PipelineLatency latency(options.pipeline_channels);
  for_each_log_event(path, [&](const LogEventView& e) {
    const char* type = decoder.type_name(e.data, e.size);
    statistics.add(*e.channel, e.log_utime, e.size, e.eventnum, type);
    std::optional<DecodedMessage> heartbeat;
    if (type != nullptr && std::string_view(type) == "heartbeat_t")
      heartbeat = decoder.decode(e.data, e.size);
    if (heartbeat) {
      statistics.add_heartbeat(*e.channel, heartbeat->fields["service"].get<std::string>(), e.log_utime,
                               e.eventnum);
    }
    if (!options.latency) return;
    if (const int stage = latency.stage_of(*e.channel); stage >= 0) {
      if (const auto scan_utime = decoder.utime(e.data, e.size)) {
        latency.add(static_cast<size_t>(stage), *scan_utime, e.log_utime);
      }
    } else if (heartbeat && *e.channel == options.heartbeat_channel) {
      const auto& f = heartbeat->fields;
      latency.add_processing({f["service"].get<std::string>(), f["processing_p50_us"].get<double>(),
                              f["processing_p99_us"].get<double>(), f["messages_in"].get<int64_t>(),
                              f["messages_out"].get<int64_t>()});
    }
  });
  LogAnalysis analysis{statistics.summary(), std::nullopt};
  if (options.latency) analysis.latency = latency.report();
  return analysis;
}

LogExportResult export_log(const std::string& path, const LogSummary& summary,
                           const LogExportRequest& request, const MessageDecoder& decoder) {
  LogExportResult result;
  const ChannelSelector selector(request.channel_patterns);
  for (const auto& c : summary.channels) {
    if (selector.matches(c.channel)) result.channels.push_back(c.channel);
  }
  if (request.jsonl_path.empty() && request.csv_path.empty()) return result;

  std::unique_ptr<JsonlExporter> jsonl;
  if (!request.jsonl_path.empty()) jsonl = std::make_unique<JsonlExporter>(request.jsonl_path, decoder);
  std::unique_ptr<CsvExporter> csv;
  if (!request.csv_path.empty()) {
    const bool single = result.channels.size() == 1;
    csv = std::make_unique<CsvExporter>(
        [&request, single](const std::string& channel) {
          return csv_path_for_channel(request.csv_path, channel, single);
        },
        decoder);
  }
  for_each_log_event(path, [&](const LogEventView& e) {
    if (!selector.matches(*e.channel)) return;
    if (jsonl) jsonl->add(e);
    if (csv) csv->add(e);
  });
  if (jsonl) result.jsonl = jsonl->counts();
  if (csv) {
    result.csv = csv->counts();
    result.csv_files = csv->files();
  }
  return result;
}

}  // namespace refloc
