#include "log_analysis.hpp"

#include "common/lcm_bounded_decode.hpp"
#include "log_reader.hpp"

#include <fmt/format.h>
#include <refloc/laser_scan_t.hpp>

#include <memory>
#include <string_view>

namespace refloc {
namespace {

void add_to_continuity(ScanContinuity& continuity, const LogEventView& e,
                       const std::optional<DecodedMessage>& heartbeat, const MessageDecoder& decoder,
                       laser_scan_t& scan) {
  continuity.add_event(e.log_utime);
  if (*e.channel == continuity.scan_channel()) {
    // Straight into the type (not JSON): a scan has hundreds of ranges.
    if (decode_lcm_bounded(e.data, e.size, scan).ok)
      continuity.add_scan(scan.scan_counter, scan.utime, e.log_utime);
  } else if (const int stage = continuity.stage_of(*e.channel); stage >= 0) {
    if (const auto scan_utime = decoder.utime(e.data, e.size))
      continuity.add_stage(static_cast<size_t>(stage), *scan_utime);
  } else if (heartbeat) {
    const auto& f = heartbeat->fields;
    continuity.add_heartbeat(f.at("service").get<std::string>(), f.at("pid").get<int32_t>(),
                             f.at("messages_in").get<int64_t>(), f.at("messages_out").get<int64_t>(),
                             f.at("decode_errors").get<int64_t>(), f.at("processing_p50_us").get<double>(),
                             f.at("processing_p99_us").get<double>(),
                             f.at("counter_names").get<std::vector<std::string>>(),
                             f.at("counter_values").get<std::vector<int64_t>>());
  }
}

}  // namespace

LogAnalysis analyze_log(const std::string& path, const LogAnalysisOptions& options,
                        const MessageDecoder& decoder) {
  LogStatistics statistics(options.gap_threshold_s, options.max_gaps);
  PipelineLatency latency(options.pipeline_channels);
  latency.set_next_channel(options.next_channel);
  ScanContinuity continuity(options.scan_channel, options.scan_stages, options.scan_tail_grace_s);
  laser_scan_t scan;
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
    if (options.scans) add_to_continuity(continuity, e, heartbeat, decoder, scan);
    if (!options.latency) return;
    if (!options.next_channel.empty() && *e.channel == options.next_channel) latency.add_next(e.log_utime);
    if (const int stage = latency.stage_of(*e.channel); stage >= 0) {
      if (const auto scan_utime = decoder.utime(e.data, e.size)) {
        latency.add(static_cast<size_t>(stage), *scan_utime, e.log_utime);
      }
    } else if (heartbeat && *e.channel == options.heartbeat_channel) {
      const auto& f = heartbeat->fields;
      latency.add_processing({f.at("service").get<std::string>(), f.at("processing_p50_us").get<double>(),
                              f.at("processing_p99_us").get<double>(), f.at("messages_in").get<int64_t>(),
                              f.at("messages_out").get<int64_t>()});
    }
  });
  LogAnalysis analysis{statistics.summary(), std::nullopt, std::nullopt};
  if (options.latency) analysis.latency = latency.report();
  if (options.scans) analysis.scans = continuity.report();
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

std::string format_export_counts(const LogExportRequest& request, const LogExportResult& exported) {
  std::string out;
  if (!request.jsonl_path.empty()) {
    out += fmt::format("{}: {} lines ({} not decodable) from {} channels\n", request.jsonl_path,
                       exported.jsonl.written, exported.jsonl.undecoded, exported.channels.size());
  }
  for (const auto& [channel, file] : exported.csv_files)
    out += fmt::format("{}: channel {}\n", file, channel);
  if (!request.csv_path.empty()) {
    out += fmt::format("CSV: {} rows, {} not decodable (skipped), {} of a changed type (skipped)\n",
                       exported.csv.written, exported.csv.undecoded, exported.csv.type_changed);
  }
  if ((!request.csv_path.empty() || !request.jsonl_path.empty()) && exported.channels.empty())
    out += "refloc-log: warning: no channel of the log matches --channel\n";
  return out;
}

}  // namespace refloc
