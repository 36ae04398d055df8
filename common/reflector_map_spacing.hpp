#pragma once
// The map reader's spacing check: reflectors that would touch are refused as they are read.

#include "common/reflector_map.hpp"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace refloc {

class JsonConfig;

/// Refuses the first reflector that stands closer than r1 + r2 + kMinReflectorGap_m to an
/// earlier one, as the map is read, so a pile at one spot fails at its second reflector. Grid
/// cells are at least as wide as the largest pair distance that can fail, so only the 3x3 cells
/// around a reflector can hold one too close; a larger radius regrids with doubled cells (at
/// most log2(5 m / 1 mm) times).
class SpacingCheck {
 public:
  /// list is the pointer of the reflector array, for messages.
  SpacingCheck(const JsonConfig& config, std::string list) : config_(config), list_(std::move(list)) {}

  /// Checks reflectors.back() against the earlier ones; throws ConfigError naming both.
  void add(const std::vector<MapReflector>& reflectors);

 private:
  int64_t cell_of(double v) const;
  void regrid(const std::vector<MapReflector>& reflectors, double cell);
  void check_pair(const std::vector<MapReflector>& reflectors, size_t i, size_t j) const;

  const JsonConfig& config_;
  std::string list_;
  double max_radius_ = 0.0;
  double cell_ = 0.0;
  std::unordered_map<uint64_t, std::vector<size_t>> grid_;
};

}  // namespace refloc
