#include "reflector_matcher/occluder_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace refloc {
namespace {

double cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

/// Liang-Barsky: the part of p + t (q - p), t in [t0, t1], inside the box; false when none.
bool clip_to_box(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& lo,
                 const Eigen::Vector2d& hi, double& t0, double& t1) {
  const Eigen::Vector2d d = q - p;
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0) {
      if (p[axis] < lo[axis] || p[axis] > hi[axis]) return false;
      continue;
    }
    double ta = (lo[axis] - p[axis]) / d[axis], tb = (hi[axis] - p[axis]) / d[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

OccluderGrid::OccluderGrid(const std::vector<MapOccluder>& occluders, double cell_size)
    : cell_size_(cell_size) {
  for (const MapOccluder& o : occluders) {
    const size_t n = o.map_points.size();
    for (size_t i = 0; i + 1 < n; ++i) segments_.push_back({o.map_points[i], o.map_points[i + 1]});
    if (o.closed && n > 2) segments_.push_back({o.map_points[n - 1], o.map_points[0]});
  }
  if (segments_.empty()) return;
  Eigen::Vector2d lo = segments_.front().a, hi = lo;
  for (const Segment& s : segments_) {
    lo = lo.cwiseMin(s.a).cwiseMin(s.b);
    hi = hi.cwiseMax(s.a).cwiseMax(s.b);
  }
  // Bounded like MapGrid: a few segments kilometres apart must not make millions of cells.
  constexpr double kMaxCells = 4e6;
  const Eigen::Vector2d extent = hi - lo;
  while ((extent.x() / cell_size_ + 1) * (extent.y() / cell_size_ + 1) > kMaxCells) cell_size_ *= 2.0;
  origin_ = lo;
  nx_ = static_cast<int>(extent.x() / cell_size_) + 1;
  ny_ = static_cast<int>(extent.y() / cell_size_) + 1;
  cell_begin_.assign(static_cast<size_t>(nx_) * static_cast<size_t>(ny_) + 1, 0);
  // Two passes over the same cells: count, then fill (CSR, one allocation).
  for (uint32_t s = 0; s < segments_.size(); ++s) insert(s, false);
  for (size_t c = 0; c + 1 < cell_begin_.size(); ++c) cell_begin_[c + 1] += cell_begin_[c];
  items_.resize(cell_begin_.back());
  for (uint32_t s = 0; s < segments_.size(); ++s) insert(s, true);
  // The fill pass advanced each cell's begin to the next cell's: shift back.
  for (size_t c = cell_begin_.size() - 1; c > 0; --c) cell_begin_[c] = cell_begin_[c - 1];
  cell_begin_[0] = 0;
}

void OccluderGrid::insert(uint32_t segment, bool fill) {
  // A segment goes into every cell whose box, padded a little, it meets: a line crossing it
  // at a cell edge finds it from either side despite rounding in the walk.
  const Segment& s = segments_[segment];
  const double pad = 1e-6 * cell_size_;
  const auto cell = [&](double v, double o, int n) {
    return std::clamp(static_cast<int>(std::floor((v - o) / cell_size_)), 0, n - 1);
  };
  const int x0 = cell(std::min(s.a.x(), s.b.x()) - pad, origin_.x(), nx_);
  const int x1 = cell(std::max(s.a.x(), s.b.x()) + pad, origin_.x(), nx_);
  const int y0 = cell(std::min(s.a.y(), s.b.y()) - pad, origin_.y(), ny_);
  const int y1 = cell(std::max(s.a.y(), s.b.y()) + pad, origin_.y(), ny_);
  for (int cy = y0; cy <= y1; ++cy) {
    for (int cx = x0; cx <= x1; ++cx) {
      const Eigen::Vector2d lo =
          origin_ + cell_size_ * Eigen::Vector2d(cx, cy) - Eigen::Vector2d::Constant(pad);
      const Eigen::Vector2d hi = lo + Eigen::Vector2d::Constant(cell_size_ + 2.0 * pad);
      double t0 = 0.0, t1 = 1.0;
      if (!clip_to_box(s.a, s.b, lo, hi, t0, t1)) continue;
      const size_t c = static_cast<size_t>(cy) * static_cast<size_t>(nx_) + static_cast<size_t>(cx);
      if (fill) {
        items_[cell_begin_[c]++] = segment;
      } else {
        ++cell_begin_[c + 1];
      }
    }
  }
}

bool OccluderGrid::blocks(const Eigen::Vector2d& map_p_from, const Eigen::Vector2d& map_p_to) const {
  if (segments_.empty()) return false;
  const Eigen::Vector2d& p = map_p_from;
  const Eigen::Vector2d d = map_p_to - p;
  const auto crosses = [&](const Segment& s) {
    const Eigen::Vector2d e = s.b - s.a;
    if (cross(e, p - s.a) * cross(e, map_p_to - s.a) >= 0.0) return false;
    return cross(d, s.a - p) * cross(d, s.b - p) <= 0.0;
  };
  double t0 = 0.0, t1 = 1.0;
  const Eigen::Vector2d hi = origin_ + cell_size_ * Eigen::Vector2d(nx_, ny_);
  if (!clip_to_box(p, map_p_to, origin_, hi, t0, t1)) return false;
  // Amanatides-Woo: visit the cells the line crosses, in order, from where it enters the grid.
  const Eigen::Vector2d start = p + t0 * d;
  int ix = std::clamp(static_cast<int>(std::floor((start.x() - origin_.x()) / cell_size_)), 0, nx_ - 1);
  int iy = std::clamp(static_cast<int>(std::floor((start.y() - origin_.y()) / cell_size_)), 0, ny_ - 1);
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const int step_x = d.x() > 0.0 ? 1 : (d.x() < 0.0 ? -1 : 0);
  const int step_y = d.y() > 0.0 ? 1 : (d.y() < 0.0 ? -1 : 0);
  const auto next_edge = [&](int step, int i, double o, double pv, double dv) {
    return step == 0 ? kNever : (o + (i + (step > 0 ? 1 : 0)) * cell_size_ - pv) / dv;
  };
  double t_next_x = next_edge(step_x, ix, origin_.x(), p.x(), d.x());
  double t_next_y = next_edge(step_y, iy, origin_.y(), p.y(), d.y());
  const double t_delta_x = step_x == 0 ? kNever : cell_size_ / std::abs(d.x());
  const double t_delta_y = step_y == 0 ? kNever : cell_size_ / std::abs(d.y());
  while (true) {
    const size_t c = static_cast<size_t>(iy) * static_cast<size_t>(nx_) + static_cast<size_t>(ix);
    for (uint32_t k = cell_begin_[c]; k < cell_begin_[c + 1]; ++k) {
      if (crosses(segments_[items_[k]])) return true;
    }
    if (t_next_x < t_next_y) {
      if (t_next_x > t1) return false;
      ix += step_x;
      t_next_x += t_delta_x;
    } else {
      if (t_next_y > t1) return false;
      iy += step_y;
      t_next_y += t_delta_y;
    }
    if (ix < 0 || ix >= nx_ || iy < 0 || iy >= ny_) return false;
  }
}

}  // namespace refloc
