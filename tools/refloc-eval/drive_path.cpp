#include "drive_path.hpp"

#include "common/angles.hpp"

#include <cmath>

namespace refloc {

DrivePath::DrivePath(double x_min, double y_min, double x_max, double y_max, double corner_radius,
                     double speed, Heading heading)
    : speed_(speed), heading_(heading) {
  const double r = corner_radius;
  const double quarter = 0.5 * M_PI * r;
  // Counter-clockwise: bottom, right, top, left leg, each followed by its corner.
  segments_ = {
      {false, {x_min + r, y_min}, 0.0, x_max - x_min - 2 * r, 0.0},
      {true, {x_max - r, y_min + r}, -0.5 * M_PI, quarter, r},
      {false, {x_max, y_min + r}, 0.5 * M_PI, y_max - y_min - 2 * r, 0.0},
      {true, {x_max - r, y_max - r}, 0.0, quarter, r},
      {false, {x_max - r, y_max}, M_PI, x_max - x_min - 2 * r, 0.0},
      {true, {x_min + r, y_max - r}, 0.5 * M_PI, quarter, r},
      {false, {x_min, y_max - r}, -0.5 * M_PI, y_max - y_min - 2 * r, 0.0},
      {true, {x_min + r, y_min + r}, M_PI, quarter, r},
  };
  for (const Segment& s : segments_) lap_length_ += s.length;
}

DrivePath DrivePath::demo_hall_loop(double speed, Heading heading) {
  return DrivePath(2.5, 2.5, 17.5, 9.5, 1.5, speed, heading);
}

DriveState DrivePath::at(double t) const {
  double s = std::fmod(speed_ * t, lap_length_);
  if (s < 0.0) s += lap_length_;
  size_t i = 0;
  while (i + 1 < segments_.size() && s > segments_[i].length) s -= segments_[i++].length;
  const Segment& g = segments_[i];
  Eigen::Vector2d p;
  double direction = 0.0, curvature = 0.0;
  if (g.arc) {
    const double phi = g.angle + s / g.radius;
    p = g.start + g.radius * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    direction = phi + 0.5 * M_PI;
    curvature = 1.0 / g.radius;
  } else {
    p = g.start + s * Eigen::Vector2d(std::cos(g.angle), std::sin(g.angle));
    direction = g.angle;
  }
  DriveState state;
  state.map_direction = {std::cos(direction), std::sin(direction)};
  if (heading_ == Heading::kTangent) {
    state.map_T_robot = {p.x(), p.y(), wrap_angle(direction)};
    state.twist = {speed_, 0.0, speed_ * curvature};
  } else {
    state.map_T_robot = {p.x(), p.y(), fixed_heading_};
    const double relative = direction - fixed_heading_;  // travel direction in the body frame
    state.twist = {speed_ * std::cos(relative), speed_ * std::sin(relative), 0.0};
  }
  return state;
}

}  // namespace refloc
