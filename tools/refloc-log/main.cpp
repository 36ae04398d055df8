// refloc-log: what is in an LCM log (per-channel counts, rates, gaps), export
// of chosen channels to CSV or JSON lines, the scan-to-pose latency of the
// pipeline, and the load test's verdict. Reads the log with LCM's own reader.

#include "common/guarded_main.hpp"
#include "common/json_config.hpp"
#include "common/program_version.hpp"
#include "load_verdict.hpp"
#include "log_analysis.hpp"
#include "log_report.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>

namespace {

struct CommandLine {
  std::string log_path;
  refloc::LogAnalysisOptions options;
  refloc::LogExportRequest request;
  bool json = false;
  std::string load_samples, load_report;
};

void add_options(CLI::App& app, CommandLine& c) {
  app.add_option("log", c.log_path, "LCM log file (lcm-logger output)")->required();
  app.add_option(
      "--channel,-c", c.request.channel_patterns,
      "channel to export; a regular expression matching the whole name; repeatable (default: all)");
  app.add_option("--csv", c.request.csv_path,
                 "write CSV here; with several channels one file each: <stem>_<CHANNEL><ext>");
  app.add_option("--jsonl", c.request.jsonl_path,
                 "write JSON lines here (all selected channels, every field)");
  app.add_option("--gap-threshold", c.options.gap_threshold_s,
                 "list gaps between messages longer than this [s]")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  app.add_option("--max-gaps", c.options.max_gaps, "list at most this many gaps")->capture_default_str();
  app.add_flag(
      "--latency", c.options.latency,
      "scan-to-pose latency: LMS100_SCAN -> REFLECTORS -> REFLECTOR_MATCHES -> LASER_POSE matched by utime");
  app.add_option("--pipeline", c.options.pipeline_channels,
                 "pipeline channels for --latency, comma separated")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--then-next", c.options.next_channel,
                 "with --latency: end each scan at the first message on this channel logged after its last "
                 "pipeline stage (POSE: the fused pose that includes it; pair with --pipeline "
                 "LMS100_SCAN,REFLECTORS,REFLECTOR_MATCHES)");
  app.add_flag(
      "--scans", c.options.scans,
      "dropped scans: LMS100_SCAN counter gaps, scans reaching REFLECTORS/REFLECTOR_MATCHES/LASER_POSE, "
      "and every service's HEARTBEAT health (decode errors, worst handler p99, restarts)");
  app.add_flag("--json", c.json, "print the summary (and latency) as one JSON document");
  app.add_option("--load-test", c.load_samples,
                 "judge a load test: this file holds deploy/load_test.sh's /proc samples; implies --latency "
                 "--scans; prints the report (JSON with --json), exit 0 pass, 1 fail");
  app.add_option("--report", c.load_report, "with --load-test: also write the JSON report to this file");
}

int run(CommandLine c) {
  if (!c.load_samples.empty()) c.options.latency = c.options.scans = true;
  const refloc::MessageDecoder decoder;
  const auto analysis = refloc::analyze_log(c.log_path, c.options, decoder);
  if (!c.load_samples.empty())
    return refloc::report_load_test(*analysis.scans, *analysis.latency, c.load_samples, c.load_report,
                                    c.json);
  const auto exported = refloc::export_log(c.log_path, analysis.summary, c.request, decoder);
  std::printf("%s", refloc::format_log_analysis(analysis, c.json).c_str());
  std::fprintf(stderr, "%s", refloc::format_export_counts(c.request, exported).c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Summarize an LCM log, export channels to CSV/JSON lines, measure scan-to-pose latency"};
  refloc::add_version_flag(app, "refloc-log");
  CommandLine command_line;
  add_options(app, command_line);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  return refloc::guarded_main("refloc-log", [&] { return run(command_line); });
}
