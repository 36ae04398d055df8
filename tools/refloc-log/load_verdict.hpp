#pragma once
// The load test's verdict (deploy/load_test.sh runs refloc-log --load-test): from the
// LCM log (dropped scans, scan-to-LASER_POSE latency, every service's HEARTBEAT) and
// the /proc samples of the run, four checks; the run passes when all hold.

#include "load_test_samples.hpp"
#include "pipeline_latency.hpp"
#include "scan_continuity.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace refloc {

/// The recorder: supervised and sampled like a service, but it sends no HEARTBEAT.
inline constexpr const char* kLoadTestRecorder = "lcm-logger";

struct LoadChecks {
  bool no_dropped_scan = false;           ///< no scan lost between the sensor and LASER_POSE
  bool latency_p99_within_limit = false;  ///< end-to-end p99 <= max_p99_ms (always true when max_p99_ms <= 0)
  bool every_service_reported = false;    ///< every program but the recorder has HEARTBEATs in the log
  bool no_restart = false;                ///< no program changed pid (sampler) or restarted (HEARTBEAT)
  double max_p99_ms = 0.0;                ///< the limit applied [ms]
  bool pass() const {
    return no_dropped_scan && latency_p99_within_limit && every_service_reported && no_restart;
  }
};

/// The four checks over what the log and the sampler saw.
LoadChecks judge_load_test(const LoadSamples& samples, const ScanContinuityReport& scans,
                           const LatencyReport& latency);

/// The whole report as load_test.json: run, scans, latency_ms, latency_stages_ms,
/// services (one per sampled program: CPU%, RSS, HEARTBEAT numbers), checks, pass.
nlohmann::ordered_json load_test_report_to_json(const LoadSamples& samples, const ScanContinuityReport& scans,
                                                const LatencyReport& latency, const LoadChecks& checks);

/// The same for a terminal: summary lines, one table row per program, checks, PASS/FAIL.
std::string format_load_test_report(const LoadSamples& samples, const ScanContinuityReport& scans,
                                    const LatencyReport& latency, const LoadChecks& checks);

/// refloc-log --load-test: judge the log's scans and latency with the run's /proc samples (read
/// from samples_path), write the JSON report to report_path (unless empty), print the report (JSON
/// when json); 0 pass, 1 fail.
int report_load_test(const ScanContinuityReport& scans, const LatencyReport& latency,
                     const std::string& samples_path, const std::string& report_path, bool json);

}  // namespace refloc
