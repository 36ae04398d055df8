// refloc-log speed on a synthetic 60 s log like a live robot's: LMS100_SCAN at
// 25 Hz (541 beams with RSSI), REFLECTORS / REFLECTOR_MATCHES / LASER_POSE per
// scan, POSE and ODOMETRY at 100 Hz. Reports events/s and bytes/s.

#include "log_analysis.hpp"

#include <benchmark/benchmark.h>
#include <unistd.h>
#include <lcm/lcm-cpp.hpp>
#include <refloc/laser_scan_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_matches_t.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace refloc {
namespace {

template <class Message>
void write(lcm::LogFile& log, const std::string& channel, int64_t t, const Message& m) {
  std::vector<uint8_t> bytes(static_cast<size_t>(m.getEncodedSize()));
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  lcm::LogEvent e{};
  e.timestamp = t;
  e.channel = channel;
  e.datalen = static_cast<int32_t>(bytes.size());
  e.data = bytes.data();
  log.writeEvent(&e);
}

struct SyntheticLog {
  std::string path = "/tmp/refloc_log_bench_" + std::to_string(getpid()) + ".lcmlog";
  int64_t events = 0;
  int64_t bytes = 0;

  explicit SyntheticLog(double duration_s) {
    auto log = std::make_unique<lcm::LogFile>(path, "w");
    const int64_t t0 = 1'700'000'000'000'000;
    const auto ticks = static_cast<int64_t>(duration_s * 100);
    for (int64_t k = 0; k < ticks; ++k) {
      const int64_t t = t0 + k * 10'000;
      if (k % 4 == 0) {
        laser_scan_t scan{};
        scan.utime = t;
        scan.ranges.assign(541, 4.2f);
        scan.nranges = 541;
        scan.rssi.assign(541, 180);
        scan.nrssi = 541;
        write(*log, "LMS100_SCAN", t + 1'000, scan);
        reflector_detections_t det{};
        det.utime = t;
        det.reflectors.resize(6);
        det.nreflectors = 6;
        write(*log, "REFLECTORS", t + 2'500, det);
        reflector_matches_t matches{};
        matches.utime = t;
        matches.matches.resize(6);
        matches.nmatches = 6;
        write(*log, "REFLECTOR_MATCHES", t + 3'500, matches);
        pose2d_t laser_pose{};
        laser_pose.utime = t;
        write(*log, "LASER_POSE", t + 4'000, laser_pose);
        events += 4;
      }
      pose2d_t pose{};
      pose.utime = t;
      write(*log, "POSE", t + 500, pose);
      odometry_t odom{};
      odom.utime = t;
      write(*log, "ODOMETRY", t + 200, odom);
      events += 2;
    }
    log.reset();
    if (FILE* f = std::fopen(path.c_str(), "rb")) {
      std::fseek(f, 0, SEEK_END);
      bytes = std::ftell(f);
      std::fclose(f);
    }
  }
  ~SyntheticLog() { std::remove(path.c_str()); }
};

void report(benchmark::State& state, const SyntheticLog& log) {
  state.SetItemsProcessed(state.iterations() * log.events);
  state.SetBytesProcessed(state.iterations() * log.bytes);
}

void BM_AnalyzeWithLatency(benchmark::State& state) {
  const SyntheticLog log(60.0);
  const MessageDecoder decoder;
  LogAnalysisOptions options;
  options.latency = true;
  for (auto _ : state) benchmark::DoNotOptimize(analyze_log(log.path, options, decoder));
  report(state, log);
}
BENCHMARK(BM_AnalyzeWithLatency)->Unit(benchmark::kMillisecond);

void BM_ExportAllJsonl(benchmark::State& state) {
  const SyntheticLog log(60.0);
  const MessageDecoder decoder;
  const auto summary = analyze_log(log.path, {}, decoder).summary;
  const std::string out = log.path + ".jsonl";
  for (auto _ : state) benchmark::DoNotOptimize(export_log(log.path, summary, {{}, out, ""}, decoder));
  std::remove(out.c_str());
  report(state, log);
}
BENCHMARK(BM_ExportAllJsonl)->Unit(benchmark::kMillisecond);

void BM_ExportScansCsv(benchmark::State& state) {
  const SyntheticLog log(60.0);
  const MessageDecoder decoder;
  const auto summary = analyze_log(log.path, {}, decoder).summary;
  const std::string out = log.path + ".csv";
  for (auto _ : state)
    benchmark::DoNotOptimize(export_log(log.path, summary, {{"LMS100_SCAN"}, "", out}, decoder));
  std::remove(out.c_str());
  report(state, log);
}
BENCHMARK(BM_ExportScansCsv)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace refloc

BENCHMARK_MAIN();
