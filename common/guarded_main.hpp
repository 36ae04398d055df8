#pragma once
#include <functional>
#include <string>

namespace refloc {

/// Exit code for bad configuration or input files.
constexpr int kExitConfigError = 2;

/// Run a program's body and turn failures into one clear line on stderr:
/// ConfigError → exit 2, any other exception → exit 1. Never an exception trace.
int guarded_main(const std::string& program, const std::function<int()>& body);

}  // namespace refloc
