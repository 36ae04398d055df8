#pragma once
// Where to add reflectors: candidate positions along the mounting lines (the occluders the
// plan uses: walls, racks, pillars), a reflector's radius off the line on the side the robot
// drives, and a choice of K that leaves the fewest ambiguous poses, then the fewest bad ones
// (blind, ambiguous, lost or above the CRLB limit): greedy, then swaps of one chosen position for
// another candidate while that improves the layout. Each trial is planned on a (coarser) grid
// with the map it would make.

#include "layout_plan.hpp"

#include <vector>

namespace refloc {

struct SuggestionConfig {
  int count = 0;            ///< reflectors to add, K [-]
  double spacing = 1.0;     ///< between candidates along a mounting line [m]
  double radius = 0.06;     ///< of the added reflectors [m]
  double resolution = 0.5;  ///< grid the choice is planned on [m]
  int headings = 8;         ///< headings the choice is planned at (ambiguity is heading-specific) [-]
  /// Rounds of swaps after the greedy choice (each tries every candidate in each chosen place;
  /// they stop early when a round changes nothing) [-].
  int swap_rounds = 2;
};

/// What a layout leaves to fix on the suggestion grid, ambiguity first: an ambiguous pose may
/// give a fix at the wrong place, where a blind or inaccurate one gives none or a poor one.
struct SuggestionScore {
  int ambiguous_poses = 0;  ///< (cell, heading) poses AMBIGUOUS or relocalized wrong [-]
  int bad_poses = 0;        ///< CellPlan::headings_bad summed [-]
  double poses = 1.0;       ///< all (cell, heading) poses, for fractions [-]
};

/// a leaves fewer ambiguous poses than b, or as many and fewer bad ones.
bool better(const SuggestionScore& a, const SuggestionScore& b);

struct Suggestion {
  MapReflector reflector;               ///< id above the map's largest
  double bad_poses_before = 0.0;        ///< PlanSummary::bad_poses before adding it (suggestion grid) [-]
  double bad_poses_after = 0.0;         ///< and after [-]
  double ambiguous_poses_before = 0.0;  ///< share of ambiguous poses before adding it [-]
  double ambiguous_poses_after = 0.0;   ///< and after [-]
};

/// Candidate centres along every occluder segment, spacing apart, on each side at radius plus
/// kMinReflectorGap_m from the line; a side is kept when it lies inside (outside) each closed
/// occluder as most grid cells do, and it keeps its distance from the map's reflectors.
std::vector<Eigen::Vector2d> candidate_positions(const ReflectorMap& map, const PlanGrid& grid,
                                                 const SuggestionConfig& config);

/// Greedy: K times, the candidate whose addition leaves the best SuggestionScore (ties: the
/// first); stops early when no candidate helps. Then swap_rounds rounds: each chosen position
/// in turn is replaced by the candidate that improves the score most, if any. The suggestions
/// keep the greedy order; their before/after figures are for adding them in that order.
/// progress gets (plans done, plans in all).
std::vector<Suggestion> suggest_reflectors(const ReflectorMap& map,
                                           const std::vector<sim::DrivableArea>& drivable,
                                           const PlanConfig& plan_config, const SuggestionConfig& config,
                                           const PlanProgress& progress = {});

/// map with the suggested reflectors appended.
ReflectorMap with_suggestions(ReflectorMap map, const std::vector<Suggestion>& suggestions);

}  // namespace refloc
