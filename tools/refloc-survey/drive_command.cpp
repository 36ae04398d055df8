#include "drive_command.hpp"

#include "drive_anchors.hpp"
#include "drive_live.hpp"
#include "drive_log.hpp"
#include "drive_map_comparison.hpp"
#include "drive_report.hpp"
#include "drive_survey.hpp"
#include "drive_truth_check.hpp"

#include "common/guarded_main.hpp"
#include "common/json_config.hpp"
#include "common/output_file.hpp"
#include "common/program_version.hpp"
#include "common/robot_config.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "survey_map_warnings.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <fstream>

namespace refloc {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// --live: the drive recorded from the bus into a log; returns its path.
std::string record_live(const DriveCommandOptions& o, const ExtractorServiceConfig& extractor) {
  DriveLiveOptions live;
  live.lcm_url = o.lcm_url;
  live.scan_channel = extractor.input_channel;
  live.odometry_channel = extractor.odometry_channel;
  live.truth_channel = o.truth_channel;
  live.record_path = o.record_path.empty()
                         ? std::filesystem::path(o.out_path).replace_extension(".lcmlog").string()
                         : o.record_path;
  live.duration_s = o.duration_s;
  live.timeout_s = o.timeout_s;
  refuse_to_replace(live.record_path, o.force, "the log of another drive? or give --record");
  const DriveLiveCounts counts = record_drive_live(live);
  if (counts.scans == 0)
    throw ConfigError(
        fmt::format("no scan on {} ({}): nothing to survey", live.scan_channel, stop_reason(counts.stop)));
  return live.record_path;
}

std::vector<DriveScan> read_scans(const DriveCommandOptions& o, const ExtractorServiceConfig& extractor,
                                  const Pose2& robot_T_laser) {
  DriveScanCounts counts;
  DriveLogCounts log_counts;
  std::vector<DriveScan> scans = read_drive_log(o.log_path, extractor, robot_T_laser, {}, counts, log_counts);
  fmt::print(
      "{}: {} events; {} {} ({} refused by the extractor, {} without odometry), {} {}, {} undecodable; "
      "{} detections\n",
      o.log_path, log_counts.events, counts.scans, extractor.input_channel, counts.scans_rejected,
      counts.scans_without_odometry, counts.odometry, extractor.odometry_channel, log_counts.undecodable,
      counts.detections);
  if (scans.size() < 2)
    throw ConfigError(fmt::format("{}: {} usable scans with odometry ({} on {}, {} on {}): nothing to survey",
                                  o.log_path, scans.size(), counts.scans, extractor.input_channel,
                                  counts.odometry, extractor.odometry_channel));
  return scans;
}

/// Simulation: the map against the true one, printed and, with a report folder, written for the picture.
void compare_with_truth(const DriveCommandOptions& o, const ReflectorMap& map,
                        const DriveSurveyResult& survey, const Pose2& robot_T_laser) {
  const MapComparison c = compare_maps(map, load_reflector_map(o.truth_path));
  fmt::print("against {} (after a rigid alignment):\n{}", o.truth_path, comparison_text(c));
  if (!o.truth_channel.empty()) {
    const std::vector<TimedPose> truth = read_true_poses(o.log_path, o.truth_channel);
    if (truth.empty()) throw ConfigError(o.log_path + ": no " + o.truth_channel + " (--truth-channel)");
    fmt::print("{}", truth_check_text(check_detections_against_truth(survey, truth, c, robot_T_laser)));
  }
  if (o.report_dir.empty()) return;
  std::ofstream out(o.report_dir + "/comparison.csv");
  out << comparison_csv(c);
  if (!out) throw ConfigError(o.report_dir + "/comparison.csv: cannot write");
}

void draw(const DriveCommandOptions& o) {
  const int plot = draw_survey_report(o.report_dir, o.truth_path);
  if (plot == 0)
    fmt::print("report: {}/report.txt, picture {}/survey.png\n", o.report_dir, o.report_dir);
  else
    fmt::print(stderr, "refloc-survey: no picture (survey_drive_plot.py exit {})\n", plot);
}

}  // namespace

