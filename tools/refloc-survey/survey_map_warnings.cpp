#include "survey_map_warnings.hpp"

#include "reflector_matcher/map_self_similarity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace refloc {

std::string self_similar_map_warning(const ReflectorMap& map) {
  // Three reflectors always match (the triangle the move was fitted to). Walls with evenly spaced
  // reflectors give partial look-alikes (demo hall: 6 of 24, where the matcher works); half
  // the map or more is a symmetric layout (the symmetric hall: 12 of 12, never localized).
  const MapSelfSimilarity s = find_map_self_similarity(map);
  const int n = static_cast<int>(map.reflectors.size());
  if (s.reflectors_matched < std::max(4, (n + 1) / 2)) return "";
  return fmt::format(
      "the map looks like itself moved by ({:+.2f} m, {:+.2f} m, {:+.1f} deg): {} of its {} reflectors land "
      "within 5 cm of others. Where a robot sees only those, localization cannot tell the two places "
      "apart (AMBIGUOUS, or a wrong fix when others are hidden); add reflectors that break the symmetry",
      s.move.x, s.move.y, s.move.theta * 180.0 / M_PI, s.reflectors_matched, map.reflectors.size());
}

}  // namespace refloc
