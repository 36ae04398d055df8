#include "mission_file.hpp"

#include "common/json_config.hpp"

#include <fmt/format.h>

namespace refloc {

Mission parse_mission(const JsonConfig& c) {
  Mission m;
  const size_t n =
      c.array_size({"/waypoints", "", "where to drive, in order: [{x_m, y_m, theta_deg}], at least one"});
  if (n == 0) c.fail("/waypoints", "expected at least one waypoint");
  for (size_t i = 0; i < n; ++i) {
    const std::string w = fmt::format("/waypoints/{}", i);
    m.waypoints.push_back({c.required_number({w + "/x_m", "m", "waypoint x in the map frame"}, -1e4, 1e4),
                           c.required_number({w + "/y_m", "m", "waypoint y in the map frame"}, -1e4, 1e4),
                           c.number({w + "/theta_deg", "deg",
                                     "heading to arrive with (robot +x against map +x, counter-clockwise)"},
                                    0.0, -360.0, 360.0) *
                               M_PI / 180.0});
  }
  m.xy_tolerance_m =
      c.number({"/xy_tolerance_m", "m",
                "sent in each NAV_GOAL: the navigator reports the waypoint reached within this distance"},
               m.xy_tolerance_m, 0.001, 1.0);
  m.heading_tolerance_rad =
      c.number({"/heading_tolerance_deg", "deg",
                "sent in each NAV_GOAL: the navigator also needs the heading within this"},
               0.5, 0.01, 45.0) *
      M_PI / 180.0;
  m.max_speed_m_s = c.number(
      {"/max_speed_m_s", "m/s", "speed limit sent with each goal (the navigator's own limits still apply)"},
      m.max_speed_m_s, 0.01, 3.0);
  m.timeout_s = c.number(
      {"/timeout_s", "s", "driving longer than this aborts the mission (exit 1, waypoints left unreached)"},
      m.timeout_s, 1.0, 36000.0);
  m.localization_timeout_s = c.number(
      {"/localization_timeout_s", "s", "no POSE with status OK within this long after start: exit 1"},
      m.localization_timeout_s, 1.0, 3600.0);
  return m;
}

Mission load_mission(const std::string& path) {
  const JsonConfig c = JsonConfig::load_file(path);
  Mission m = parse_mission(c);
  c.reject_unknown_keys();
  return m;
}

}  // namespace refloc
