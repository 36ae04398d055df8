#include "pose_solver/solver_config_file.hpp"

#include "common/json_config.hpp"

namespace refloc {

SolverServiceConfig parse_solver_service_config(const JsonConfig& config) {
  SolverServiceConfig s;
  SolverConfig& c = s.solver;
  c.mode = config.choice("/mode", "default", {"default", "paper"}) == "paper" ? SolverMode::kPaper
                                                                              : SolverMode::kDefault;
  s.input_channel = config.string("/input_channel", s.input_channel);
  s.output_channel = config.string("/output_channel", s.output_channel);
  c.max_iterations = static_cast<int>(config.integer("/max_iterations", c.max_iterations, 1, 1000));
  c.detection_min_sigma = config.number("/detection_min_sigma_m", c.detection_min_sigma, 1e-5, 1.0);
  c.outlier_threshold = config.number("/outlier_threshold_sigma", c.outlier_threshold, 1.0, 100.0);
  c.min_reflectors_ok = static_cast<int>(config.integer("/min_reflectors_ok", c.min_reflectors_ok, 3, 100));
  c.max_rms_residual_ok = config.number("/max_rms_residual_ok_m", c.max_rms_residual_ok, 1e-4, 10.0);
  RangeBiasConfig& b = c.range_bias;
  b.estimate = config.boolean("/range_bias_estimate", b.estimate);
  b.prior_mean = config.number("/range_bias_prior_mean_m", b.prior_mean, -0.5, 0.5);
  b.prior_sigma = config.number("/range_bias_prior_sigma_m", b.prior_sigma, 0.0, 1.0);
  b.drift = config.number("/range_bias_drift_m_per_sqrt_s", b.drift, 0.0, 0.1);
  b.min_reflectors = static_cast<int>(config.integer("/range_bias_min_reflectors", b.min_reflectors, 4, 100));
  b.max_scan_sigma = config.number("/range_bias_max_scan_sigma_m", b.max_scan_sigma, 1e-4, 1.0);
  if (b.estimate && b.prior_sigma < 1e-4)
    config.fail(
        "/range_bias_prior_sigma_m",
        "must be >= 0.0001 m while /range_bias_estimate is true (a prior of 0 leaves nothing to estimate)");
  return s;
}

SolverServiceConfig load_solver_service_config(const std::string& path) {
  if (path.empty()) return {};
  const JsonConfig file = JsonConfig::load_file(path);
  SolverServiceConfig config = parse_solver_service_config(file);
  file.reject_unknown_keys();
  return config;
}

}  // namespace refloc
