#include "reflector_matcher/triangle_signature.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

LargestAngleSignature largest_angle_signature(const std::array<Eigen::Vector2d, 3>& p) {
  LargestAngleSignature best;
  best.largest_angle = -1.0;
  for (int apex = 0; apex < 3; ++apex) {
    const int a = (apex + 1) % 3, b = (apex + 2) % 3;
    const Eigen::Vector2d u = p[a] - p[apex], v = p[b] - p[apex];
    // atan2 of cross and dot stays accurate near 0 and pi, unlike acos of the cosine rule.
    const double angle = std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
    if (angle > best.largest_angle) {
      best.largest_angle = angle;
      best.apex = apex;
      const double nu = u.norm(), nv = v.norm();
      best.long_end = nu >= nv ? a : b;
      best.short_end = nu >= nv ? b : a;
      best.long_side = std::max(nu, nv);
      best.short_side = std::min(nu, nv);
    }
  }
  return best;
}

bool signatures_match(const LargestAngleSignature& a, const LargestAngleSignature& b, double side_tol,
                      double angle_tol) {
  return std::abs(a.largest_angle - b.largest_angle) <= angle_tol &&
         std::abs(a.long_side - b.long_side) <= side_tol && std::abs(a.short_side - b.short_side) <= side_tol;
}

SortedSides sorted_sides(const std::array<Eigen::Vector2d, 3>& p) {
  SortedSides s;
  // Side k is opposite vertex k: it joins the two other vertices.
  std::array<double, 3> len = {(p[1] - p[2]).norm(), (p[0] - p[2]).norm(), (p[0] - p[1]).norm()};
  std::array<int, 3> order = {0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return len[i] < len[j]; });
  for (int k = 0; k < 3; ++k) {
    s.side[k] = len[order[k]];
    s.opposite[k] = order[k];
  }
  return s;
}

}  // namespace refloc
