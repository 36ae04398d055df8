#include "path_plot_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <limits>

namespace refloc {

bool write_path_plot_svg(const std::string& path, const std::string& title,
                         const std::vector<PlotSeries>& series) {
  double min_x = std::numeric_limits<double>::max(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  for (const auto& s : series) {
    for (const auto& p : s.points) {
      min_x = std::min(min_x, p.x());
      max_x = std::max(max_x, p.x());
      min_y = std::min(min_y, p.y());
      max_y = std::max(max_y, p.y());
    }
  }
  if (min_x > max_x) min_x = min_y = 0.0, max_x = max_y = 1.0;
  const double margin = 0.5, width_px = 1000.0;
  const double scale = width_px / std::max(max_x - min_x + 2 * margin, 1e-3);
  const double height_px = (max_y - min_y + 2 * margin) * scale;
  // SVG's y axis points down; the map's points up.
  auto px = [&](const Eigen::Vector2d& p) {
    return fmt::format("{:.1f},{:.1f}", (p.x() - min_x + margin) * scale, (max_y + margin - p.y()) * scale);
  };
  std::ofstream out(path);
  if (!out) return false;
  out << fmt::format(R"(<svg xmlns="http://www.w3.org/2000/svg" width="{:.0f}" height="{:.0f}">)", width_px,
                     height_px + 40)
      << "\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << fmt::format("<text x=\"10\" y=\"{:.0f}\" font-family=\"sans-serif\" font-size=\"14\">{}</text>\n",
                     height_px + 20, title);
  double legend_x = 10;
  for (const auto& s : series) {
    if (s.markers) {
      for (const auto& p : s.points) {
        const auto c = px(p);
        const auto comma = c.find(',');
        out << fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"4\" fill=\"{}\"/>\n", c.substr(0, comma),
                           c.substr(comma + 1), s.color);
      }
    } else if (!s.points.empty()) {
      out << "<polyline fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\"1.5\" points=\"";
      for (const auto& p : s.points) out << px(p) << ' ';
      out << "\"/>\n";
    }
    out << fmt::format(
        "<text x=\"{:.0f}\" y=\"{:.0f}\" font-family=\"sans-serif\" font-size=\"13\" fill=\"{}\">{}</text>\n",
        legend_x, height_px + 36, s.color, s.label);
    legend_x += 12.0 * static_cast<double>(s.label.size()) + 20.0;
  }
  out << "</svg>\n";
  return static_cast<bool>(out);
}

}  // namespace refloc
