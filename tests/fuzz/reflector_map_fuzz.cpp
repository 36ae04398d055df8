// libFuzzer entry: arbitrary bytes as a map file through JsonConfig::parse_text and
// parse_reflector_map (the validation load_reflector_map applies: ids, finite coordinates,
// radii, spacing, colinearity). A bad map must end in ConfigError; anything else is a finding.

#include "common/json_config.hpp"
#include "common/reflector_map.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const refloc::JsonConfig config = refloc::JsonConfig::parse_text(text, "fuzz_map.json");
    const refloc::ReflectorMap map = refloc::parse_reflector_map(config);
    (void)map.index_of(1);
  } catch (const refloc::ConfigError&) {
  }
  return 0;
}
