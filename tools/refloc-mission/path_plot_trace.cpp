#include "path_plot_trace.hpp"

#include <fmt/format.h>

#include <fstream>

namespace refloc {
namespace {

std::string seconds_since(int64_t utime, int64_t start_utime) {
  return fmt::format("{:.4f}", static_cast<double>(utime - start_utime) * 1e-6);
}

std::string millimetres_or_empty(double value_m) {
  return std::isfinite(value_m) ? fmt::format("{:.3f}", value_m * 1000.0) : "";
}

}  // namespace

std::string path_trace_csv(const PathTrace& trace) {
  std::string csv = "kind,t_s,x_m,y_m,theta_rad,error_mm\n";
  for (const auto& s : trace.samples) {
    csv +=
        fmt::format("{},{},{:.5f},{:.5f},{:.6f},{}\n", s.channel, seconds_since(s.utime, trace.start_utime),
                    s.map_T_robot.x, s.map_T_robot.y, s.map_T_robot.theta, millimetres_or_empty(s.error_m));
  }
  for (const auto& w : trace.waypoints) {
    csv += fmt::format("WAYPOINT,{},{:.5f},{:.5f},{:.6f},{}\n",
                       w.reached ? seconds_since(w.reached_utime, trace.start_utime) : "", w.target.x,
                       w.target.y, w.target.theta, w.reached ? millimetres_or_empty(w.error_m) : "");
  }
  return csv;
}

bool write_path_trace_csv(const std::string& path, const PathTrace& trace) {
  std::ofstream out(path);
  return static_cast<bool>(out << path_trace_csv(trace));
}

}  // namespace refloc
