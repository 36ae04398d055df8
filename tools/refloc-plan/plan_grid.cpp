#include "plan_grid.hpp"

#include <cmath>
#include <stdexcept>

namespace refloc {
namespace {

double polygon_area(const std::vector<Eigen::Vector2d>& points) {
  double twice = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d& a = points[i];
    const Eigen::Vector2d& b = points[(i + 1) % points.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twice);
}

}  // namespace

bool inside_polygon(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& map_p) {
  bool inside = false;
  if (points.size() < 3) return false;
  for (size_t i = 0, j = points.size() - 1; i < points.size(); j = i++) {
    const Eigen::Vector2d& a = points[i];
    const Eigen::Vector2d& b = points[j];
    if ((a.y() > map_p.y()) != (b.y() > map_p.y()) &&
        map_p.x() < (b.x() - a.x()) * (map_p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

PlanGrid make_plan_grid(const ReflectorMap& map, const std::vector<sim::DrivableArea>& drivable,
                        double resolution, size_t max_cells) {
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw std::invalid_argument("grid resolution must be > 0 m");
  }
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
  const auto extend = [&](const Eigen::Vector2d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  if (!drivable.empty()) {
    for (const auto& a : drivable) {
      extend({a.x_min, a.y_min});
      extend({a.x_max, a.y_max});
    }
  } else {
    for (const auto& r : map.reflectors) extend(r.map_p_center);
    for (const auto& o : map.occluders) {
      for (const auto& p : o.map_points) extend(p);
    }
  }
  PlanGrid grid;
  grid.resolution = resolution;
  grid.origin = lo;
  const double columns = std::ceil((hi.x() - lo.x()) / resolution);
  const double rows = std::ceil((hi.y() - lo.y()) / resolution);
  if (columns * rows > static_cast<double>(max_cells)) {
    throw std::invalid_argument("grid of " + std::to_string(static_cast<long long>(columns * rows)) +
                                " cells is more than " + std::to_string(max_cells) +
                                ": raise the resolution");
  }
  grid.columns = std::max(1, static_cast<int>(columns));
  grid.rows = std::max(1, static_cast<int>(rows));
  const double box_area = (hi.x() - lo.x()) * (hi.y() - lo.y());
  std::vector<const MapOccluder*> solid;  // racks and pillars, not the hall's outline
  for (const auto& o : map.occluders) {
    if (o.closed && o.map_points.size() >= 3 && polygon_area(o.map_points) < 0.5 * box_area)
      solid.push_back(&o);
  }
  for (int r = 0; r < grid.rows; ++r) {
    for (int c = 0; c < grid.columns; ++c) {
      const Eigen::Vector2d p = lo + resolution * Eigen::Vector2d(c + 0.5, r + 0.5);
      bool keep = drivable.empty();
      for (const auto& a : drivable) keep = keep || a.contains(p);
      for (const MapOccluder* o : solid) keep = keep && !inside_polygon(o->map_points, p);
      if (keep) grid.map_p_cells.push_back(p);
    }
  }
  return grid;
}

}  // namespace refloc
