#pragma once
// What the driver expects of the scanner it talks to, chosen by the config key /device instead
// of the LMS100's limits written into the code: the range limits published with each scan, the
// scan frequencies and beam counts a telegram may report, the field its beams may lie in, and
// the RSSI resolution asked for by default. Figures from SICK's data sheets; margins as stated.

#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace refloc {

struct DeviceProfile {
  std::string name;                         ///< the /device value: "lms1xx", "lms5xx", "tim5xx_7xx"
  double range_min_m = 0.05;                ///< published range_min [m]: closer returns are not echoes
  double range_max_m = 20.0;                ///< published range_max [m]: the data sheet's working range
  std::vector<double> scan_frequencies_hz;  ///< frequencies a telegram may report [Hz]
  double default_frequency_hz = 50.0;       ///< /frequency_hz when not set [Hz]
  std::vector<float> dist_scales;           ///< DIST1 scale factors accepted [mm per raw unit]
  size_t max_beams = 1141;                  ///< most beams in one telegram
  int64_t min_angle_1e4deg = -475000;       ///< field the beams must lie in, sensor angles [deg x 1e4]
  int64_t max_angle_1e4deg = 2375000;
  int default_rssi_bits = 16;      ///< RSSI resolution asked for when /rssi_bits is not set: 16 or 8
  bool lms1xx_scan_config = true;  ///< mLMPsetscancfg with the LMS1xx field (-45..225 deg) applies
};

/// The profile of that name; nullptr when there is none.
const DeviceProfile* find_device_profile(std::string_view name);
/// The default: a SICK LMS100 / LMS1xx.
const DeviceProfile& lms1xx_profile();
/// "lms1xx, lms5xx, tim5xx_7xx" for messages.
std::string device_profile_names();
/// The same names as a set, for JsonConfig::choice.
std::set<std::string> device_profile_name_set();

}  // namespace refloc
