#pragma once
// Where to add reflectors: candidate positions along the mounting lines (the occluders the
// plan uses: walls, racks, pillars), a reflector's radius off the line on the side the robot
// drives, and a greedy choice of the K that most reduce the bad area (blind, ambiguous, lost or
// above the CRLB limit), each choice planned on a (coarser) grid with the map it would make.

#include "layout_plan.hpp"

#include <vector>

namespace refloc {

struct SuggestionConfig {
  int count = 0;            ///< reflectors to add, K [-]
  double spacing = 1.0;     ///< between candidates along a mounting line [m]
  double radius = 0.06;     ///< of the added reflectors [m]
  double resolution = 0.5;  ///< grid the choice is planned on [m]
  int headings = 4;         ///< headings the choice is planned at [-]
};

struct Suggestion {
  MapReflector reflector;         ///< id above the map's largest
  double bad_poses_before = 0.0;  ///< PlanSummary::bad_poses before adding it (suggestion grid) [-]
  double bad_poses_after = 0.0;   ///< and after [-]
};

/// Candidate centres along every occluder segment, spacing apart, on each side at radius plus
/// kMinReflectorGap_m from the line; a side is kept when it lies inside (outside) each closed
/// occluder as most grid cells do, and it keeps its distance from the map's reflectors.
std::vector<Eigen::Vector2d> candidate_positions(const ReflectorMap& map, const PlanGrid& grid,
                                                 const SuggestionConfig& config);

/// Greedy: K times, the candidate whose addition leaves the fewest bad poses (PlanSummary::
/// bad_poses; ties: the first).
/// progress gets (plans done, plans in all). Stops early when no candidate helps.
std::vector<Suggestion> suggest_reflectors(const ReflectorMap& map,
                                           const std::vector<sim::DrivableArea>& drivable,
                                           const PlanConfig& plan_config, const SuggestionConfig& config,
                                           const PlanProgress& progress = {});

/// map with the suggested reflectors appended.
ReflectorMap with_suggestions(ReflectorMap map, const std::vector<Suggestion>& suggestions);

}  // namespace refloc
