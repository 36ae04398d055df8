#include "log_report.hpp"

#include <fmt/format.h>

#include <ctime>

namespace refloc {
namespace {

std::string iso_utc(int64_t utime) {
  const std::time_t seconds = static_cast<std::time_t>(utime / 1'000'000);
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%S", &tm);
  return fmt::format("{}.{:03d}Z", text, static_cast<int>((utime % 1'000'000) / 1000));
}

std::string stats_line(const std::string& name, const LatencyStats& s) {
  if (s.count == 0)
    return fmt::format("  {:<40} {:>7} {:>9} {:>9} {:>9} {:>9}\n", name, 0, "-", "-", "-", "-");
  return fmt::format("  {:<40} {:>7} {:>9.2f} {:>9.2f} {:>9.2f} {:>9.2f}\n", name, s.count, s.p50_ms,
                     s.p99_ms, s.mean_ms, s.max_ms);
}

nlohmann::ordered_json stats_json(const LatencyStats& s) {
  return {{"count", s.count},
          {"p50_ms", s.p50_ms},
          {"p99_ms", s.p99_ms},
          {"mean_ms", s.mean_ms},
          {"max_ms", s.max_ms}};
}

}  // namespace

std::string format_log_summary(const LogSummary& summary) {
  std::string out;
  if (summary.events == 0) return "empty log: no events\n";
  out += fmt::format("{} events on {} channels over {:.3f} s ({} .. {})\n", summary.events,
                     summary.channels.size(), summary.duration_s, iso_utc(summary.first_utime),
                     iso_utc(summary.last_utime));
  out += fmt::format("largest gap on all channels: {:.3f} s at {:.3f} s\n", summary.largest_gap_s,
                     summary.largest_gap_at_s);
  out += fmt::format("{:<22} {:<24} {:>8} {:>9} {:>11} {:>10} {:>10}\n", "CHANNEL", "TYPE", "COUNT",
                     "RATE[Hz]", "BYTES", "MAXGAP[s]", "AT[s]");
  for (const auto& c : summary.channels) {
    out += fmt::format("{:<22} {:<24} {:>8} {:>9.2f} {:>11} {:>10.3f} {:>10.3f}\n", c.channel, c.type,
                       c.count, c.rate_hz, c.bytes, c.largest_gap_s, c.largest_gap_at_s);
  }
  out += fmt::format("gaps longer than {:.3f} s: {}\n", summary.gap_threshold_s,
                     summary.gaps.size() + summary.gaps_not_listed);
  for (const auto& g : summary.gaps) {
    out += fmt::format("  {:<22} at {:>10.3f} s  for {:>8.3f} s  (ended by event {})\n", g.channel, g.start_s,
                       g.length_s, g.end_event);
  }
  if (summary.gaps_not_listed > 0) out += fmt::format("  ... and {} more\n", summary.gaps_not_listed);
  return out;
}

nlohmann::ordered_json log_summary_to_json(const LogSummary& summary) {
  nlohmann::ordered_json channels = nlohmann::ordered_json::array();
  for (const auto& c : summary.channels) {
    channels.push_back({{"channel", c.channel},
                        {"type", c.type},
                        {"count", c.count},
                        {"bytes", c.bytes},
                        {"rate_hz", c.rate_hz},
                        {"first_utime", c.first_utime},
                        {"last_utime", c.last_utime},
                        {"largest_gap_s", c.largest_gap_s},
                        {"largest_gap_at_s", c.largest_gap_at_s},
                        {"largest_gap_event", c.largest_gap_event}});
  }
  nlohmann::ordered_json gaps = nlohmann::ordered_json::array();
  for (const auto& g : summary.gaps) {
    gaps.push_back({{"channel", g.channel},
                    {"start_s", g.start_s},
                    {"length_s", g.length_s},
                    {"end_event", g.end_event}});
  }
  return {{"events", summary.events},
          {"first_utime", summary.first_utime},
          {"last_utime", summary.last_utime},
          {"duration_s", summary.duration_s},
          {"largest_gap_s", summary.largest_gap_s},
          {"largest_gap_at_s", summary.largest_gap_at_s},
          {"gap_threshold_s", summary.gap_threshold_s},
          {"channels", std::move(channels)},
          {"gaps", std::move(gaps)},
          {"gaps_not_listed", summary.gaps_not_listed}};
}

std::string format_latency_report(const LatencyReport& report) {
  std::string out = "scan-to-pose latency from log receive times [ms]\n";
  out +=
      fmt::format("  {:<40} {:>7} {:>9} {:>9} {:>9} {:>9}\n", "STAGE", "SCANS", "P50", "P99", "MEAN", "MAX");
  for (size_t i = 0; i < report.stages.size(); ++i) {
    out += stats_line(report.channels[i] + " -> " + report.channels[i + 1], report.stages[i]);
  }
  if (!report.channels.empty()) {
    out +=
        stats_line(report.channels.front() + " -> " + report.channels.back() + " (total)", report.end_to_end);
  }
  out += "  scans seen per channel:";
  for (size_t i = 0; i < report.channels.size(); ++i) {
    out += fmt::format(" {}={}", report.channels[i], report.reached[i]);
  }
  out += "\n";
  if (!report.processing.empty()) {
    out += "handler time per service from its last HEARTBEAT [us]\n";
    out += fmt::format("  {:<24} {:>9} {:>9} {:>10} {:>10}\n", "SERVICE", "P50", "P99", "IN", "OUT");
    for (const auto& p : report.processing) {
      out += fmt::format("  {:<24} {:>9.0f} {:>9.0f} {:>10} {:>10}\n", p.service, p.p50_us, p.p99_us,
                         p.messages_in, p.messages_out);
    }
  }
  return out;
}

nlohmann::ordered_json latency_report_to_json(const LatencyReport& report) {
  nlohmann::ordered_json stages = nlohmann::ordered_json::array();
  for (size_t i = 0; i < report.stages.size(); ++i) {
    auto s = stats_json(report.stages[i]);
    s["from"] = report.channels[i];
    s["to"] = report.channels[i + 1];
    stages.push_back(std::move(s));
  }
  nlohmann::ordered_json reached = nlohmann::ordered_json::object();
  for (size_t i = 0; i < report.channels.size(); ++i) reached[report.channels[i]] = report.reached[i];
  nlohmann::ordered_json processing = nlohmann::ordered_json::array();
  for (const auto& p : report.processing) {
    processing.push_back({{"service", p.service},
                          {"processing_p50_us", p.p50_us},
                          {"processing_p99_us", p.p99_us},
                          {"messages_in", p.messages_in},
                          {"messages_out", p.messages_out}});
  }
  return {{"end_to_end", stats_json(report.end_to_end)},
          {"stages", std::move(stages)},
          {"scans_per_channel", std::move(reached)},
          {"heartbeat_processing", std::move(processing)}};
}

std::string format_scan_continuity(const ScanContinuityReport& r) {
  std::string out = fmt::format("scan continuity on {}\n", r.scan_channel);
  out += fmt::format(
      "  scans {} over {:.3f} s ({:.2f} Hz), counters {}..{}: expected {}, missing {} in {} gaps, "
      "duplicates {}, out of order {}\n",
      r.scans, r.duration_s, r.rate_hz, r.first_counter, r.last_counter, r.expected, r.missing, r.gap_count,
      r.duplicates, r.out_of_order);
  for (const auto& g : r.gaps) {
    out += fmt::format("    gap after counter {}: {} scans missing (at {:.3f} s)\n", g.after_counter,
                       g.missing, g.at_s);
  }
  if (r.gap_count > static_cast<int64_t>(r.gaps.size()))
    out += fmt::format("    ... and {} more gaps\n", r.gap_count - static_cast<int64_t>(r.gaps.size()));
  for (const auto& s : r.stages) {
    out += fmt::format("  {:<20} messages {:>8}  scans reached {:>8}  scans missing {:>6}\n", s.channel,
                       s.messages, s.scans_reached, s.scans_missing);
  }
  out += fmt::format("  not logged but processed downstream: {}\n  dropped scans: {}\n",
                     r.unlogged_but_processed, r.dropped());
  if (!r.services.empty()) {
    out += "service health from HEARTBEAT\n";
    out += fmt::format("  {:<22} {:>6} {:>10} {:>10} {:>8} {:>9} {:>9} {:>8}\n", "SERVICE", "BEATS",
                       "IN(LOG)", "OUT(LOG)", "DECERR", "P99[us]", "MAXP99", "RESTART");
    for (const auto& h : r.services) {
      out += fmt::format("  {:<22} {:>6} {:>10} {:>10} {:>8} {:>9.0f} {:>9.0f} {:>8}\n", h.service,
                         h.heartbeats, h.messages_in_logged, h.messages_out_logged, h.decode_errors,
                         h.last_p99_us, h.max_p99_us, h.restarts);
    }
  }
  return out;
}

nlohmann::ordered_json scan_continuity_to_json(const ScanContinuityReport& r) {
  nlohmann::ordered_json gaps = nlohmann::ordered_json::array();
  for (const auto& g : r.gaps)
    gaps.push_back({{"after_counter", g.after_counter}, {"missing", g.missing}, {"at_s", g.at_s}});
  nlohmann::ordered_json stages = nlohmann::ordered_json::array();
  for (const auto& s : r.stages) {
    stages.push_back({{"channel", s.channel},
                      {"messages", s.messages},
                      {"scans_reached", s.scans_reached},
                      {"scans_missing", s.scans_missing}});
  }
  nlohmann::ordered_json services = nlohmann::ordered_json::array();
  for (const auto& h : r.services) {
    services.push_back({{"service", h.service},
                        {"heartbeats", h.heartbeats},
                        {"restarts", h.restarts},
                        {"messages_in", h.messages_in},
                        {"messages_out", h.messages_out},
                        {"messages_in_logged", h.messages_in_logged},
                        {"messages_out_logged", h.messages_out_logged},
                        {"decode_errors", h.decode_errors},
                        {"processing_p50_us", h.last_p50_us},
                        {"processing_p99_us", h.last_p99_us},
                        {"max_processing_p99_us", h.max_p99_us},
                        {"counters", h.counters}});
  }
  return {{"channel", r.scan_channel},        {"scans", r.scans},
          {"duration_s", r.duration_s},       {"rate_hz", r.rate_hz},
          {"first_counter", r.first_counter}, {"last_counter", r.last_counter},
          {"expected", r.expected},           {"missing", r.missing},
          {"gap_count", r.gap_count},         {"duplicates", r.duplicates},
          {"out_of_order", r.out_of_order},   {"unlogged_but_processed", r.unlogged_but_processed},
          {"dropped", r.dropped()},           {"gaps", std::move(gaps)},
          {"stages", std::move(stages)},      {"services", std::move(services)}};
}

std::string format_log_analysis(const LogAnalysis& analysis, bool json) {
  if (json) {
    nlohmann::ordered_json doc = log_summary_to_json(analysis.summary);
    if (analysis.latency) doc["latency"] = latency_report_to_json(*analysis.latency);
    if (analysis.scans) doc["scans"] = scan_continuity_to_json(*analysis.scans);
    return doc.dump(2) + "\n";
  }
  std::string out = format_log_summary(analysis.summary);
  if (analysis.latency) out += format_latency_report(*analysis.latency);
  if (analysis.scans) out += format_scan_continuity(*analysis.scans);
  return out;
}

}  // namespace refloc
