#pragma once
// Warnings about a surveyed map's layout that the survey itself cannot see as errors: a map is
// written with them, never as a silent success.

#include "common/reflector_map.hpp"

#include <string>

namespace refloc {

/// "" unless a rigid move (other than the identity) puts half of the map's reflectors (and at
/// least 4) onto others within 5 cm; else a sentence naming the move, how many reflectors it matches, and
/// what it means for localization (reflector_matcher's find_map_self_similarity).
std::string self_similar_map_warning(const ReflectorMap& map);

}  // namespace refloc