CLI::App* add_drive_command(CLI::App& app, DriveCommandOptions& o) {
  o.robot_path = shipped_path(o.robot_path);
  o.extractor_path = shipped_path(o.extractor_path);
  CLI::App* c = app.add_subcommand(
      "drive", "survey a hall from an LCM log of a drive (LMS100_SCAN, ODOMETRY), or live");
  CLI::Option* log = c->add_option("--log", o.log_path, "LCM log of the drive");
  CLI::Option* live =
      c->add_flag("--live", o.live,
                  "record the drive from the bus (until Ctrl-C, --duration-s or --timeout-s), "
                  "then survey that log");
  log->excludes(live);
  c->add_option("--record", o.record_path, "live: the LCM log to write (default: --out with .lcmlog)")
      ->needs(live);
  c->add_option("--lcm-url", o.lcm_url, "live: the bus (default: LCM_DEFAULT_URL, else LCM's default)")
      ->needs(live);
  c->add_option("--duration-s", o.duration_s, "live: stop recording after this long; 0: at Ctrl-C")
      ->check(CLI::Range(0.0, 86400.0))
      ->capture_default_str()
      ->needs(live);
  c->add_option("--timeout-s", o.timeout_s, "live: stop recording after this long without a scan")
      ->check(CLI::Range(0.1, 3600.0))
      ->capture_default_str()
      ->needs(live);
  c->callback([&o] {
    if (o.log_path.empty() && !o.live) throw CLI::RequiredError("--log F or --live");
  });
  c->add_option("--out", o.out_path, "the map file to write (format 2)")->required();
  c->add_option("--robot", o.robot_path, "robot file (laser mount, odometry noise)")->capture_default_str();
  c->add_option("--extractor-config", o.extractor_path, "reflector_extractor's config, as the service ran")
      ->capture_default_str();
  c->add_option("--start-pose", o.start_pose,
                "x_m,y_m,theta_rad of the robot at the first scan: the map frame")
      ->delimiter(',')
      ->expected(3);
  c->add_option("--anchors", o.anchors_path,
                "JSON file of 2+ reflectors with known map coordinates (fixes the frame)");
  c->add_option("--report", o.report_dir, "folder for the report's files and picture (survey.png)");
  c->add_option("--truth", o.truth_path, "simulation: the true map, compared and drawn");
  c->add_option("--truth-channel", o.truth_channel,
                "simulation, with --truth: also judge the detections at the true poses of this channel "
                "(GROUND_TRUTH)")
      ->needs("--truth");
  c->add_option("--map-id", o.map_id, "the map's id in its header")->capture_default_str();
  c->add_flag("--force", o.force, "replace an existing --out");
  c->add_flag("!--no-range-bias", o.estimate_range_bias,
              "hold the LMS100's range bias at 0 instead of estimating it");
  c->add_flag("!--as-service", o.mapping_corrections,
              "extract exactly as the service does; by default the survey models the wall behind a "
              "reflector and removes the centre fit's second-order bias, which a map's long averages "
              "need (README)");
  c->add_option("--same-view-steps", o.same_view_beam_steps,
                "detections of a reflector whose bearing stays within this many of the scan's beam steps "
                "of a run's first (and range within --same-view-range-m) weigh as one: a standing robot "
                "repeats the same beams' errors; 0: every detection independent")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 10.0));
  c->add_option("--scale-sigma-ppm", o.scale_sigma_ppm,
                "without anchors: the map's scale error, std dev, added to each reflector's covariance along "
                "its line from the map's centroid (the ranges alone set the scale); 0: none")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 100000.0));
  c->add_option("--same-view-range-m", o.same_view_range_m, "see --same-view-steps")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 10.0));
  return c;
}

