#include "load_test_samples.hpp"

#include "common/json_config.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

namespace refloc {
namespace {

[[noreturn]] void fail(const std::string& source, int line, const std::string& what) {
  throw ConfigError(fmt::format("{}:{}: {}", source, line, what));
}

double parse_number(const std::string& text, const std::string& source, int line, const std::string& key) {
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size())
    fail(source, line, fmt::format("{}: expected a number, got '{}'", key, text));
  return value;
}

int64_t parse_count(const std::string& text, const std::string& source, int line, const std::string& key) {
  const double value = parse_number(text, source, line, key);
  if (value < 0 || value != static_cast<double>(static_cast<int64_t>(value)))
    fail(source, line, fmt::format("{}: expected a whole number >= 0, got '{}'", key, text));
  return static_cast<int64_t>(value);
}

ProcessUsage parse_process(std::istringstream& fields, const std::string& source, int line) {
  static const char* const kColumns[] = {"cpu_ticks",  "samples",     "rss_sum_kb",
                                         "rss_end_kb", "rss_peak_kb", "pid_restarts"};
  ProcessUsage p;
  if (!(fields >> p.program)) fail(source, line, "process: expected NAME and 6 counts");
  int64_t* const targets[] = {&p.cpu_ticks,  &p.samples,     &p.rss_sum_kb,
                              &p.rss_end_kb, &p.rss_peak_kb, &p.pid_restarts};
  for (size_t i = 0; i < 6; ++i) {
    std::string text;
    if (!(fields >> text))
      fail(source, line, fmt::format("process {}: missing {} (expected 6 counts)", p.program, kColumns[i]));
    *targets[i] = parse_count(text, source, line, fmt::format("process {} {}", p.program, kColumns[i]));
  }
  std::string extra;
  if (fields >> extra)
    fail(source, line, fmt::format("process {}: unexpected '{}' after 6 counts", p.program, extra));
  return p;
}

std::string rest_of(std::istringstream& fields) {
  std::string rest;
  std::getline(fields >> std::ws, rest);
  return rest;
}

}  // namespace

LoadSamples parse_load_samples(std::istream& in, const std::string& source) {
  LoadSamples s;
  bool have_duration = false, have_measured = false;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    std::istringstream fields(text);
    std::string key;
    if (!(fields >> key) || key[0] == '#') continue;
    if (key == "process") {
      s.processes.push_back(parse_process(fields, source, line));
      continue;
    }
    const std::string value = rest_of(fields);
    if (value.empty()) fail(source, line, fmt::format("{}: missing value", key));
    if (key == "duration_s") {
      s.run.duration_s = parse_number(value, source, line, key);
      have_duration = true;
    } else if (key == "measured_s") {
      s.run.measured_s = parse_number(value, source, line, key);
      have_measured = true;
    } else if (key == "cores") {
      s.run.cores = parse_count(value, source, line, key);
    } else if (key == "clock_ticks_per_s") {
      s.run.clock_ticks_per_s = parse_number(value, source, line, key);
      if (s.run.clock_ticks_per_s <= 0) fail(source, line, "clock_ticks_per_s: must be > 0");
    } else if (key == "scan_rate_hz") {
      s.run.scan_rate_hz = parse_number(value, source, line, key);
    } else if (key == "max_p99_ms") {
      s.run.max_p99_ms = parse_number(value, source, line, key);
    } else if (key == "build") {
      s.run.build = value;
    } else if (key == "log") {
      s.run.log = value;
    } else if (key == "load_average_before") {
      s.run.load_average_before = value;
    } else if (key == "load_average_after") {
      s.run.load_average_after = value;
    } else {
      fail(source, line, fmt::format("unknown record '{}'", key));
    }
  }
  if (!have_duration) throw ConfigError(source + ": no duration_s record");
  if (!have_measured) throw ConfigError(source + ": no measured_s record");
  if (s.processes.empty()) throw ConfigError(source + ": no process record");
  return s;
}

LoadSamples load_load_samples(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError(fmt::format("{}: cannot read", path));
  return parse_load_samples(in, path);
}

}  // namespace refloc
