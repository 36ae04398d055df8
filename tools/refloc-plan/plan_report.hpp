#pragma once
// refloc-plan's outputs: grid.json (every cell, the map, the drivable area, the suggestions
// and the plan after them; tools/refloc-plot/refloc-plot.py plan draws it) and summary.txt.

#include "layout_plan.hpp"
#include "placement_suggestions.hpp"

#include <string>
#include <vector>

namespace refloc {

struct PlanReport {
  std::string map_name;
  ReflectorMap map;
  std::vector<sim::DrivableArea> drivable;
  PlanConfig config;
  LayoutPlan plan;
  std::vector<Suggestion> suggestions;
  LayoutPlan plan_after;       ///< with the suggestions (cells empty when there are none)
  double runtime_s = 0.0;      ///< of plan (not of the suggestions) [s]
  std::string measured;        ///< measure_summary_text of the plan ("" when not measured)
  std::string measured_after;  ///< same with the suggestions added to map and world
};

/// The summary's lines: area fractions, median bound, and the suggestions' before/after.
std::string plan_summary_text(const PlanReport& report);

/// The whole report as the JSON text of grid.json (lengths in m, sigma in mm and mrad).
std::string plan_json_text(const PlanReport& report);

/// Writes out_dir/grid.json and out_dir/summary.txt (the folder is created). Throws
/// std::runtime_error naming the file that cannot be written.
/// Writes text to path (its folder created); std::runtime_error naming the path on failure.
void write_text_file(const std::string& path, const std::string& text);

void write_plan_report(const PlanReport& report, const std::string& out_dir);

}  // namespace refloc
