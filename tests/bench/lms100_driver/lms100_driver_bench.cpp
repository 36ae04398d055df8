// Parse time of a 541-beam LMDscandata telegram with 16-bit RSSI (the LMS100's
// 50 Hz / 0.5 deg stream), and of the steps around it.

#include <benchmark/benchmark.h>

#include <fmt/format.h>

#include <string>
#include <vector>

#include "common/laser_scan.hpp"
#include "lms100_driver/cola_a_format.hpp"
#include "lms100_driver/cola_a_splitter.hpp"
#include "lms100_driver/lmd_scandata_parser.hpp"
#include "lms100_driver/scan_conversion.hpp"

namespace {

std::string make_telegram(int beams) {
  auto channel = [beams](const char* name, unsigned base) {
    std::string s = fmt::format("{} 3F800000 00000000 FFF92230 1388 {:X}", name, beams);
    for (int i = 0; i < beams; ++i) s += fmt::format(" {:X}", base + static_cast<unsigned>((i * 37) % 4000));
    return s;
  };
  return "sSN LMDscandata 1 1 8D4C04 0 0 45FF 37 280F6 28A73 0 0 7 0 0 1388 168 0 2 " +
         channel("DIST1", 500) + " " + channel("RSSI1", 20000) + " 0 0 0 0 1 7EA B 1C 13 5 7 1E240 0";
}

void BM_ParseLmdScandata541Rssi16(benchmark::State& state) {
  const std::string telegram = make_telegram(541);
  refloc::LmdScanData data;
  for (auto _ : state) {
    const auto r = refloc::parse_lmd_scandata(telegram, data);
    benchmark::DoNotOptimize(r);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * telegram.size()));
}
BENCHMARK(BM_ParseLmdScandata541Rssi16);

void BM_ParseAndConvert541Rssi16(benchmark::State& state) {
  const std::string telegram = make_telegram(541);
  refloc::LmdScanData data;
  refloc::LaserScan scan;
  for (auto _ : state) {
    const auto r = refloc::parse_lmd_scandata(telegram, data);
    const auto c = refloc::to_laser_scan(data, scan);
    benchmark::DoNotOptimize(r);
    benchmark::DoNotOptimize(c);
  }
}
BENCHMARK(BM_ParseAndConvert541Rssi16);

void BM_SplitAndParse1081Rssi16(benchmark::State& state) {
  const std::string framed = refloc::frame_cola_a(make_telegram(1081));
  refloc::ColaASplitter splitter;
  refloc::LmdScanData data;
  std::string payload;
  for (auto _ : state) {
    splitter.feed(reinterpret_cast<const uint8_t*>(framed.data()), framed.size());
    while (splitter.next(payload)) benchmark::DoNotOptimize(refloc::parse_lmd_scandata(payload, data));
  }
}
BENCHMARK(BM_SplitAndParse1081Rssi16);

}  // namespace

BENCHMARK_MAIN();
