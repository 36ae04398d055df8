#pragma once
// refloc-config-check --map's quick version of refloc-plan: a coarse grid over the map's own
// extent, four headings, the deployed matcher defaults; a warning when the layout localizes
// nowhere (a symmetric hall) or is ambiguous over part of its area.

#include "layout_plan.hpp"

#include <string>

namespace refloc {

/// Ambiguous over at least this share of the cells: a warning [-]. Below it are single spots where
/// noise-free detections leave a rival within the matcher's margin: on the demo hall (1 % of its
/// cells) rendered scans localized there (tools/refloc-plan/README.md); refloc-plan shows them.
inline constexpr double kAmbiguousAreaWarning = 0.05;

struct QuickLayoutCheck {
  PlanSummary summary;
  double resolution = 0.0;  ///< of the grid used [m]
  int headings = 4;         ///< [-]
  std::string warning;      ///< "" when the layout is fine
};

/// The grid has at most max_cells cells (resolution >= 0.5 m). source names the map in the text.
/// Warns when no cell relocalizes at any heading, or when kAmbiguousAreaWarning of them are ambiguous.
QuickLayoutCheck quick_layout_check(const ReflectorMap& map, const std::string& source,
                                    size_t max_cells = 400);

}  // namespace refloc
