#pragma once
// Circle fits of one cluster's laser points: the paper's free algebraic fit and our
// Gauss-Newton fit of the centre alone with the reflector radius known.

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace refloc {

/// One beam of a cluster as the fits see it.
struct FitBeam {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();       ///< laser_p of the echo [m]
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  ///< unit beam direction
  double range = 0.0;                                    ///< measured range [m]
  double weight = 1.0;                                   ///< 1 / sigma_range^2 [1/m^2]
  /// A dull surface behind the reflector close enough to blend into this beam's echo (the wall
  /// it is mounted on), at this range along the beam [m]; NaN: none (the spot model's background).
  double background_range = std::numeric_limits<double>::quiet_NaN();
  /// That surface's echo energy per unit of spot over the reflector's (an RSSI ratio, 0..1).
  double background_energy_ratio = 0.0;
};

struct CircleFit {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();      ///< [m]
  double radius = 0.0;                                   ///< [m]
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();  ///< of center [m^2]
  double radius_sigma = 0.0;  ///< standard deviation of radius, free-radius fits only [m]
  double chi2 = 0.0;          ///< sum of weighted squared residuals at the solution
  /// Known-radius fits with the spot model: chi2 of the central-ray fit it started from (the
  /// shape tests take the smaller of the two, so a sensor whose echoes follow the central ray
  /// more than our spot model keeps its recall); otherwise equal to chi2.
  double central_ray_chi2 = 0.0;
  int iterations = 0;
};

/// The laser spot the fits model: a beam's echo off a cylinder is the spot-weighted mean range
/// of the part of the spot on the cylinder, not the range of its central ray. Past ~6 m the
/// LMS100's spot (15 mrad) is as wide as a 120 mm reflector, every beam's echo averages the
/// curved face, and a central-ray model puts the centre up to 10 mm too far (emulator, 8-15 m;
/// extractor README "Beam spot"). The spot is exit_diameter + range * divergence wide with a
/// Gaussian profile (1/e^2 at its rim), integrated over the chord it covers. The part of the spot
/// beside the cylinder that lands on a surface just behind it (a wall the reflector is mounted on,
/// FitBeam::background_range) blends into the echo too, by its energy: a mixed pixel that reads
/// the beam long, more the more of the spot misses the cylinder (far and edge beams).
struct EchoSpotModel {
  bool enabled = true;             ///< false: every beam is its central ray
  double divergence_rad = 0.015;   ///< full angle [rad] (LMS100 datasheet: 15 mrad)
  double exit_diameter_m = 0.008;  ///< spot diameter at the optics cover [m]
  /// Model the surface behind (when FitBeam has one). Off in the service: for a single-scan fix the
  /// model's dependence on the neighbours' noisy ranges costs more variance than its bias removal
  /// gains (refloc-eval random: RMSE 6.00 -> 6.17 mm with both corrections); on for maps, which
  /// average thousands of detections (mapping_corrections()).
  bool background = false;
  /// Returns along one beam closer than this blend into one echo (the pulse's length): a dull
  /// surface beside the cluster at most this far behind its edge is its background [m].
  double background_merge_distance_m = 0.4;
  bool applies() const { return enabled && (divergence_rad > 0.0 || exit_diameter_m > 0.0); }
};

struct KnownRadiusFitConfig {
  int max_iterations = 10;
  double step_tolerance = 1e-6;  ///< stop when the centre moves less [m]
  /// Floor on the cosine of the incidence angle: near-grazing beams are where beam width
  /// and mixed pixels hurt most, and where the linearisation fails first, so their leverage
  /// is capped (cos 53 deg; 0.6 gave NEES ~2 over 1-8 m in circle_fit_test).
  double min_incidence_cos = 0.6;
  EchoSpotModel spot;
  /// Remove the fit's second-order bias along the line of sight (Box 1971: a least-squares fit of a
  /// curved model to noisy ranges is biased by half the model's curvature times the centre's
  /// covariance; a cylinder's flanks put a known-radius centre 1-3 mm too close at 3-6 m). Off in
  /// the service, on for maps, like EchoSpotModel::background.
  bool second_order_bias_correction = false;
};

/// Kasa algebraic least-squares circle; false for fewer than 3 points or collinear points.
/// covariance uses isotropic point noise point_sigma [m].
bool fit_circle_algebraic(const std::vector<FitBeam>& beams, double point_sigma, CircleFit& out);

/// Centre of a circle of known radius [m] seen by these beams: Gauss-Newton on range
/// residuals (first-order, with the incidence floor), started behind the points as seen
/// from the sensor, so one or two beams still give the physically right centre.
/// covariance = (J^T W J)^-1. False when there are no beams or the result is not finite.
bool fit_circle_known_radius(const std::vector<FitBeam>& beams, double radius,
                             const KnownRadiusFitConfig& config, CircleFit& out);

/// Same residuals with the radius free as well, started from (center, radius); fills
/// radius and radius_sigma. Needs at least 4 beams.
bool fit_circle_free_radius(const std::vector<FitBeam>& beams, const Eigen::Vector2d& center, double radius,
                            const KnownRadiusFitConfig& config, CircleFit& out);

/// Range residual of one beam against a circle [m], negative when the echo lies beyond the
/// predicted surface; also its derivatives with respect to the centre and the radius. With the
/// spot model on: predicted spot-mean range - measured range (the spot's rays that meet the
/// circle, integrated). Without it, or when no ray of the spot meets the circle:
/// the linearised (|p - c| - radius) / cos(incidence), cos floored at min_incidence_cos.
double range_residual(const FitBeam& beam, const Eigen::Vector2d& center, double radius,
                      const KnownRadiusFitConfig& config, Eigen::Vector2d* d_center = nullptr,
                      double* d_radius = nullptr);

}  // namespace refloc
