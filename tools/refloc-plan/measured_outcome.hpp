#pragma once
// The prediction checked against measurement: scans rendered at sampled grid poses (the
// world's LMS100 model, distractors included) run through refloc-eval's pipeline (the services'
// extractor, matcher and solver nodes, each scan without a prior), and the outcome compared with
// what PosePredictor said: blind / ambiguous / ok, and the fixes' RMSE against the CRLB.

#include "layout_plan.hpp"
#include "localization_pipeline.hpp"

#include "world_renderer/world.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace refloc {

/// "blind": no fix, "ambiguous": AMBIGUOUS or a fix at the wrong place, "ok": a fix here.
enum class PoseOutcome : signed char { kOk, kBlind, kAmbiguous };

const char* to_string(PoseOutcome outcome);

/// What PosePredictor's answer means as an outcome: fewer than min_matches visible or no fix
/// (kLost, kNoPose) is blind, kAmbiguous and kWrong are ambiguous, kUnique is ok.
PoseOutcome predicted_outcome(const PosePrediction& prediction, int min_matches);

struct MeasureConfig {
  int cells = 200;              ///< grid cells sampled (each at every plan heading) [-]
  int scans = 5;                ///< rendered scans per pose [-]
  uint64_t seed = 1;            ///< cell sampling and sensor noise
  double wrong_distance = 0.2;  ///< a fix farther from the truth is wrong [m]
};

struct PoseMeasurement {
  size_t cell = 0;  ///< index into the plan's cells
  Pose2 map_T_robot;
  PosePrediction predicted;
  int fixes_here = 0;                          ///< scans published OK within wrong_distance [-]
  int fixes_wrong = 0;                         ///< published OK elsewhere [-]
  int ambiguous = 0;                           ///< matcher AMBIGUOUS [-]
  int no_fix = 0;                              ///< the rest: LOST, nothing published [-]
  double rmse_xy = 0.0;                        ///< of the fixes here [m]
  PoseOutcome measured = PoseOutcome::kBlind;  ///< the majority, any wrong fix counting as ambiguous
};

struct MeasureSummary {
  size_t poses = 0, cells = 0;
  double pose_agreement = 0.0;  ///< poses whose predicted outcome is the measured one [-]
  double cell_agreement = 0.0;  ///< cells whose every heading agrees [-]
  /// Cells whose worst-heading outcome agrees (ambiguous if any heading is, else blind if any
  /// is, else ok; predicted and measured alike) [-].
  double cell_worst_agreement = 0.0;
  int cell_confusion[3][3] = {};  ///< [predicted][measured] worst-heading outcome of the cells [-]
  int confusion[3][3] = {};       ///< [predicted][measured], PoseOutcome order [-]
  size_t ratio_count = 0;         ///< poses with a bound and >= 2 fixes here [-]
  double ratio_median = 0.0, ratio_p10 = 0.0, ratio_p90 = 0.0;  ///< RMSE / CRLB sigma [-]
  double ratio_pooled = 0.0;     ///< sqrt(sum of squared errors / sum of CRLB variances) [-]
  double log_correlation = 0.0;  ///< Pearson of log CRLB sigma and log RMSE [-]
};

/// Measures config.cells random cells of plan at every plan heading against map (the
/// localization's map) in world (what is rendered). progress: (poses done, poses in all).
std::vector<PoseMeasurement> measure_plan(const sim::World& world, const ReflectorMap& map,
                                          const LayoutPlan& plan, const PlanConfig& plan_config,
                                          const PipelineConfigs& pipeline, const MeasureConfig& config,
                                          const PlanProgress& progress = {});

MeasureSummary summarize_measurements(const std::vector<PoseMeasurement>& poses, int min_matches);

/// One line per pose: cell, pose, prediction, measurement (CSV with a header).
std::string measurements_csv(const std::vector<PoseMeasurement>& poses, int min_matches);

/// The summary's lines (agreement, confusion matrix, RMSE / CRLB).
std::string measure_summary_text(const MeasureSummary& summary, const MeasureConfig& config);

}  // namespace refloc
