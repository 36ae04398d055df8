#pragma once
#include <functional>
#include <string>

namespace refloc {

// refloc's exit codes, the same in every binary and script (README "Exit codes"):
// 0 success, 1 runtime failure, 2 bad configuration or input file, 64 usage error.
/// Exit code for a runtime failure (lost device, LCM down, a check that failed).
constexpr int kExitRuntimeFailure = 1;
/// Exit code for bad configuration or input files.
constexpr int kExitConfigError = 2;
/// Exit code for a bad command line (sysexits.h EX_USAGE); CLI11's own codes are mapped to it.
constexpr int kExitUsageError = 64;

/// Run a program's body and turn failures into one clear line on stderr:
/// ConfigError → exit 2, any other exception → exit 1. Never an exception trace.
int guarded_main(const std::string& program, const std::function<int()>& body);

}  // namespace refloc
