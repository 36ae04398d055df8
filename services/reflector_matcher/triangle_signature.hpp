#pragma once
// Rigid-motion invariants of a triangle of reflectors, used to recognise the
// same three reflectors in the laser frame and in the map.

#include <Eigen/Core>

#include <array>

namespace refloc {

/// The paper's §3.5 signature: the largest angle and the two sides adjacent to it.
/// Vertex roles: apex holds the largest angle, long_end ends the longer adjacent side.
struct LargestAngleSignature {
  double largest_angle = 0.0;  ///< [rad]
  double long_side = 0.0;      ///< [m] apex to long_end
  double short_side = 0.0;     ///< [m] apex to short_end
  int apex = 0;                ///< index (0..2) of the input vertex at the largest angle
  int long_end = 1;
  int short_end = 2;
};

/// Signature of the triangle p[0], p[1], p[2] (invariant to rotation, translation and order).
LargestAngleSignature largest_angle_signature(const std::array<Eigen::Vector2d, 3>& p);

/// Both signatures within tolerance: |angle difference| <= angle_tol [rad], sides <= side_tol [m].
bool signatures_match(const LargestAngleSignature& a, const LargestAngleSignature& b, double side_tol,
                      double angle_tol);

/// Side lengths sorted ascending, each with the vertex opposite to it.
struct SortedSides {
  std::array<double, 3> side{};   ///< [m], side[0] <= side[1] <= side[2]
  std::array<int, 3> opposite{};  ///< input vertex index (0..2) opposite side[k]
};

/// Sorted side lengths of the triangle p[0], p[1], p[2].
SortedSides sorted_sides(const std::array<Eigen::Vector2d, 3>& p);

}  // namespace refloc
