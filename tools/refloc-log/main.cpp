// refloc-log: what is in an LCM log (per-channel counts, rates, gaps), export
// of chosen channels to CSV or JSON lines, the scan-to-pose latency of the
// pipeline, and the load test's verdict. Reads the log with LCM's own reader.

#include "common/guarded_main.hpp"
#include "common/json_config.hpp"
#include "load_verdict.hpp"
#include "log_analysis.hpp"
#include "log_report.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>

namespace {

/// --load-test: the verdict over the log and the run's samples; exit 0 pass, 1 fail.
int report_load_test(const refloc::LogAnalysis& analysis, const std::string& samples_path,
                     const std::string& report_path, bool json) {
  const refloc::LoadSamples samples = refloc::load_load_samples(samples_path);
  const refloc::LoadChecks checks = refloc::judge_load_test(samples, *analysis.scans, *analysis.latency);
  const auto doc = refloc::load_test_report_to_json(samples, *analysis.scans, *analysis.latency, checks);
  if (!report_path.empty()) {
    std::ofstream out(report_path);
    if (!(out << doc.dump(2) << "\n")) throw refloc::ConfigError(report_path + ": cannot write");
  }
  if (json) {
    std::printf("%s\n", doc.dump(2).c_str());
  } else {
    std::printf("%s",
                refloc::format_load_test_report(samples, *analysis.scans, *analysis.latency, checks).c_str());
  }
  return checks.pass() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Summarize an LCM log, export channels to CSV/JSON lines, measure scan-to-pose latency"};
  std::string log_path;
  refloc::LogAnalysisOptions options;
  refloc::LogExportRequest request;
  bool json = false;
  app.add_option("log", log_path, "LCM log file (lcm-logger output)")->required();
  app.add_option(
      "--channel,-c", request.channel_patterns,
      "channel to export; a regular expression matching the whole name; repeatable (default: all)");
  app.add_option("--csv", request.csv_path,
                 "write CSV here; with several channels one file each: <stem>_<CHANNEL><ext>");
  app.add_option("--jsonl", request.jsonl_path, "write JSON lines here (all selected channels, every field)");
  app.add_option("--gap-threshold", options.gap_threshold_s,
                 "list gaps between messages longer than this [s]")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  app.add_option("--max-gaps", options.max_gaps, "list at most this many gaps")->capture_default_str();
  app.add_flag(
      "--latency", options.latency,
      "scan-to-pose latency: LMS100_SCAN -> REFLECTORS -> REFLECTOR_MATCHES -> LASER_POSE matched by utime");
  app.add_option("--pipeline", options.pipeline_channels, "pipeline channels for --latency, comma separated")
      ->delimiter(',')
      ->capture_default_str();
  app.add_flag(
      "--scans", options.scans,
      "dropped scans: LMS100_SCAN counter gaps, scans reaching REFLECTORS/REFLECTOR_MATCHES/LASER_POSE, "
      "and every service's HEARTBEAT health (decode errors, worst handler p99, restarts)");
  app.add_flag("--json", json, "print the summary (and latency) as one JSON document");
  std::string load_samples, load_report;
  app.add_option("--load-test", load_samples,
                 "judge a load test: this file holds deploy/load_test.sh's /proc samples; implies --latency "
                 "--scans; prints the report (JSON with --json), exit 0 pass, 1 fail");
  app.add_option("--report", load_report, "with --load-test: also write the JSON report to this file");
  CLI11_PARSE(app, argc, argv);
  if (!load_samples.empty()) options.latency = options.scans = true;

  return refloc::guarded_main("refloc-log", [&] {
    const refloc::MessageDecoder decoder;
    const auto analysis = refloc::analyze_log(log_path, options, decoder);
    if (!load_samples.empty()) return report_load_test(analysis, load_samples, load_report, json);
    const auto exported = refloc::export_log(log_path, analysis.summary, request, decoder);
    if (json) {
      nlohmann::ordered_json doc = refloc::log_summary_to_json(analysis.summary);
      if (analysis.latency) doc["latency"] = refloc::latency_report_to_json(*analysis.latency);
      if (analysis.scans) doc["scans"] = refloc::scan_continuity_to_json(*analysis.scans);
      std::printf("%s\n", doc.dump(2).c_str());
    } else {
      std::printf("%s", refloc::format_log_summary(analysis.summary).c_str());
      if (analysis.latency) std::printf("%s", refloc::format_latency_report(*analysis.latency).c_str());
      if (analysis.scans) std::printf("%s", refloc::format_scan_continuity(*analysis.scans).c_str());
    }
    if (!request.jsonl_path.empty()) {
      std::fprintf(stderr, "%s: %lld lines (%lld not decodable) from %zu channels\n",
                   request.jsonl_path.c_str(), static_cast<long long>(exported.jsonl.written),
                   static_cast<long long>(exported.jsonl.undecoded), exported.channels.size());
    }
    for (const auto& [channel, file] : exported.csv_files) {
      std::fprintf(stderr, "%s: channel %s\n", file.c_str(), channel.c_str());
    }
    if (!request.csv_path.empty()) {
      std::fprintf(stderr, "CSV: %lld rows, %lld not decodable (skipped), %lld of a changed type (skipped)\n",
                   static_cast<long long>(exported.csv.written),
                   static_cast<long long>(exported.csv.undecoded),
                   static_cast<long long>(exported.csv.type_changed));
    }
    if ((!request.csv_path.empty() || !request.jsonl_path.empty()) && exported.channels.empty()) {
      std::fprintf(stderr, "refloc-log: warning: no channel of the log matches --channel\n");
    }
    return 0;
  });
}
