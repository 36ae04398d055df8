#include "rssi_calibration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>

namespace refloc {
namespace {

constexpr int kBins = 52;  // bins of 5 over 0..260 on the 8-bit scale
constexpr double kBinWidth = 5.0;
constexpr double kLeft = 60.0, kTop = 40.0, kWidth = 780.0, kHeight = 360.0;

double x_of(double rssi) { return kLeft + rssi / (kBins * kBinWidth) * kWidth; }

void vertical(std::string& svg, double rssi, const char* colour, const std::string& label, double label_y) {
  const double x = x_of(rssi);
  svg += fmt::format(
      "<line x1='{0:.1f}' y1='{1}' x2='{0:.1f}' y2='{2}' stroke='{3}' stroke-dasharray='4 3'/>"
      "<text x='{4:.1f}' y='{5}' font-size='11' fill='{3}'>{6}</text>\n",
      x, kTop, kTop + kHeight, colour, x + 3.0, label_y, label);
}

}  // namespace

std::string rssi_histogram_svg(const std::vector<RssiSample>& samples, const RssiCalibration& calibration) {
  std::array<double, kBins> reflector{}, other{};
  for (const RssiSample& s : samples) {
    const int bin = std::clamp(static_cast<int>(s.rssi_8bit / kBinWidth), 0, kBins - 1);
    (s.on_reflector ? reflector : other)[static_cast<size_t>(bin)] += 1.0;
  }
  double max_count = 1.0;
  for (int i = 0; i < kBins; ++i) max_count = std::max({max_count, reflector[i], other[i]});
  const double log_max = std::log10(max_count + 1.0);
  auto y_of = [&](double count) { return kTop + kHeight - std::log10(count + 1.0) / log_max * kHeight; };

  std::string svg = fmt::format(
      "<svg xmlns='http://www.w3.org/2000/svg' width='{}' height='{}' font-family='sans-serif'>\n"
      "<rect width='100%' height='100%' fill='white'/>\n"
      "<text x='{}' y='22' font-size='14'>RSSI of echo beams (8-bit scale), count on a log scale: "
      "reflector {} beams (red), other {} beams (grey)</text>\n",
      kLeft + kWidth + 40.0, kTop + kHeight + 50.0, kLeft, calibration.reflector.count,
      calibration.other.count);
  const double bar = kWidth / kBins;
  for (int i = 0; i < kBins; ++i) {
    const double x = kLeft + i * bar;
    for (const auto& [counts, colour, inset] :
         {std::tuple{&other, "#999999", 0.0}, std::tuple{&reflector, "#d62728", bar * 0.25}}) {
      const double count = (*counts)[static_cast<size_t>(i)];
      if (count <= 0.0) continue;
      const double y = y_of(count);
      svg += fmt::format(
          "<rect x='{:.1f}' y='{:.1f}' width='{:.1f}' height='{:.1f}' fill='{}' opacity='0.8'/>\n", x + inset,
          y, bar - 2.0 * inset, kTop + kHeight - y, colour);
    }
  }
  svg += fmt::format("<rect x='{}' y='{}' width='{}' height='{}' fill='none' stroke='black'/>\n", kLeft, kTop,
                     kWidth, kHeight);
  for (int v = 0; v <= 250; v += 50) {
    svg += fmt::format("<text x='{:.1f}' y='{}' font-size='11' text-anchor='middle'>{}</text>\n", x_of(v),
                       kTop + kHeight + 15.0, v);
  }
  svg += fmt::format("<text x='{}' y='{}' font-size='11'>max count {:.0f}</text>\n", kLeft, kTop - 5.0,
                     max_count);
  const ThresholdRecommendation& r = calibration.recommendation;
  if (r.have_both) {
    vertical(svg, r.other_p999, "#555555", fmt::format("other p99.9 {:.1f}", r.other_p999), kTop + 15.0);
    vertical(svg, r.reflector_p1, "#d62728", fmt::format("reflector p1 {:.1f}", r.reflector_p1), kTop + 30.0);
    vertical(svg, r.threshold, "#1f77b4", fmt::format("threshold {:.0f}", r.threshold), kTop + 45.0);
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace refloc
