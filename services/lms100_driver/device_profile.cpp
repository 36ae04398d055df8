#include "lms100_driver/device_profile.hpp"

namespace refloc {
namespace {

const std::vector<DeviceProfile>& profiles() {
  static const std::vector<DeviceProfile> all = [] {
    // LMS1xx: 0.5-20 m (LMS100/111), 25 or 50 Hz, 270 deg (-45..225) at 0.25 deg at most: 1081
    // beams; 285 deg at 0.25 deg (1141) and 2.5 deg each side allowed.
    DeviceProfile lms1xx{"lms1xx", 0.05,    20.0,    {25.0, 50.0}, 50.0, {1.0F, 2.0F},
                         1141,     -475000, 2375000, 16,           true};
    // LMS5xx: up to 80 m (LMS511), 25..100 Hz, 190 deg (-5..185) at down to 0.0833 deg: 2281
    // beams; the recorded LMS511 sends 1141 beams at 0.1667 deg with 8-bit RSSI.
    DeviceProfile lms5xx{
        "lms5xx", 0.05, 80.0, {25.0, 35.0, 50.0, 75.0, 100.0}, 25.0, {1.0F, 2.0F}, 2281, -75000,
        1875000,  8,    false};
    // TiM5xx/7xx: 0.05 m to 25 m (TiM571/781; TiM551 8 m, TiM561 10 m), 15 Hz, 270 deg at 0.33
    // deg: 811 beams.
    DeviceProfile tim{"tim5xx_7xx", 0.05, 25.0, {15.0}, 15.0, {1.0F}, 811, -475000, 2375000, 8, false};
    return std::vector<DeviceProfile>{lms1xx, lms5xx, tim};
  }();
  return all;
}

}  // namespace

const DeviceProfile* find_device_profile(std::string_view name) {
  for (const DeviceProfile& p : profiles()) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

const DeviceProfile& lms1xx_profile() { return profiles().front(); }

std::string device_profile_names() {
  std::string names;
  for (const DeviceProfile& p : profiles()) names += (names.empty() ? "" : ", ") + p.name;
  return names;
}

std::set<std::string> device_profile_name_set() {
  std::set<std::string> names;
  for (const DeviceProfile& p : profiles()) names.insert(p.name);
  return names;
}

}  // namespace refloc
