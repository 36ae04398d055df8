#pragma once
// A plain SVG plot of paths in the map frame (true vs estimated), with
// reflectors and waypoints, readable in any browser.

#include "common/se2.hpp"

#include <string>
#include <vector>

namespace refloc {

struct PlotSeries {
  std::string label;
  std::string color;  ///< SVG colour name or #rrggbb
  std::vector<Eigen::Vector2d> points;
  bool markers = false;  ///< draw points instead of a line
};

/// Write the series into an SVG file; returns false when the file cannot be written.
bool write_path_plot_svg(const std::string& path, const std::string& title,
                         const std::vector<PlotSeries>& series);

}  // namespace refloc
