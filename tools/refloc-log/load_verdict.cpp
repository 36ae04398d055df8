#include "load_verdict.hpp"

#include "common/json_config.hpp"
#include "log_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace refloc {
namespace {

const ServiceHealth* health_of(const ScanContinuityReport& scans, const std::string& program) {
  for (const auto& h : scans.services)
    if (h.service == program) return &h;
  return nullptr;
}

double cpu_percent(const ProcessUsage& p, const LoadRun& run) {
  if (run.measured_s <= 0.0) return 0.0;
  return static_cast<double>(p.cpu_ticks) / run.clock_ticks_per_s / run.measured_s * 100.0;
}

double mb(int64_t kb) { return static_cast<double>(kb) / 1024.0; }

/// Rounded to `decimals` places, as the report prints it.
double rounded(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(value * scale) / scale;
}

nlohmann::ordered_json service_json(const ProcessUsage& p, const LoadRun& run, const ServiceHealth* h) {
  nlohmann::ordered_json j = {
      {"cpu_percent", cpu_percent(p, run)},
      {"rss_mean_mb", p.samples > 0
                          ? nlohmann::ordered_json(mb(p.rss_sum_kb) / static_cast<double>(p.samples))
                          : nlohmann::ordered_json(nullptr)},
      {"rss_end_mb", mb(p.rss_end_kb)},
      {"rss_peak_mb", mb(p.rss_peak_kb)},
      {"samples", p.samples},
      {"pid_restarts", p.pid_restarts},
      {"service", p.program}};
  const auto or_null = [h](auto value) {
    return h ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
  };
  j["heartbeat_p99_us"] = or_null(h ? h->last_p99_us : 0.0);
  j["heartbeat_max_p99_us"] = or_null(h ? h->max_p99_us : 0.0);
  j["messages_in_logged"] = or_null(h ? h->messages_in_logged : 0);
  j["messages_out_logged"] = or_null(h ? h->messages_out_logged : 0);
  j["decode_errors"] = or_null(h ? h->decode_errors : 0);
  j["heartbeat_restarts"] = or_null(h ? h->restarts : 0);
  j["counters"] = h ? nlohmann::ordered_json(h->counters) : nlohmann::ordered_json(nullptr);
  return j;
}

std::string number_or_dash(const ServiceHealth* h, double value, int decimals) {
  return h ? fmt::format("{}", rounded(value, decimals)) : "-";
}

/// Columns padded to their widest cell, two spaces apart (what `column -t` did).
std::string aligned(const std::vector<std::vector<std::string>>& rows) {
  std::vector<size_t> width;
  for (const auto& row : rows) {
    width.resize(std::max(width.size(), row.size()), 0);
    for (size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  }
  std::string out;
  for (const auto& row : rows) {
    std::string line;
    for (size_t c = 0; c < row.size(); ++c)
      line += c + 1 < row.size() ? fmt::format("{:<{}}  ", row[c], width[c]) : row[c];
    out += line + "\n";
  }
  return out;
}

}  // namespace

LoadChecks judge_load_test(const LoadSamples& samples, const ScanContinuityReport& scans,
                           const LatencyReport& latency) {
  LoadChecks c;
  c.max_p99_ms = samples.run.max_p99_ms;
  c.no_dropped_scan = scans.dropped() == 0;
  c.latency_p99_within_limit = c.max_p99_ms <= 0.0 || latency.end_to_end.p99_ms <= c.max_p99_ms;
  c.every_service_reported = true;
  c.no_restart = true;
  for (const auto& p : samples.processes) {
    const ServiceHealth* h = health_of(scans, p.program);
    if (!h && p.program != kLoadTestRecorder) c.every_service_reported = false;
    if (p.pid_restarts > 0 || (h && h->restarts > 0)) c.no_restart = false;
  }
  return c;
}

nlohmann::ordered_json load_test_report_to_json(const LoadSamples& samples, const ScanContinuityReport& scans,
                                                const LatencyReport& latency, const LoadChecks& checks) {
  const LoadRun& run = samples.run;
  const nlohmann::ordered_json s = scan_continuity_to_json(scans);
  const nlohmann::ordered_json l = latency_report_to_json(latency);
  nlohmann::ordered_json services = nlohmann::ordered_json::array();
  for (const auto& p : samples.processes)
    services.push_back(service_json(p, run, health_of(scans, p.program)));
  return {{"run",
           {{"duration_s", run.duration_s},
            {"measured_s", run.measured_s},
            {"cores", run.cores},
            {"build", run.build},
            {"log", run.log},
            {"load_average_before", run.load_average_before},
            {"load_average_after", run.load_average_after}}},
          {"scans",
           {{"published", scans.scans},
            {"expected_50hz", run.scan_rate_hz * run.duration_s},
            {"expected_50hz_over_log", std::round(run.scan_rate_hz * scans.duration_s + 1.0)},
            {"log_duration_s", scans.duration_s},
            {"expected_from_counter", scans.expected},
            {"rate_hz", scans.rate_hz},
            {"missing_counters", scans.missing},
            {"counter_gaps", scans.gap_count},
            {"duplicates", scans.duplicates},
            {"out_of_order", scans.out_of_order},
            {"unlogged_but_processed", scans.unlogged_but_processed},
            {"gaps", s["gaps"]},
            {"stages", s["stages"]},
            {"dropped", scans.dropped()}}},
          {"latency_ms", l["end_to_end"]},
          {"latency_stages_ms", l["stages"]},
          {"services", std::move(services)},
          {"checks",
           {{"no_dropped_scan", checks.no_dropped_scan},
            {"latency_p99_within_limit", checks.latency_p99_within_limit},
            {"every_service_reported", checks.every_service_reported},
            {"no_restart", checks.no_restart},
            {"max_p99_ms", checks.max_p99_ms}}},
          {"pass", checks.pass()}};
}

std::string format_load_test_report(const LoadSamples& samples, const ScanContinuityReport& scans,
                                    const LatencyReport& latency, const LoadChecks& checks) {
  const LoadRun& run = samples.run;
  std::string out =
      fmt::format("== load test result ({} s measured, {} cores, load average {} before, {} after)\n",
                  std::floor(run.measured_s), run.cores, run.load_average_before, run.load_average_after);
  out += fmt::format(
      "scans: published {} in {} s of log ({} Hz), expected {} at {} Hz over the log ({} over the nominal {} "
      "s); "
      "counter span {}, missing {} in {} gaps, duplicates {}\n",
      scans.scans, rounded(scans.duration_s, 1), rounded(scans.rate_hz, 2),
      std::round(run.scan_rate_hz * scans.duration_s + 1.0), run.scan_rate_hz,
      run.scan_rate_hz * run.duration_s, run.duration_s, scans.expected, scans.missing, scans.gap_count,
      scans.duplicates);
  for (const auto& st : scans.stages)
    out += fmt::format("  {}: {} messages, scans reached {}, without it {}\n", st.channel, st.messages,
                       st.scans_reached, st.scans_missing);
  out += fmt::format(
      "dropped scans: {} (missing counters that no later stage saw either, plus scans without a LASER_POSE; "
      "{} scans only the logger missed)\n",
      scans.dropped(), scans.unlogged_but_processed);
  const LatencyStats& e = latency.end_to_end;
  out += fmt::format("scan-to-LASER_POSE latency [ms]: p50 {}  p99 {}  max {}  ({} scans; p99 limit {})\n",
                     rounded(e.p50_ms, 3), rounded(e.p99_ms, 3), rounded(e.max_ms, 3), e.count,
                     checks.max_p99_ms > 0.0 ? fmt::format("{} ms", checks.max_p99_ms) : "none");
  std::vector<std::vector<std::string>> rows = {{"SERVICE", "CPU%", "RSS_MB", "PEAK_MB", "HB_P99_US",
                                                 "HB_MAXP99", "IN_LOGGED", "OUT_LOGGED", "DECERR",
                                                 "RESTARTS"}};
  for (const auto& p : samples.processes) {
    const ServiceHealth* h = health_of(scans, p.program);
    const double rss_mean = p.samples > 0 ? mb(p.rss_sum_kb) / static_cast<double>(p.samples) : 0.0;
    rows.push_back(
        {p.program, fmt::format("{}", rounded(cpu_percent(p, run), 1)),
         fmt::format("{}", rounded(rss_mean, 1)), fmt::format("{}", rounded(mb(p.rss_peak_kb), 1)),
         number_or_dash(h, h ? h->last_p99_us : 0.0, 0), number_or_dash(h, h ? h->max_p99_us : 0.0, 0),
         h ? fmt::format("{}", h->messages_in_logged) : "-",
         h ? fmt::format("{}", h->messages_out_logged) : "-", h ? fmt::format("{}", h->decode_errors) : "-",
         fmt::format("{}", p.pid_restarts + (h ? h->restarts : 0))});
  }
  out += aligned(rows);
  out += fmt::format(
      "checks: no_dropped_scan={} latency_p99_within_limit={} every_service_reported={} no_restart={} "
      "max_p99_ms={}\n",
      checks.no_dropped_scan, checks.latency_p99_within_limit, checks.every_service_reported,
      checks.no_restart, checks.max_p99_ms);
  out += checks.pass() ? "PASS\n" : "FAIL\n";
  return out;
}

int report_load_test(const ScanContinuityReport& scans, const LatencyReport& latency,
                     const std::string& samples_path, const std::string& report_path, bool json) {
  const LoadSamples samples = load_load_samples(samples_path);
  const LoadChecks checks = judge_load_test(samples, scans, latency);
  const auto doc = load_test_report_to_json(samples, scans, latency, checks);
  if (!report_path.empty()) {
    std::ofstream out(report_path);
    if (!(out << doc.dump(2) << "\n")) throw ConfigError(report_path + ": cannot write");
  }
  if (json) {
    std::printf("%s\n", doc.dump(2).c_str());
  } else {
    std::printf("%s", format_load_test_report(samples, scans, latency, checks).c_str());
  }
  return checks.pass() ? 0 : 1;
}

}  // namespace refloc
