#pragma once
// Whether a reflector map looks like itself somewhere else: a rigid move, not the identity,
// that puts several reflectors onto other reflectors. In such a layout (a symmetric hall) a
// robot that sees those reflectors cannot tell the two places apart: the matcher stays
// AMBIGUOUS there, or, with a few reflectors unseen, may pick the wrong one. Found with the
// matcher's own triangle index: every map triangle against its look-alikes.

#include "common/reflector_map.hpp"
#include "common/se2.hpp"

namespace refloc {

struct MapSelfSimilarity {
  int reflectors_matched = 0;  ///< most reflectors one move puts within tolerance of another
  Pose2 move;                  ///< that move (map_T_map)
};

/// The strongest self-similarity among triangles with sides in [0.3, max_side] [m] whose look-
/// alikes agree within tolerance [m]; a move closer to the identity than 0.2 m / 5 deg does not
/// count. At most max_triangles triangles are tried (more: max_side shrinks until they fit, the
/// triangle index's own rule).
MapSelfSimilarity find_map_self_similarity(const ReflectorMap& map, double tolerance = 0.05,
                                           double max_side = 16.0, size_t max_triangles = 20000);

}  // namespace refloc
