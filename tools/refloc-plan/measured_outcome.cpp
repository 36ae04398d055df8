#include "measured_outcome.hpp"

#include "world_renderer/scan_renderer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace refloc {

const char* to_string(PoseOutcome outcome) {
  switch (outcome) {
    case PoseOutcome::kOk:
      return "ok";
    case PoseOutcome::kBlind:
      return "blind";
    case PoseOutcome::kAmbiguous:
      return "ambiguous";
  }
  return "?";
}

PoseOutcome predicted_outcome(const PosePrediction& p, int min_matches) {
  if (p.visible < min_matches || p.relocalization == Relocalization::kLost ||
      p.relocalization == Relocalization::kNoPose) {
    return PoseOutcome::kBlind;
  }
  if (p.relocalization == Relocalization::kAmbiguous || p.relocalization == Relocalization::kWrong) {
    return PoseOutcome::kAmbiguous;
  }
  return PoseOutcome::kOk;
}

std::vector<PoseMeasurement> measure_plan(const sim::World& world, const ReflectorMap& map,
                                          const LayoutPlan& plan, const PlanConfig& plan_config,
                                          const PipelineConfigs& pipeline_configs,
                                          const MeasureConfig& config, const PlanProgress& progress) {
  std::mt19937_64 rng(config.seed);
  std::vector<size_t> cells(plan.cells.size());
  std::iota(cells.begin(), cells.end(), size_t{0});
  std::shuffle(cells.begin(), cells.end(), rng);
  cells.resize(std::min(cells.size(), static_cast<size_t>(std::max(config.cells, 0))));
  std::sort(cells.begin(), cells.end());
  sim::ScanRenderer renderer{sim::ScanRenderConfig{}};
  LocalizationPipeline pipeline(PipelineMode::kDefault, pipeline_configs, map, plan_config.robot_T_laser);
  PosePredictor predictor(map, plan_config);
  const int headings = std::max(plan_config.headings, 1);
  std::vector<PoseMeasurement> out;
  LaserScan scan;
  int64_t utime = 1700000000000000;
  const size_t total = cells.size() * static_cast<size_t>(headings);
  for (size_t c : cells) {
    for (int h = 0; h < headings; ++h) {
      PoseMeasurement m;
      m.cell = c;
      m.map_T_robot = Pose2{plan.cells[c].map_p.x(), plan.cells[c].map_p.y(), 2.0 * M_PI * h / headings};
      m.predicted = predictor.predict(m.map_T_robot);
      const Pose2 map_T_laser = m.map_T_robot * plan_config.robot_T_laser;
      double sum_squared = 0.0;
      for (int s = 0; s < config.scans; ++s) {
        // 10 s apart: beyond every prior's age, each scan is relocalized from the map alone.
        utime += 10000000;
        renderer.render(world, map_T_laser, utime, rng, scan);
        const PipelineOutput& o = pipeline.on_scan(scan);
        const double error = (o.fix->map_T_robot.translation() - m.map_T_robot.translation()).norm();
        if (o.match->result.status == MatchStatus::kAmbiguous) {
          ++m.ambiguous;
        } else if (!o.published_ok()) {
          ++m.no_fix;
        } else if (error > config.wrong_distance) {
          ++m.fixes_wrong;
        } else {
          ++m.fixes_here;
          sum_squared += error * error;
        }
      }
      m.rmse_xy = m.fixes_here > 0 ? std::sqrt(sum_squared / m.fixes_here) : 0.0;
      if (m.fixes_wrong > 0 || (m.ambiguous >= m.fixes_here && m.ambiguous >= m.no_fix && m.ambiguous > 0)) {
        m.measured = PoseOutcome::kAmbiguous;
      } else {
        m.measured = m.no_fix > m.fixes_here ? PoseOutcome::kBlind : PoseOutcome::kOk;
      }
      out.push_back(m);
      if (progress) progress(out.size(), total);
    }
  }
  return out;
}

namespace {

/// Ambiguous is worse than blind, blind worse than ok.
PoseOutcome worse(PoseOutcome a, PoseOutcome b) {
  const auto rank = [](PoseOutcome o) {
    return o == PoseOutcome::kAmbiguous ? 2 : o == PoseOutcome::kBlind ? 1 : 0;
  };
  return rank(a) >= rank(b) ? a : b;
}

}  // namespace

