#include "lms100_emulator/fault_command.hpp"

#include "lms100_emulator/emulator_config_loader.hpp"

#include <poll.h>
#include <unistd.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace refloc {

namespace {

bool parse_count(const std::string& word, int max_value, int& value) {
  try {
    size_t used = 0;
    value = std::stoi(word, &used);
    return used == word.size() && value >= 0 && value <= max_value;
  } catch (const std::exception&) {
    return false;
  }
}

bool parse_float(const std::string& word, float& value) {
  try {
    size_t used = 0;
    value = std::stof(word, &used);
    return used == word.size() && std::isfinite(value);
  } catch (const std::exception&) {
    return false;
  }
}

bool parse_on_off(const std::string& word, bool& value) {
  if (word != "on" && word != "off") return false;
  value = word == "on";
  return true;
}

std::string describe(const FaultSettings& s) {
  std::ostringstream out;
  const char* split = s.split_mode == WriteSplitMode::none     ? "none"
                      : s.split_mode == WriteSplitMode::random ? "random"
                                                               : "boundaries";
  out << "split " << split << ", merge " << s.merge_scan_telegrams << ", junk "
      << s.junk_bytes_between_telegrams << ", duplicate " << (s.duplicate_replies ? "on" : "off")
      << ", ready " << (s.refuse_readiness ? "off" : "on");
  if (s.corrupts_scan_header()) {
    out << ", header: scale " << s.dist_scale << ", offset " << s.dist_offset_mm << " mm, scan-frequency "
        << s.scan_frequency_1e2hz << ", beam-rate " << s.measurement_frequency_1e1khz << ", codes "
        << (s.reserved_distance_codes ? "on" : "off") << ", layer " << s.layer_angle_1e4deg;
  }
  return out.str();
}

}  // namespace

bool apply_fault_command(const std::string& line, FaultInjector& faults, std::string& message) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  const std::string command = words.empty() ? "" : words[0];
  const std::string arg = words.size() == 2 ? words[1] : "";
  const bool no_arg = words.size() == 1;
  const bool one_arg = words.size() == 2;

  FaultSettings settings = faults.settings();
  int n = 0;
  float value = 0.0F;
  bool flag = false;
  bool ok = true;
  if (command == "drop" && one_arg && parse_count(arg, 100000, n)) {
    faults.drop_next_scans(n);
  } else if (command == "stall" && one_arg && parse_count(arg, 600000, n)) {
    faults.stall_for_ms(n);
  } else if (command == "close" && no_arg) {
    faults.close_connection_now();
  } else if (command == "reset" && no_arg) {
    faults.reset_mid_telegram();
  } else if (command == "refuse-write" && no_arg) {
    faults.refuse_next_write();
  } else if (command == "ready" && one_arg && parse_on_off(arg, flag)) {
    settings.refuse_readiness = !flag;
    faults.set_settings(settings);
  } else if (command == "split" && one_arg && (arg == "none" || arg == "random" || arg == "boundaries")) {
    settings.split_mode = parse_split_mode(arg);
    faults.set_settings(settings);
  } else if (command == "merge" && one_arg && parse_count(arg, 50, n) && n >= 1) {
    settings.merge_scan_telegrams = n;
    faults.set_settings(settings);
  } else if (command == "junk" && one_arg && parse_count(arg, 10000, n)) {
    settings.junk_bytes_between_telegrams = n;
    faults.set_settings(settings);
  } else if (command == "duplicate" && one_arg && parse_on_off(arg, flag)) {
    settings.duplicate_replies = flag;
    faults.set_settings(settings);
  } else if (command == "scale" && one_arg && parse_float(arg, value)) {
    settings.dist_scale = value;
    faults.set_settings(settings);
  } else if (command == "offset" && one_arg && parse_float(arg, value)) {
    settings.dist_offset_mm = value;
    faults.set_settings(settings);
  } else if (command == "scan-frequency" && one_arg && parse_count(arg, 1000000, n)) {
    settings.scan_frequency_1e2hz = static_cast<uint32_t>(n);
    faults.set_settings(settings);
  } else if (command == "beam-rate" && one_arg && parse_count(arg, 1000000, n)) {
    settings.measurement_frequency_1e1khz = static_cast<uint32_t>(n);
    faults.set_settings(settings);
  } else if (command == "codes" && one_arg && parse_on_off(arg, flag)) {
    settings.reserved_distance_codes = flag;
    faults.set_settings(settings);
  } else if (command == "layer" && one_arg && parse_count(arg, 0xFFFF, n)) {
    settings.layer_angle_1e4deg = static_cast<uint16_t>(n);
    faults.set_settings(settings);
  } else if (command == "header" && one_arg && arg == "ok") {
    const FaultSettings honest;
    settings.dist_scale = honest.dist_scale;
    settings.dist_offset_mm = honest.dist_offset_mm;
    settings.scan_frequency_1e2hz = honest.scan_frequency_1e2hz;
    settings.measurement_frequency_1e1khz = honest.measurement_frequency_1e1khz;
    settings.reserved_distance_codes = honest.reserved_distance_codes;
    settings.layer_angle_1e4deg = honest.layer_angle_1e4deg;
    faults.set_settings(settings);
  } else if (command == "status" && no_arg) {
  } else {
    ok = false;
  }
  if (!ok) {
    message =
        "unknown or malformed command '" + line +
        "' (drop N | stall MS | close | reset | refuse-write | ready on|off | split none|random|boundaries"
        " | merge N | junk N | duplicate on|off | scale F | offset MM | scan-frequency HZx100"
        " | beam-rate HZ/100 | codes on|off | layer N | header ok | status)";
    return false;
  }
  message = "ok: " + describe(faults.settings());
  return true;
}

void run_fault_commands(int fd, FaultInjector& faults, const std::atomic<bool>& stop,
                        const FaultCommandReport& report) {
  std::string pending;
  while (!stop.load()) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 200) <= 0) continue;
    char buffer[256];
    const ssize_t n = ::read(fd, buffer, sizeof(buffer));
    if (n <= 0) return;
    pending.append(buffer, static_cast<size_t>(n));
    for (size_t eol; (eol = pending.find('\n')) != std::string::npos; pending.erase(0, eol + 1)) {
      const std::string line = pending.substr(0, eol);
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      std::string message;
      const bool accepted = apply_fault_command(line, faults, message);
      report(accepted, message);
    }
  }
}

}  // namespace refloc
