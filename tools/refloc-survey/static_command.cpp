#include "static_command.hpp"

#include "common/guarded_main.hpp"
#include "common/json_config.hpp"
#include "common/output_file.hpp"
#include "common/program_version.hpp"
#include "common/robot_config.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "reflector_extractor/extractor_node.hpp"
#include "static_progress.hpp"
#include "static_scans.hpp"
#include "survey_map_warnings.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>

namespace refloc {
namespace {

StaticSurveyConfig survey_config(const StaticCommandOptions& o) {
  StaticSurveyConfig config;
  config.min_seen_fraction = o.min_seen_fraction;
  config.range_bias_m = o.range_bias_mm * 1e-3;
  config.range_bias_sigma_m = o.range_bias_sigma_mm * 1e-3;
  return config;
}

// N scans through the extractor the service runs, into the survey, with the progress on stderr.
void collect(const StaticCommandOptions& o, const ExtractorServiceConfig& extractor,
             const Pose2& robot_T_laser, StaticSurvey& survey) {
  ExtractorNode node(extractor, robot_T_laser);
  SurveyProgress progress(stderr, o.scans, ::isatty(STDERR_FILENO) != 0);
  int rejected = 0;
  const ScanSink sink = [&](const LaserScan& scan) {
    const ExtractorOutput& out = node.on_scan(scan);
    if (!out.accepted) return ++rejected, false;
    survey.add_scan(out.detections);
    progress.update(survey.scans(), static_cast<int>(out.detections.size()));
    return true;
  };
  const std::string channel = o.channel.empty() ? extractor.input_channel : o.channel;
  const ScanReadCounts counts = o.log_path.empty()
                                    ? read_live_scans(o.lcm_url, channel, o.scans, o.timeout_s, sink)
                                    : read_log_scans(o.log_path, channel, o.scans, sink);
  progress.finish();
  const std::string from = o.log_path.empty() ? "the bus" : o.log_path;
  fmt::print("{}: {} scans used of {} on {} ({} refused by the extractor's input checks, {} undecodable)\n",
             from, counts.counted, counts.messages, channel, rejected, counts.undecodable);
  if (counts.counted == 0) throw ConfigError(fmt::format("{}: no usable scan on {}", from, channel));
  if (counts.counted < o.scans)
    fmt::print(stderr, "refloc-survey: warning: {} scans of the {} asked for\n", counts.counted, o.scans);
}

}  // namespace

CLI::App* add_static_command(CLI::App& app, StaticCommandOptions& o) {
  o.robot_path = shipped_path(o.robot_path);
  o.extractor_path = shipped_path(o.extractor_path);
  CLI::App* c =
      app.add_subcommand("static", "survey the reflectors around the robot standing still (N scans)");
  c->add_option("--pose", o.pose,
                "x_m,y_m,theta_rad of the robot in the map (default 0,0,0: it defines the frame)")
      ->delimiter(',')
      ->expected(3);
  c->add_option("--scans", o.scans, "scans to average")->check(CLI::Range(2, 100000))->capture_default_str();
  c->add_option("--log", o.log_path, "LCM log with the scans (default: live from the bus)");
  c->add_option("--lcm-url", o.lcm_url, "LCM URL when live (default: $LCM_DEFAULT_URL or udpm ttl=0)");
  c->add_option("--channel", o.channel, "scan channel (default: the extractor config's, LMS100_SCAN)");
  c->add_option("--timeout-s", o.timeout_s, "live: give up after this long without a scan")
      ->check(CLI::Range(0.1, 3600.0))
      ->capture_default_str();
  c->add_option("--robot", o.robot_path, "robot file (laser mount)")->capture_default_str();
  c->add_option("--extractor-config", o.extractor_path, "reflector_extractor's config, as the service runs")
      ->capture_default_str();
  c->add_option("--out", o.out_path, "the map file to write (format 2)")->required();
  c->add_option("--map-id", o.map_id, "the map's id in its header")->capture_default_str();
  c->add_option("--range-bias-mm", o.range_bias_mm,
                "the LMS100's systematic range error, measured - true [mm]")
      ->check(CLI::Range(-200.0, 200.0));
  c->add_option("--range-bias-sigma-mm", o.range_bias_sigma_mm, "its uncertainty [mm] (0: known exactly)")
      ->check(CLI::Range(0.0, 200.0))
      ->capture_default_str();
  c->add_option("--min-seen-fraction", o.min_seen_fraction,
                "keep reflectors seen in at least this share of scans")
      ->check(CLI::Range(0.01, 1.0))
      ->capture_default_str();
  c->add_flag("--force", o.force, "replace an existing --out file");
  c->callback(
      [c, &o] { o.range_bias_stated = c->count("--range-bias-mm") + c->count("--range-bias-sigma-mm") > 0; });
  return c;
}

int run_static_command(const StaticCommandOptions& o) {
  refuse_to_replace(o.out_path, o.force);
  const RobotConfig robot = load_robot_config(o.robot_path);
  const ExtractorServiceConfig extractor = load_extractor_service_config(o.extractor_path);
  StaticSurvey survey(survey_config(o));
  collect(o, extractor, robot.robot_T_laser, survey);
  const Pose2 map_T_robot{o.pose[0], o.pose[1], o.pose[2]};
  const StaticSurveyResult result = survey.finish(map_T_robot * robot.robot_T_laser);
  fmt::print("{}", static_survey_report(result));
  if (!o.range_bias_stated) {
    fmt::print(
        stderr,
        "refloc-survey: warning: range bias not stated: 0 +- {} mm assumed along every line of sight (it "
        "dominates the sigmas); give --range-bias-mm/--range-bias-sigma-mm from a calibration (README)\n",
        o.range_bias_sigma_mm);
  }
  if (result.reflectors.size() < 3) {
    fmt::print(
        stderr,
        "refloc-survey: error: {} reflectors seen in {:.0f} % of the scans; a map needs 3, not written\n",
        result.reflectors.size(), 100.0 * o.min_seen_fraction);
    return kExitRuntimeFailure;
  }
  const ReflectorMap map = static_survey_map(result, o.map_id, extractor.extractor.reflector_radius);
  const std::string colinear = colinear_map_warning(map, o.out_path);
  if (!colinear.empty()) fmt::print(stderr, "refloc-survey: warning: {}\n", colinear);
  const std::string self_similar = self_similar_map_warning(map);
  if (!self_similar.empty()) fmt::print(stderr, "refloc-survey: warning: {}\n", self_similar);
  write_reflector_map(map, o.out_path);
  fmt::print("map written: {} ({} reflectors, source surveyed)\n", o.out_path, map.reflectors.size());
  return 0;
}

}  // namespace refloc
