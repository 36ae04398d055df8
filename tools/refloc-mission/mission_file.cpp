#include "mission_file.hpp"

#include "common/json_config.hpp"

#include <fmt/format.h>

namespace refloc {

Mission load_mission(const std::string& path) {
  const JsonConfig c = JsonConfig::load_file(path);
  Mission m;
  const size_t n = c.array_size("/waypoints");
  if (n == 0) c.fail("/waypoints", "expected at least one waypoint");
  for (size_t i = 0; i < n; ++i) {
    const std::string w = fmt::format("/waypoints/{}", i);
    m.waypoints.push_back({c.required_number(w + "/x_m", -1e4, 1e4), c.required_number(w + "/y_m", -1e4, 1e4),
                           c.number(w + "/theta_deg", 0.0, -360.0, 360.0) * M_PI / 180.0});
  }
  m.xy_tolerance_m = c.number("/xy_tolerance_m", m.xy_tolerance_m, 0.001, 1.0);
  m.heading_tolerance_rad = c.number("/heading_tolerance_deg", 0.5, 0.01, 45.0) * M_PI / 180.0;
  m.max_speed_m_s = c.number("/max_speed_m_s", m.max_speed_m_s, 0.01, 3.0);
  m.timeout_s = c.number("/timeout_s", m.timeout_s, 1.0, 36000.0);
  m.localization_timeout_s = c.number("/localization_timeout_s", m.localization_timeout_s, 1.0, 3600.0);
  c.reject_unknown_keys();
  return m;
}

}  // namespace refloc
