#pragma once
// Settings of the pose solver.

namespace refloc {

enum class SolverMode {
  kPaper,    ///< §3.6: pairwise-subtracted circle equations, arithmetic-mean heading, eq. 8 offset
  kDefault,  ///< Levenberg-Marquardt on (x, y, theta) from the detections' 2D points and covariances
};

/// The LMS100's systematic range error (up to +-30 mm): a common offset b = measured - true
/// range of every detection, estimated jointly with the pose when the geometry supports it and
/// carried into the covariance when it does not (range_bias_filter.hpp, range_bias_refinement.hpp).
struct RangeBiasConfig {
  bool estimate = true;       ///< false: b fixed at prior_mean, its prior_sigma only inflates the covariance
  double prior_mean = 0.0;    ///< [m] what b is believed to be before any scan
  double prior_sigma = 0.03;  ///< [m] 1 sigma about prior_mean (the LMS100's data sheet: +-30 mm)
  double drift = 2e-4;        ///< [m/sqrt(s)] random walk of b between scans (temperature, ageing)
  int min_reflectors = 4;     ///< fewer used reflectors: b is not estimated from the scan
  double max_scan_sigma = 0.02;  ///< [m] a scan whose data alone give b a larger sigma does not estimate it
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
  RangeBiasConfig range_bias;
};

}  // namespace refloc
