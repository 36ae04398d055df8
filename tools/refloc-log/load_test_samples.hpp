#pragma once
// What deploy/load_test.sh measures outside the LCM log, in the plain text file it
// writes for refloc-log --load-test: the run (asked and measured duration, cores,
// load averages) and, per program, CPU time and memory sampled from /proc.

#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace refloc {

/// One supervised program over the measured run (summed over its restarts).
struct ProcessUsage {
  std::string program;
  int64_t cpu_ticks = 0;     ///< utime + stime over the run [clock ticks]
  int64_t samples = 0;       ///< /proc samples that had a VmRSS
  int64_t rss_sum_kb = 0;    ///< VmRSS summed over the samples [kB]
  int64_t rss_end_kb = 0;    ///< VmRSS of the last sample [kB]
  int64_t rss_peak_kb = 0;   ///< largest VmHWM seen [kB]
  int64_t pid_restarts = 0;  ///< times the sampler found the program under a new pid
};

struct LoadRun {
  double duration_s = 0.0;           ///< asked for (--duration)
  double measured_s = 0.0;           ///< logger start to logger stop, wall clock
  int64_t cores = 0;                 ///< nproc
  double clock_ticks_per_s = 100.0;  ///< getconf CLK_TCK
  double max_p99_ms = 5.0;           ///< scan-to-pose p99 limit; <= 0: report only
  double scan_rate_hz = 50.0;        ///< the sensor's scan rate, for the expected scan count
  std::string build;
  std::string log;
  std::string load_average_before;  ///< /proc/loadavg, first three fields
  std::string load_average_after;
};

struct LoadSamples {
  LoadRun run;
  std::vector<ProcessUsage> processes;  ///< in file order
};

/// One record a line, '#' starts a comment line:
///   duration_s S | measured_s S | cores N | clock_ticks_per_s HZ | max_p99_ms MS | scan_rate_hz HZ
///   build PATH | log PATH | load_average_before TEXT | load_average_after TEXT
///   process NAME CPU_TICKS SAMPLES RSS_SUM_KB RSS_END_KB RSS_PEAK_KB PID_RESTARTS
/// duration_s, measured_s and at least one process are required. Throws ConfigError
/// naming source:line and the record on anything else.
LoadSamples parse_load_samples(std::istream& in, const std::string& source);

/// parse_load_samples of a file; ConfigError when it cannot be read.
LoadSamples load_load_samples(const std::string& path);

}  // namespace refloc
