// libFuzzer entry: arbitrary bytes as a config file through JsonConfig::parse_text (the
// checks load_file applies after reading: size, nesting depth, JSON), then the readers a
// service calls and reject_unknown_keys. A bad file must end in ConfigError (main turns it
// into exit 2 and one line); any other exception, a crash or a stack overflow is a finding.

#include "common/json_config.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const refloc::JsonConfig config = refloc::JsonConfig::parse_text(text, "fuzz.json");
    (void)config.number("/clustering/range_sigma_m", 0.012, 1e-6, 1.0);
    (void)config.integer("/energy_threshold_8bit", 200, 0, 255);
    (void)config.boolean("/enabled", true);
    (void)config.string("/name", "x");
    (void)config.choice("/mode", "default", {"default", "paper"});
    if (config.has("/list")) (void)config.array_size("/list");
    config.reject_unknown_keys();
  } catch (const refloc::ConfigError&) {
  }
  return 0;
}
