#include "eval_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace refloc {

void print_progress(size_t done, size_t total) {
  const int width = 40;
  const int filled = static_cast<int>(width * done / std::max<size_t>(total, 1));
  std::fprintf(stderr, "\r[%s%s] %zu/%zu", std::string(static_cast<size_t>(filled), '#').c_str(),
               std::string(static_cast<size_t>(width - filled), ' ').c_str(), done, total);
  if (done == total) std::fprintf(stderr, "\n");
}

void print_summary(const char* name, const ModeSummary& s) {
  fmt::print(
      "{:<8} published {:>5}/{:<5} wrong {:>3}  mean max err x {:6.2f} mm  y {:6.2f} mm  RMSE {:6.2f} mm  "
      "CRLB {:6.2f} mm  RMSE/CRLB {:5.2f} (point beams {:5.2f} mm, {:5.2f})  heading RMSE {:.3f} deg  "
      "recall {:.4f}  false det. {:.4f}\n",
      name, s.published_ok, s.measurements, s.wrong_matches, s.mean_max_err_x_mm, s.mean_max_err_y_mm,
      s.rmse_mm, s.crlb_rmse_mm, s.crlb_ratio, s.point_beam_crlb_rmse_mm, s.point_beam_crlb_ratio,
      s.heading_rmse_deg, s.recall, s.false_detection_rate);
}

void print_paper_table(const StudyResult& r, const std::vector<Pose2>& poses, int repeats) {
  fmt::print("Table 1 protocol: robot static at 10 positions, {} measurements each (mm)\n", repeats);
  for (PipelineMode mode : {PipelineMode::kPaper, PipelineMode::kDefault}) {
    fmt::print("\nmode {}\n{:>3}  {:<48} {:<14} {:<18} {:>6} {:>6}\n", to_string(mode), "No", "measured",
               "actual", "(dx_max, dy_max)", "RMSE", "CRLB");
    for (size_t p = 0; p < poses.size(); ++p) {
      std::string measured;
      double dx = 0.0, dy = 0.0, sum_e2 = 0.0, sum_crlb = 0.0;
      int n_e = 0, n_crlb = 0;
      for (const auto& m : r.measurements) {
        if (m.mode != mode || m.pose_index != static_cast<int>(p)) continue;
        if (m.has_crlb) {
          sum_crlb += m.crlb_var_xy;
          ++n_crlb;
        }
        if (!m.published_ok) {
          measured += "(  no pose  ) ";
          continue;
        }
        measured += fmt::format("({:.1f}, {:.1f}) ", 1000 * m.estimate.x, 1000 * m.estimate.y);
        dx = std::max(dx, std::abs(m.estimate.x - m.truth.x));
        dy = std::max(dy, std::abs(m.estimate.y - m.truth.y));
        sum_e2 += (m.estimate.translation() - m.truth.translation()).squaredNorm();
        ++n_e;
      }
      const std::string rmse = n_e > 0 ? fmt::format("{:.2f}", 1000 * std::sqrt(sum_e2 / n_e)) : "-";
      const std::string crlb = n_crlb > 0 ? fmt::format("{:.2f}", 1000 * std::sqrt(sum_crlb / n_crlb)) : "-";
      fmt::print("{:>3}  {:<48} {:<14} {:<18} {:>6} {:>6}\n", p + 1, measured,
                 fmt::format("({:.0f}, {:.0f})", 1000 * poses[p].x, 1000 * poses[p].y),
                 fmt::format("({:.1f}, {:.1f})", 1000 * dx, 1000 * dy), rmse, crlb);
    }
    fmt::print("RMSE and CRLB: position error over the measurements (mm); CRLB of the LMS100 beam spot\n");
  }
  fmt::print("\npaper (LabVIEW, real LMS100): mean max err x 14.30 mm  y 14.70 mm\n");
}

std::vector<Eigen::Vector2d> errors_mm(const StudyResult& r, PipelineMode mode) {
  std::vector<Eigen::Vector2d> e;
  for (const auto& m : r.measurements) {
    if (m.mode == mode && m.published_ok && !m.wrong) {
      e.push_back(1000.0 * Eigen::Vector2d(m.estimate.x - m.truth.x, m.estimate.y - m.truth.y));
    }
  }
  return e;
}

std::vector<Eigen::Vector2d> paper_reported_errors_mm() {
  const double d[30][2] = {
      {5, 10},   {-12, 9},  {12, 13}, {8, 11}, {-9, 12}, {17, -14}, {10, -11}, {6, 9},   {-11, 15}, {7, 11},
      {10, 9},   {-12, 15}, {20, 9},  {-9, 7}, {6, 10},  {-6, 7},   {6, 11},   {8, 10},  {60, 15},  {7, 8},
      {-10, 13}, {14, 17},  {23, 8},  {9, 4},  {15, 1},  {-10, 18}, {12, 11},  {16, 19}, {11, 13},  {12, 15}};
  std::vector<Eigen::Vector2d> e;
  for (const auto& p : d) e.emplace_back(p[0], p[1]);
  return e;
}

}  // namespace refloc
