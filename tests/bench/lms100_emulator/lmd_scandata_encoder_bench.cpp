// Cost of the emulator's per-scan work outside the renderer: writing one
// LMDscandata telegram, and answering a status request.

#include "lms100_emulator/lmd_scandata_encoder.hpp"
#include "lms100_emulator/lms100_device.hpp"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace refloc {
namespace {

void BM_EncodeLmdScandata(benchmark::State& state) {
  const auto beams = static_cast<size_t>(state.range(0));
  const int rssi_bits = static_cast<int>(state.range(1));
  std::vector<uint16_t> dist(beams), rssi(beams);
  for (size_t i = 0; i < beams; ++i) {
    dist[i] = static_cast<uint16_t>(500 + (i * 37) % 19000);
    rssi[i] = static_cast<uint16_t>(rssi_bits == 8 ? (i * 13) % 256 : (i * 911) % 65536);
  }
  LmdTelegramHeader header;
  LmdBeamLayout layout;
  layout.step_1e4deg = beams > 541 ? 2500 : 5000;
  LmdOutputOptions options;
  options.rssi_bits = rssi_bits;
  options.send_time_info = true;
  std::string out;
  for (auto _ : state) {
    encode_lmd_scandata(header, layout, dist.data(), rssi.data(), beams, options, out);
    benchmark::DoNotOptimize(out.data());
    ++header.telegram_counter;
  }
  state.counters["bytes"] = static_cast<double>(out.size());
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * out.size()));
}
BENCHMARK(BM_EncodeLmdScandata)->Args({541, 16})->Args({541, 8})->Args({541, 0})->Args({1081, 16});

void BM_DeviceAnswersStlms(benchmark::State& state) {
  Lms100Device device{Lms100DeviceConfig{}};
  std::string reply;
  uint64_t now = 1000000;
  for (auto _ : state) {
    device.handle_request("sRN STlms", now, reply);
    benchmark::DoNotOptimize(reply.data());
    now += 1000;
  }
}
BENCHMARK(BM_DeviceAnswersStlms);

}  // namespace
}  // namespace refloc

BENCHMARK_MAIN();
