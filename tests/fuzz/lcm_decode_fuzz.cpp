// libFuzzer entry, built once per LCM type (REFLOC_FUZZ_LCM_TYPE names it): arbitrary bytes,
// and the same bytes behind the type's true fingerprint, through decode_lcm_bounded, the
// guarded decode every subscription and tool uses. Beyond "no crash, no huge allocation"
// (-rss_limit_mb / -malloc_limit_mb) it checks the bounds check against lcm-gen's decoder:
// what the check accepts must decode, and must encode back to exactly the same bytes.

#include "common/lcm_bounded_decode.hpp"

#include <refloc_lcm_samples.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace {

using Message = refloc::REFLOC_FUZZ_LCM_TYPE;

void decode_and_compare(const uint8_t* data, size_t size) {
  Message message{};
  const refloc::LcmDecodeResult result = refloc::decode_lcm_bounded(data, size, message);
  if (!result.ok) {
    // The check refused it: fine. The decoder refusing what the check accepted is a bug.
    if (result.reason.rfind("lcm-gen", 0) == 0) std::abort();
    return;
  }
  const int encoded_size = message.getEncodedSize();
  if (encoded_size < 0 || static_cast<size_t>(encoded_size) != size) std::abort();
  std::vector<uint8_t> encoded(size);
  if (message.encode(encoded.data(), 0, encoded_size) != encoded_size) std::abort();
  for (size_t i = 0; i < size; ++i)
    if (encoded[i] != data[i]) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  decode_and_compare(data, size);
  std::vector<uint8_t> with_fingerprint(8 + size);
  const auto fingerprint = static_cast<uint64_t>(Message::getHash());
  for (size_t i = 0; i < 8; ++i) with_fingerprint[i] = static_cast<uint8_t>(fingerprint >> (56 - 8 * i));
  for (size_t i = 0; i < size; ++i) with_fingerprint[8 + i] = data[i];
  decode_and_compare(with_fingerprint.data(), with_fingerprint.size());
  return 0;
}