MeasureSummary summarize_measurements(const std::vector<PoseMeasurement>& poses, int min_matches) {
  MeasureSummary s;
  s.poses = poses.size();
  std::vector<double> ratios, log_sigma, log_rmse;
  double errors2 = 0.0, variances = 0.0;
  size_t agree = 0, cells_agree = 0, worst_agree = 0;
  for (size_t i = 0; i < poses.size(); ++i) {
    const PoseMeasurement& m = poses[i];
    const PoseOutcome predicted = predicted_outcome(m.predicted, min_matches);
    ++s.confusion[static_cast<int>(predicted)][static_cast<int>(m.measured)];
    agree += predicted == m.measured;
    const bool first_of_cell = i == 0 || poses[i - 1].cell != m.cell;
    if (first_of_cell) {
      ++s.cells;
      bool all = true;
      PoseOutcome worst_predicted = PoseOutcome::kOk, worst_measured = PoseOutcome::kOk;
      for (size_t k = i; k < poses.size() && poses[k].cell == m.cell; ++k) {
        const PoseOutcome p = predicted_outcome(poses[k].predicted, min_matches);
        all = all && p == poses[k].measured;
        worst_predicted = worse(worst_predicted, p);
        worst_measured = worse(worst_measured, poses[k].measured);
      }
      cells_agree += all;
      worst_agree += worst_predicted == worst_measured;
      ++s.cell_confusion[static_cast<int>(worst_predicted)][static_cast<int>(worst_measured)];
    }
    if (m.predicted.has_bound && m.fixes_here >= 2 && m.predicted.sigma_xy > 0.0 && m.rmse_xy > 0.0) {
      ratios.push_back(m.rmse_xy / m.predicted.sigma_xy);
      log_sigma.push_back(std::log(m.predicted.sigma_xy));
      log_rmse.push_back(std::log(m.rmse_xy));
      errors2 += m.rmse_xy * m.rmse_xy * m.fixes_here;
      variances += m.predicted.sigma_xy * m.predicted.sigma_xy * m.fixes_here;
    }
  }
  if (s.poses == 0) return s;
  s.pose_agreement = static_cast<double>(agree) / static_cast<double>(s.poses);
  s.cell_agreement = static_cast<double>(cells_agree) / static_cast<double>(s.cells);
  s.cell_worst_agreement = static_cast<double>(worst_agree) / static_cast<double>(s.cells);
  s.ratio_count = ratios.size();
  if (!ratios.empty()) {
    std::sort(ratios.begin(), ratios.end());
    const auto at = [&](double q) {
      return ratios[static_cast<size_t>(q * static_cast<double>(ratios.size() - 1))];
    };
    s.ratio_median = at(0.5);
    s.ratio_p10 = at(0.1);
    s.ratio_p90 = at(0.9);
    s.ratio_pooled = std::sqrt(errors2 / variances);
    const double n = static_cast<double>(log_sigma.size());
    const double ms = std::accumulate(log_sigma.begin(), log_sigma.end(), 0.0) / n;
    const double mr = std::accumulate(log_rmse.begin(), log_rmse.end(), 0.0) / n;
    double sxy = 0.0, sxx = 0.0, syy = 0.0;
    for (size_t k = 0; k < log_sigma.size(); ++k) {
      sxy += (log_sigma[k] - ms) * (log_rmse[k] - mr);
      sxx += (log_sigma[k] - ms) * (log_sigma[k] - ms);
      syy += (log_rmse[k] - mr) * (log_rmse[k] - mr);
    }
    s.log_correlation = sxx > 0.0 && syy > 0.0 ? sxy / std::sqrt(sxx * syy) : 0.0;
  }
  return s;
}

std::string measurements_csv(const std::vector<PoseMeasurement>& poses, int min_matches) {
  std::string csv =
      "cell,x_m,y_m,theta_rad,visible,relocalization,predicted,crlb_sigma_xy_mm,fixes_here,fixes_wrong,"
      "ambiguous,"
      "no_fix,measured,rmse_xy_mm\n";
  for (const PoseMeasurement& m : poses) {
    csv += fmt::format("{},{:.3f},{:.3f},{:.4f},{},{},{},{},{},{},{},{},{},{}\n", m.cell, m.map_T_robot.x,
                       m.map_T_robot.y, m.map_T_robot.theta, m.predicted.visible,
                       to_string(m.predicted.relocalization),
                       to_string(predicted_outcome(m.predicted, min_matches)),
                       m.predicted.has_bound ? fmt::format("{:.3f}", 1e3 * m.predicted.sigma_xy) : "",
                       m.fixes_here, m.fixes_wrong, m.ambiguous, m.no_fix, to_string(m.measured),
                       m.fixes_here > 0 ? fmt::format("{:.3f}", 1e3 * m.rmse_xy) : "");
  }
  return csv;
}

std::string measure_summary_text(const MeasureSummary& s, const MeasureConfig& config) {
  std::string text = fmt::format(
      "prediction vs rendered scans ({} cells x headings = {} poses, {} scans each, refloc-eval's pipeline "
      "without a prior):\n"
      "  outcome agrees on {:.1f} % of poses; on {:.1f} % of cells by the worst heading's outcome, on "
      "every heading of {:.1f} % of cells\n"
      "  predicted \\ measured: ok / blind / ambiguous\n",
      s.cells, s.poses, config.scans, 100.0 * s.pose_agreement, 100.0 * s.cell_worst_agreement,
      100.0 * s.cell_agreement);
  for (int p = 0; p < 3; ++p) {
    text += fmt::format("    {:>9}: {} / {} / {}\n", to_string(static_cast<PoseOutcome>(p)),
                        s.confusion[p][0], s.confusion[p][1], s.confusion[p][2]);
  }
  text += "  cells (worst heading), predicted \\ measured: ok / blind / ambiguous\n";
  for (int p = 0; p < 3; ++p) {
    text += fmt::format("    {:>9}: {} / {} / {}\n", to_string(static_cast<PoseOutcome>(p)),
                        s.cell_confusion[p][0], s.cell_confusion[p][1], s.cell_confusion[p][2]);
  }
  text += fmt::format(
      "  fix RMSE / CRLB sigma over {} poses: median {:.2f}, 10-90 % {:.2f}-{:.2f}, pooled {:.2f}; "
      "correlation of log CRLB and log RMSE {:.2f}\n",
      s.ratio_count, s.ratio_median, s.ratio_p10, s.ratio_p90, s.ratio_pooled, s.log_correlation);
  return text;
}

}  // namespace refloc
