#include "quick_layout_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace refloc {

QuickLayoutCheck quick_layout_check(const ReflectorMap& map, const std::string& source, size_t max_cells) {
  QuickLayoutCheck check;
  Eigen::Vector2d lo = map.reflectors.front().map_p_center, hi = lo;
  for (const auto& r : map.reflectors) {
    lo = lo.cwiseMin(r.map_p_center);
    hi = hi.cwiseMax(r.map_p_center);
  }
  for (const auto& o : map.occluders) {
    for (const auto& p : o.map_points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  const double area = std::max((hi.x() - lo.x()) * (hi.y() - lo.y()), 1e-6);
  check.resolution = std::max(0.5, std::sqrt(area / static_cast<double>(max_cells)));
  PlanConfig config;
  config.resolution = check.resolution;
  config.headings = check.headings;
  config.spot = BeamSpotModel::point_beam();  // the warning reads no bound: the cheapest one
  const LayoutPlan plan = plan_layout(map, make_plan_grid(map, {}, check.resolution), config);
  check.summary = plan.summary;
  const PlanSummary& s = plan.summary;
  const std::string figures = fmt::format(
      "blind {:.0f} %, ambiguous {:.0f} %, no fix {:.0f} % of {} cells of {:.2g} m over the map's "
      "extent, {} headings (refloc-plan draws where)",
      100.0 * s.blind, 100.0 * s.ambiguous, 100.0 * s.lost, s.cells, check.resolution, check.headings);
  const bool nowhere = std::none_of(plan.cells.begin(), plan.cells.end(),
                                    [](const CellPlan& c) { return c.headings_unique > 0; });
  if (plan.cells.empty() || nowhere) {
    check.warning = fmt::format("{}: the layout localizes nowhere: {}", source, figures);
  } else if (s.ambiguous >= kAmbiguousAreaWarning) {
    check.warning = fmt::format(
        "{}: the layout is ambiguous over part of its area (the matcher may take one place for "
        "another): {}",
        source, figures);
  }
  return check;
}

}  // namespace refloc
