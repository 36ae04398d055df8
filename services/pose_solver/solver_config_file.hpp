#pragma once
// deploy/config/pose_solver.json: the solver's settings and channels. Every key is
// optional (defaults as in SolverConfig). The laser mount comes from robot.json.

#include "pose_solver/solver_config.hpp"

#include <string>

namespace refloc {

class JsonConfig;

struct SolverServiceConfig {
  SolverConfig solver;
  std::string input_channel = "REFLECTOR_MATCHES";
  std::string output_channel = "LASER_POSE";
};

/// Read and validate (ConfigError naming the key on a bad value).
SolverServiceConfig parse_solver_service_config(const JsonConfig& config);
/// Load, read and reject unknown keys; the defaults when path is empty.
SolverServiceConfig load_solver_service_config(const std::string& path);

}  // namespace refloc
