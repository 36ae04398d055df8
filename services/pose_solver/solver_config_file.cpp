#include "pose_solver/solver_config_file.hpp"

#include "common/json_config.hpp"

namespace refloc {

SolverServiceConfig parse_solver_service_config(const JsonConfig& config) {
  SolverServiceConfig s;
  SolverConfig& c = s.solver;
  c.mode = config.choice({"/mode", "",
                          "default: Levenberg-Marquardt on (x, y, theta) and the range offset with each "
                          "detection's covariance, outliers dropped; paper: §3.6 as published (baseline)"},
                         "default", {"default", "paper"}) == "paper"
               ? SolverMode::kPaper
               : SolverMode::kDefault;
  s.input_channel = config.string(
      {"/input_channel", "", "LCM channel of the matched detections read (reflector_matches_t)"},
      s.input_channel);
  s.output_channel = config.string(
      {"/output_channel", "",
       "LCM channel of the fixes (pose2d_t): one per matches message, with or without a pose (status)"},
      s.output_channel);
  c.max_iterations = static_cast<int>(config.integer(
      {"/max_iterations", "count",
       "default mode: Levenberg-Marquardt iterations per refinement (stops earlier at a 1e-9 step); "
       "not converged by then: LOST, no pose"},
      c.max_iterations, 1, 1000));
  c.detection_min_sigma =
      config.number({"/detection_min_sigma_m", "m",
                     "added in quadrature to every detection's x and y sigma: keeps weights finite; larger "
                     "weighs near and far reflectors more alike, widens the covariance"},
                    c.detection_min_sigma, 1e-5, 1.0);
  c.outlier_threshold =
      config.number({"/outlier_threshold_sigma", "sigma",
                     "a match whose normalised residual exceeds this is dropped, worst first, while > 3 "
                     "remain (default mode); any still above: DEGRADED. Lower drops good matches"},
                    c.outlier_threshold, 1.0, 100.0);
  c.min_reflectors_ok = static_cast<int>(
      config.integer({"/min_reflectors_ok", "count",
                      "fewer reflectors used (3 at least) make the fix DEGRADED: fusion corrects with it but "
                      "never (re-)initialises from it"},
                     c.min_reflectors_ok, 3, 100));
  c.max_rms_residual_ok =
      config.number({"/max_rms_residual_ok_m", "m",
                     "RMS range residual of the used reflectors above this makes the fix DEGRADED; raise "
                     "for a noisier sensor or a less exact map"},
                    c.max_rms_residual_ok, 1e-4, 10.0);
  RangeBiasConfig& b = c.range_bias;
  b.estimate =
      config.boolean({"/range_bias_estimate", "",
                      "default mode: estimate the range offset b (measured - true) with the pose where "
                      "the geometry allows; false: b held at the prior mean, its sigma in the covariance"},
                     b.estimate);
  b.prior_mean = config.number({"/range_bias_prior_mean_m", "m",
                                "range offset b believed before any scan (subtracted from every range); the "
                                "estimate starts here"},
                               b.prior_mean, -0.5, 0.5);
  b.prior_sigma = config.number({"/range_bias_prior_sigma_m", "m",
                                 "1 sigma of b about the prior mean (LMS100: +-30 mm), also the cap of its "
                                 "growth between scans; larger: b follows the data more"},
                                b.prior_sigma, 0.0, 1.0);
  b.drift =
      config.number({"/range_bias_drift_m_per_sqrt_s", "m/sqrt(s)",
                     "random walk of b between scans (temperature): larger follows changes faster with a "
                     "noisier b; 0.0002 is 12 mm in 1 h"},
                    b.drift, 0.0, 0.1);
  b.min_reflectors = static_cast<int>(
      config.integer({"/range_bias_min_reflectors", "count",
                      "fewer reflectors used: this scan does not estimate b (b held, its sigma inflates the "
                      "covariance)"},
                     b.min_reflectors, 4, 100));
  b.max_scan_sigma =
      config.number({"/range_bias_max_scan_sigma_m", "m",
                     "a scan whose data alone give b a larger sigma (reflectors all on one side: "
                     "b looks like a shift) does not estimate it; larger lets pose error into b"},
                    b.max_scan_sigma, 1e-4, 1.0);
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
