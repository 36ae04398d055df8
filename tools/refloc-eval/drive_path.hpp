#pragma once
// The true motion of refloc-eval's drive study: a closed loop of straight legs and
// quarter-circle corners driven at constant speed, as an exact function of time, so the
// truth at every beam's and every fix's stamp is known without integration error.

#include "common/se2.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

/// The robot's true state at one instant.
struct DriveState {
  Pose2 map_T_robot;
  BodyTwist twist;                             ///< body frame [m/s, m/s, rad/s]
  Eigen::Vector2d map_direction = {1.0, 0.0};  ///< unit direction of travel in the map
};

class DrivePath {
 public:
  enum class Heading {
    kTangent,  ///< the robot faces where it drives (vx only; wz = v / r in the corners)
    kFixed,    ///< Mecanum crab: heading held at the start's, the twist's vx/vy turn
  };

  /// The rounded rectangle with corners (x_min, y_min)-(x_max, y_max) and corner_radius
  /// [m], driven counter-clockwise at speed [m/s] from the start of the bottom leg.
  DrivePath(double x_min, double y_min, double x_max, double y_max, double corner_radius, double speed,
            Heading heading);
  /// The loop through the middle of world_demo.json's ring corridor: (2.5, 2.5)-(17.5, 9.5),
  /// corners of 1.5 m (41.4 m a lap).
  static DrivePath demo_hall_loop(double speed, Heading heading);

  /// The state t [s] after the start (the loop repeats).
  DriveState at(double t) const;
  double lap_length() const { return lap_length_; }  ///< [m]
  double speed() const { return speed_; }            ///< [m/s]

 private:
  struct Segment {
    bool arc = false;
    Eigen::Vector2d start = Eigen::Vector2d::Zero();  ///< straight: first point; arc: centre
    double angle = 0.0;   ///< straight: direction; arc: polar angle of the first point [rad]
    double length = 0.0;  ///< [m]
    double radius = 0.0;  ///< arc only [m]
  };
  std::vector<Segment> segments_;
  double lap_length_ = 0.0;
  double speed_;
  Heading heading_;
  double fixed_heading_ = 0.0;
};

}  // namespace refloc
