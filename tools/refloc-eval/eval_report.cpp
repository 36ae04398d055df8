#include "eval_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace refloc {

nlohmann::json to_json(const sim::Lms100ErrorModel& m) {
  return {{"range_sigma", m.range_sigma},
          {"weak_echo_sigma_factor", m.weak_echo_sigma_factor},
          {"range_offset", m.range_offset},
          {"range_scale_ppm", m.range_scale_ppm},
          {"range_walk_weak", m.range_walk_weak},
          {"range_walk_bright", m.range_walk_bright},
          {"range_walk_rssi_weak", m.range_walk_rssi_weak},
          {"range_walk_rssi_bright", m.range_walk_rssi_bright},
          {"retro_range_bias", m.retro_range_bias},
          {"range_min", m.range_min},
          {"range_max", m.range_max},
          {"quantize_to_mm", m.quantize_to_mm},
          {"beam_divergence", m.beam_divergence},
          {"beam_exit_diameter", m.beam_exit_diameter},
          {"beam_subrays", m.beam_subrays},
          {"echo_merge_distance", m.echo_merge_distance},
          {"detection_limit_remission", m.detection_limit_remission},
          {"detection_limit_range", m.detection_limit_range},
          {"rssi_at_detection_limit", m.rssi_at_detection_limit},
          {"rssi_per_decade", m.rssi_per_decade},
          {"diffuse_rssi_max", m.diffuse_rssi_max},
          {"max_incidence", m.max_incidence},
          {"retro_rssi_near", m.retro_rssi_near},
          {"retro_rssi_drop_per_m", m.retro_rssi_drop_per_m},
          {"retro_incidence_exponent", m.retro_incidence_exponent},
          {"tape_rssi_near", m.tape_rssi_near},
          {"tape_full_incidence", m.tape_full_incidence},
          {"tape_cutoff_incidence", m.tape_cutoff_incidence},
          {"metal_rssi_peak", m.metal_rssi_peak},
          {"metal_lobe_width", m.metal_lobe_width},
          {"rssi_coverage_exponent", m.rssi_coverage_exponent},
          {"rssi_sigma", m.rssi_sigma},
          {"rssi_scale", sim::to_string(m.rssi_scale)},
          {"dazzle_range", m.dazzle_range}};
}

std::string describe(const sim::Lms100ErrorModel& m) {
  return fmt::format(
      "sensor: sigma {:.1f} mm, offset {:+.1f} mm, scale {:+.0f} ppm, walk {:+.1f} mm at RSSI <= {:.0f} to "
      "{:+.1f} mm at RSSI >= {:.0f}, retro bias {:+.1f} mm, RSSI scale {}",
      1000 * m.range_sigma, 1000 * m.range_offset, m.range_scale_ppm, 1000 * m.range_walk_weak,
      m.range_walk_rssi_weak, 1000 * m.range_walk_bright, m.range_walk_rssi_bright, 1000 * m.retro_range_bias,
      sim::to_string(m.rssi_scale));
}

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
  fmt::print("{:<8} matcher OK {} of {} scans, {} of them with a wrong pair\n", "", s.match_ok,
             s.measurements, s.match_ok_wrong);
  const ConsistencySummary& c = s.consistency;
  fmt::print(
      "{:<8} NEES over {} OK fixes ({} unusable covariances): position mean {:.2f} (honest 2), outside 99 % "
      "{:.1f} % (honest 1 %); heading mean {:.2f} (honest 1), outside 99 % {:.1f} %\n",
      "", c.fixes, c.unusable_covariances, c.position_nees_mean, 100 * c.position_outside_99,
      c.heading_nees_mean, 100 * c.heading_outside_99);
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

}  // namespace refloc