int run_drive_command(const DriveCommandOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  refuse_to_replace(o.out_path, o.force);
  const RobotConfig robot = load_robot_config(o.robot_path);
  ExtractorServiceConfig extractor = load_extractor_service_config(o.extractor_path);
  if (o.mapping_corrections) extractor.extractor = mapping_corrections(extractor.extractor);
  const std::vector<SurveyAnchor> anchors =
      o.anchors_path.empty() ? std::vector<SurveyAnchor>{} : load_survey_anchors(o.anchors_path);
  DriveCommandOptions from_log = o;
  if (o.live) from_log.log_path = record_live(o, extractor);
  const auto read_start = std::chrono::steady_clock::now();
  const std::vector<DriveScan> scans = read_scans(from_log, extractor, robot.robot_T_laser);
  const double read_s = seconds_since(read_start);

  DriveSurveyConfig config;
  config.bundle.estimate_range_bias = o.estimate_range_bias;
  config.bundle.same_view_beam_steps = o.same_view_beam_steps;
  config.bundle.same_view_range_m = o.same_view_range_m;
  config.scale_sigma_ppm = o.scale_sigma_ppm;
  const Pose2 start_pose{o.start_pose[0], o.start_pose[1], o.start_pose[2]};
  const DriveSurveyResult survey =
      run_drive_survey(scans, robot.robot_T_laser, robot.odometry_noise, start_pose, anchors, config);
  const ReflectorMap map =
      surveyed_map(survey, survey.occluders, o.map_id, extractor.extractor.reflector_radius);
  fmt::print("{}", survey_report_text(survey));
  fmt::print("{} occluders traced; log read and extracted in {:.2f} s; total {:.2f} s{}\n",
             survey.occluders.size(), read_s, seconds_since(start), o.live ? " (with the recording)" : "");
  if (map.reflectors.size() < 3) {
    fmt::print(stderr, "refloc-survey: no map written: {} reflectors surveyed, a map needs 3\n",
               map.reflectors.size());
    return kExitRuntimeFailure;
  }
  const std::string self_similar = self_similar_map_warning(map);
  if (!self_similar.empty()) fmt::print(stderr, "refloc-survey: warning: {}\n", self_similar);
  write_reflector_map(map, o.out_path);
  fmt::print("map written: {}{}\n", o.out_path, self_similar.empty() ? "" : " (with the warning above)");
  if (!o.report_dir.empty()) write_survey_report(o.report_dir, survey, map);
  if (!o.truth_path.empty()) compare_with_truth(from_log, map, survey, robot.robot_T_laser);
  if (!o.report_dir.empty()) draw(o);
  return 0;
}

CLI::App* add_compare_command(CLI::App& app, CompareCommandOptions& o) {
  CLI::App* c = app.add_subcommand("compare", "a map against the true one: errors after a rigid alignment");
  c->add_option("--map", o.map_path, "the map to judge (e.g. a surveyed one)")->required();
  c->add_option("--truth", o.truth_path, "the true map (the world's map, a total-station survey)")
      ->required();
  c->add_option("--match-gate-m", o.match_gate_m, "an entry farther from every true reflector is extra")
      ->check(CLI::Range(0.001, 10.0))
      ->capture_default_str();
  c->add_flag("!--no-align", o.align, "compare in the frames as given (a map surveyed with anchors)");
  return c;
}

int run_compare_command(const CompareCommandOptions& o) {
  const ReflectorMap map = load_reflector_map(o.map_path);
  const ReflectorMap truth = load_reflector_map(o.truth_path);
  MapComparisonOptions options;
  options.align = o.align;
  options.match_gate = o.match_gate_m;
  const MapComparison c = compare_maps(map, truth, options);
  fmt::print("{} ({} reflectors) against {} ({}):\n{}", o.map_path, map.reflectors.size(), o.truth_path,
             truth.reflectors.size(), comparison_text(c));
  return c.aligned ? 0 : kExitRuntimeFailure;
}

}  // namespace refloc
