#pragma once
// Settings of the pose solver.

namespace refloc {

enum class SolverMode {
  kPaper,    ///< §3.6: pairwise-subtracted circle equations, arithmetic-mean heading, eq. 8 offset
  kDefault,  ///< Levenberg-Marquardt on (x, y, theta) from the detections' 2D points and covariances
};

struct SolverConfig {
  SolverMode mode = SolverMode::kDefault;
  int max_iterations = 30;
  double convergence_step = 1e-9;      ///< stop when the update's norm is below this [m, rad]
  double detection_min_sigma = 0.002;  ///< floor of a detection's std dev, keeps weights finite [m]
  double outlier_threshold = 4.0;      ///< normalised residual sqrt(e^T C^-1 e) above this is dropped
  int min_reflectors_ok = 4;           ///< fewer (but >= 3) gives DEGRADED
  double max_rms_residual_ok = 0.03;   ///< [m] RMS range residual above this gives DEGRADED
  double min_position_conditioning =
      1e-6;  ///< smallest eigenvalue ratio of the linear system; below is collinear
};

}  // namespace refloc
