#pragma once
// refloc-eval's console tables and JSON of a study's result (eval_plot.hpp: its picture).

#include "accuracy_study.hpp"
#include "world_renderer/lms100_error_model.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace refloc {

/// The simulated sensor's error model, every field (lengths in m, angles in rad, RSSI in 16-bit units).
nlohmann::json to_json(const sim::Lms100ErrorModel& model);
/// One line naming the model's range error terms, for the text report.
std::string describe(const sim::Lms100ErrorModel& model);
/// A progress bar on stderr.
void print_progress(size_t done, size_t total);
/// One line of a mode's summary numbers.
void print_summary(const char* name, const ModeSummary& s);
/// The paper's Table 1 layout: per position the measurements, max errors, RMSE and CRLB.
void print_paper_table(const StudyResult& r, const std::vector<Pose2>& poses, int repeats);

}  // namespace refloc
