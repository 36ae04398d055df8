// Writes the seed corpus of the LCM decode fuzz targets: per type a message with every
// variable array 0, 1 and 3 long (fill_lcm_sample), fingerprint first as on the bus.
//   lcm_fuzz_seeds OUT_DIR   ->  OUT_DIR/lcm_<type>_fuzz/n<k>.lcm

#include <refloc_lcm_samples.hpp>
#include <refloc_lcm_schemas.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

template <class Message>
void write_seeds(const std::filesystem::path& out, const char* type_name) {
  const std::filesystem::path dir = out / (std::string("lcm_") + type_name + "_fuzz");
  std::filesystem::create_directories(dir);
  for (int32_t n : {0, 1, 3}) {
    Message m{};
    refloc::fill_lcm_sample(m, n);
    std::vector<char> bytes(static_cast<size_t>(m.getEncodedSize()));
    m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    std::ofstream(dir / ("n" + std::to_string(n) + ".lcm"), std::ios::binary)
        .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
    return 64;
  }
#define REFLOC_WRITE_SEEDS(type) write_seeds<refloc::type>(argv[1], #type);
  REFLOC_LCM_TYPES(REFLOC_WRITE_SEEDS)
#undef REFLOC_WRITE_SEEDS
  return 0;
}
