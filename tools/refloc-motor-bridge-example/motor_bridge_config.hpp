#pragma once
// The example bridge's config file (JSON, optional; --config). Every key has the
// default of MotorBridgeConfig; --print-config lists them with unit, range and meaning.

#include "motor_bridge.hpp"

#include <string>

namespace refloc {

class JsonConfig;

/// The whole file; the caller rejects unknown keys.
MotorBridgeConfig parse_motor_bridge_config(const JsonConfig& config);

/// Load, parse and reject unknown keys; "" gives the defaults.
MotorBridgeConfig load_motor_bridge_config(const std::string& path);

}  // namespace refloc
