#include "plan_command.hpp"

#include "layout_plan.hpp"
#include "measured_outcome.hpp"
#include "placement_suggestions.hpp"
#include "plan_input.hpp"
#include "plan_progress.hpp"
#include "plan_report.hpp"

#include "common/child_program.hpp"
#include "common/json_config.hpp"
#include "common/program_version.hpp"
#include "common/robot_config.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>

namespace refloc {
namespace {

PlanConfig plan_config(const PlanOptions& o) {
  PlanConfig c;
  c.resolution = o.resolution_m;
  c.headings = o.headings;
  c.crlb_limit = 1e-3 * o.crlb_limit_mm;
  c.range_sigma = 1e-3 * o.range_sigma_mm;
  c.spot.samples = o.spot_samples;
  c.check_ambiguity = o.ambiguity;
  c.threads = o.threads;
  c.robot_T_laser = load_robot_config(o.robot_file).robot_T_laser;
  // The services' files read as the measurement reads them (default mode).
  const PipelineConfigs services =
      load_pipeline_configs(PipelineMode::kDefault, o.extractor_file, o.matcher_file, o.solver_file);
  c.matcher = services.matcher.matcher;
  c.extractor = services.extractor.extractor;
  c.solver = services.solver.solver;
  return c;
}

PlanProgress progress_of(PlanProgressBar& bar, bool show) {
  return show ? PlanProgress([&bar](size_t d, size_t t) { bar.update(d, t); }) : PlanProgress();
}

/// Rendered scans at sampled cells, before and (with suggestions) after; writes measure*.csv.
void measure(const PlanOptions& o, const PlanInput& input, bool terminal, PlanReport& report) {
  if (!input.has_world) throw ConfigError("--measure-cells needs --world (the scans are rendered from it)");
  const PipelineConfigs pipeline =
      load_pipeline_configs(PipelineMode::kDefault, o.extractor_file, o.matcher_file, o.solver_file);
  MeasureConfig config;
  config.cells = o.measure_cells;
  config.scans = o.measure_scans;
  config.seed = o.seed;
  const int m = report.config.matcher.min_matches;
  const auto run = [&](const sim::World& world, const ReflectorMap& map, const LayoutPlan& plan,
                       const std::string& csv) {
    PlanProgressBar bar(stderr, "measuring", terminal);
    const auto poses =
        measure_plan(world, map, plan, report.config, pipeline, config, progress_of(bar, o.progress));
    write_text_file(o.out_dir + "/" + csv, measurements_csv(poses, m));
    return measure_summary_text(summarize_measurements(poses, m), config);
  };
  report.measured = run(input.world, input.map, report.plan, "measure.csv");
  if (report.suggestions.empty()) return;
  sim::World world = input.world;
  for (const Suggestion& s : report.suggestions) world.reflectors.reflectors.push_back(s.reflector);
  report.measured_after =
      run(world, with_suggestions(input.map, report.suggestions), report.plan_after, "measure_after.csv");
}

}  // namespace

int run_plan(const PlanOptions& o) {
  PlanReport report;
  report.config = plan_config(o);
  PlanInput input = load_plan_input(o.map_file, o.world_file, o.occluders);
  for (const std::string& w : input.map.warnings) fmt::print(stderr, "refloc-plan: {}\n", w);
  report.map_name = input.map_name;
  report.map = input.map;
  report.drivable = input.drivable;
  const bool terminal = o.progress && isatty(fileno(stderr));
  PlanProgressBar bar(stderr, "planning", terminal);
  const PlanGrid grid = make_plan_grid(input.map, input.drivable, report.config.resolution);
  const auto start = std::chrono::steady_clock::now();
  report.plan = plan_layout(input.map, grid, report.config, progress_of(bar, o.progress));
  report.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (o.suggest > 0) {
    SuggestionConfig s;
    s.count = o.suggest;
    s.spacing = o.suggest_spacing_m;
    s.resolution = o.suggest_resolution_m;
    s.headings = o.suggest_headings;
    s.swap_rounds = o.suggest_swap_rounds;
    PlanProgressBar suggest_bar(stderr, "suggesting", terminal);
    report.suggestions =
        suggest_reflectors(input.map, input.drivable, report.config, s, progress_of(suggest_bar, o.progress));
    if (!report.suggestions.empty()) {
      const ReflectorMap after = with_suggestions(input.map, report.suggestions);
      PlanProgressBar after_bar(stderr, "after", terminal);
      report.plan_after = plan_layout(after, grid, report.config, progress_of(after_bar, o.progress));
    } else {
      fmt::print(stderr, "refloc-plan: no candidate position reduces the bad area (or there is none)\n");
    }
  }
  if (o.measure_cells > 0) measure(o, input, terminal, report);
  write_plan_report(report, o.out_dir);
  fmt::print("{}", plan_summary_text(report));
  fmt::print("wrote {0}/grid.json, {0}/summary.txt\n", o.out_dir);
  if (o.plot) {
    const int status = run_child_program({shipped_path("tools/refloc-plot/refloc-plot.py"), "plan", "--grid",
                                          o.out_dir + "/grid.json", "--out", o.out_dir + "/plan.png", "--out",
                                          o.out_dir + "/plan.svg"});
    if (status != 0) {
      fmt::print(stderr,
                 "refloc-plan: no picture (tools/refloc-plot needs /usr/bin/python3 and matplotlib)\n");
    } else {
      fmt::print("wrote {0}/plan.png, {0}/plan.svg\n", o.out_dir);
    }
  }
  return 0;
}

}  // namespace refloc
