#include "drive_report.hpp"

#include "common/child_program.hpp"
#include "common/json_config.hpp"
#include "common/program_version.hpp"

#include <fmt/format.h>
#include <Eigen/Eigenvalues>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>

namespace refloc {
namespace {

/// sqrt of the eigenvalues of a 2x2 covariance, major first [m].
Eigen::Vector2d sigmas(const Eigen::Matrix2d& covariance) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(covariance);
  return {std::sqrt(std::max(0.0, eigen.eigenvalues()(1))), std::sqrt(std::max(0.0, eigen.eigenvalues()(0)))};
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw ConfigError(path + ": cannot write");
}

std::string reflectors_csv(const DriveSurveyResult& s) {
  std::string csv =
      "id,x_m,y_m,cov_xx_m2,cov_xy_m2,cov_yy_m2,sigma_major_mm,sigma_minor_mm,times_seen,scans_seen,scans_"
      "expected,"
      "residual_rms_mm,normalised_rms,view_span_deg,surface_clearance_mm,anchor\n";
  for (const SurveyedReflector& r : s.reflectors) {
    const Eigen::Vector2d sigma = sigmas(r.covariance);
    csv += fmt::format(
        "{},{:.6f},{:.6f},{:.6e},{:.6e},{:.6e},{:.3f},{:.3f},{},{},{},{:.3f},{:.3f},{:.1f},{:.1f},{}\n", r.id,
        r.map_p.x(), r.map_p.y(), r.covariance(0, 0), r.covariance(0, 1), r.covariance(1, 1), sigma(0) * 1e3,
        sigma(1) * 1e3, r.times_seen, r.scans_seen, r.scans_expected, r.residual_rms * 1e3, r.normalised_rms,
        r.view_span * 180.0 / M_PI, r.surface_clearance * 1e3, r.anchor ? 1 : 0);
  }
  return csv;
}

std::string rejected_csv(const DriveSurveyResult& s) {
  std::string csv = "x_m,y_m,times_seen,view_span_deg,scatter_mm,seen_fraction,reason\n";
  for (const RejectedTrack& t : s.rejected)
    csv += fmt::format("{:.4f},{:.4f},{},{:.1f},{:.1f},{:.3f},\"{}\"\n", t.map_p.x(), t.map_p.y(),
                       t.times_seen, t.view_span * 180.0 / M_PI, t.scatter * 1e3, t.seen_fraction, t.reason);
  return csv;
}

std::string trajectory_csv(const DriveSurveyResult& s) {
  std::string csv = "t_s,x_m,y_m,theta_rad,front_end_x_m,front_end_y_m\n";
  const int64_t t0 = s.utime.empty() ? 0 : s.utime.front();
  for (size_t k = 0; k < s.map_T_robot.size(); ++k) {
    const Pose2& p = s.map_T_robot[k];
    const Pose2& f = s.front_end_map_T_robot[k];
    csv += fmt::format("{:.3f},{:.5f},{:.5f},{:.6f},{:.5f},{:.5f}\n",
                       static_cast<double>(s.utime[k] - t0) * 1e-6, p.x, p.y, p.theta, f.x, f.y);
  }
  return csv;
}

/// Residual split along the measured beam (range) and across it [mm].
std::string observations_csv(const DriveSurveyResult& s) {
  std::string csv =
      "t_s,utime,id,range_m,bearing_rad,laser_x_m,laser_y_m,sigma_range_mm,sigma_across_mm,beams,roundness_"
      "mm,"
      "fitted_radius_mm,mean_rssi,residual_range_mm,residual_across_mm\n";
  const int64_t t0 = s.utime.empty() ? 0 : s.utime.front();
  for (const SurveyObservation& o : s.observations) {
    const ReflectorDetection& d = o.detection;
    const Eigen::Vector2d u = d.laser_p_center.normalized();
    const Eigen::Vector2d v(-u.y(), u.x());
    const int64_t utime = s.utime[static_cast<size_t>(o.scan)];
    csv += fmt::format(
        "{:.3f},{},{},{:.4f},{:.5f},{:.4f},{:.4f},{:.2f},{:.2f},{},{:.2f},{:.1f},{:.1f},{:.2f},{:.2f}\n",
        static_cast<double>(utime - t0) * 1e-6, utime, o.reflector_id, d.range, d.bearing,
        d.laser_p_center.x(), d.laser_p_center.y(), std::sqrt(u.dot(d.covariance * u)) * 1e3,
        std::sqrt(v.dot(d.covariance * v)) * 1e3, d.num_beams, d.roundness_m * 1e3, d.fitted_radius_m * 1e3,
        d.mean_rssi, u.dot(o.residual) * 1e3, v.dot(o.residual) * 1e3);
  }
  return csv;
}

std::string occluders_csv(const ReflectorMap& map) {
  std::string csv = "name,x0_m,y0_m,x1_m,y1_m\n";
  for (const MapOccluder& o : map.occluders) {
    const size_t n = o.map_points.size();
    for (size_t i = 0; i + 1 < n + (o.closed ? 1 : 0); ++i) {
      const Eigen::Vector2d& a = o.map_points[i];
      const Eigen::Vector2d& b = o.map_points[(i + 1) % n];
      csv += fmt::format("\"{}\",{:.4f},{:.4f},{:.4f},{:.4f}\n", o.name, a.x(), a.y(), b.x(), b.y());
    }
  }
  return csv;
}

nlohmann::json summary_json(const DriveSurveyResult& s, const ReflectorMap& map) {
  return {{"scans", s.scans},
          {"scans_dead_reckoned", s.scans_dead_reckoned},
          {"observations", s.observations_used},
          {"reflectors", s.reflectors.size()},
          {"rejected_tracks", s.rejected.size()},
          {"occluders", map.occluders.size()},
          {"range_bias_m", s.range_bias},
          {"range_bias_sigma_m", s.range_bias_sigma},
          {"chi2_per_dof", s.chi2_per_dof},
          {"batch_runs", s.batch_runs},
          {"front_end_s", s.front_end_s},
          {"batch_s", s.batch_s},
          {"covariance_s", s.covariance_s},
          {"batch_message", s.batch_message},
          {"warnings", s.warnings}};
}

}  // namespace

ReflectorMap surveyed_map(const DriveSurveyResult& survey, const std::vector<MapOccluder>& occluders,
                          const std::string& map_id, double reflector_radius) {
  ReflectorMap map;
  map.info.format = 2;
  map.info.map_id = map_id;
  map.info.version = 1;
  map.info.created = utc_now();
  map.info.source = "surveyed";
  for (const SurveyedReflector& r : survey.reflectors) {
    MapReflector m;
    m.id = r.id;
    m.map_p_center = r.map_p;
    m.radius = reflector_radius;
    if (!r.anchor && r.covariance.trace() > 0.0) m.map_cov_center = r.covariance;
    map.reflectors.push_back(m);
  }
  map.occluders = occluders;
  map.warnings = survey.warnings;
  return map;
}

std::string survey_report_text(const DriveSurveyResult& s) {
  std::string text = fmt::format("{} reflectors surveyed from {} scans ({} observations)\n",
                                 s.reflectors.size(), s.scans, s.observations_used);
  text +=
      "   id        x_m        y_m  sigma_mm (major/minor)  detections  scans seen/in view  residual_rms_mm  "
      "norm_rms  surface_mm\n";
  const bool frame_free =
      std::any_of(s.reflectors.begin(), s.reflectors.end(), [](const SurveyedReflector& r) {
        return !r.anchor && (r.covariance - r.frame_covariance).norm() > 0.0;
      });
  for (const SurveyedReflector& r : s.reflectors) {
    const Eigen::Vector2d sigma = sigmas(r.covariance);
    text += fmt::format(
        "{:5d} {:10.4f} {:10.4f}  {:8.2f} / {:5.2f}{:9}  {:10d}  {:8d} / {:7d}  {:15.2f}  {:8.2f}  "
        "{:10.0f}\n",
        r.id, r.map_p.x(), r.map_p.y(), sigma(0) * 1e3, sigma(1) * 1e3, r.anchor ? " (anchor)" : "",
        r.times_seen, r.scans_seen, r.scans_expected, r.residual_rms * 1e3, r.normalised_rms,
        r.surface_clearance * 1e3);
  }
  if (frame_free) {
    std::vector<double> majors, frame_majors;
    for (const SurveyedReflector& r : s.reflectors) {
      if (r.anchor) continue;
      majors.push_back(sigmas(r.covariance)(0));
      frame_majors.push_back(sigmas(r.frame_covariance)(0));
    }
    std::sort(majors.begin(), majors.end());
    std::sort(frame_majors.begin(), frame_majors.end());
    text += fmt::format(
        "sigma: frame-free (the start pose's own uncertainty, a rigid motion of the whole map, taken out: "
        "what localization in this map sees), the map's scale uncertainty (--scale-sigma-ppm) in; median "
        "major {:.2f} mm; with the frame's: {:.2f} mm\n",
        majors[majors.size() / 2] * 1e3, frame_majors[frame_majors.size() / 2] * 1e3);
  }
  text += fmt::format("range bias (measured - true range): {:+.2f} mm, sigma {:.2f} mm\n", s.range_bias * 1e3,
                      s.range_bias_sigma * 1e3);
  text += fmt::format("batch: chi2/dof {:.2f}, {} runs; {}\n", s.chi2_per_dof, s.batch_runs, s.batch_message);
  int shown = 0;
  for (const RejectedTrack& t : s.rejected) {
    if (t.times_seen < 5) continue;
    if (shown++ == 0) text += "not mapped (seen 5 times or more):\n";
    text += fmt::format("  at ({:7.3f}, {:7.3f}) seen {:4d}, views {:5.1f} deg, scatter {:6.1f} mm: {}\n",
                        t.map_p.x(), t.map_p.y(), t.times_seen, t.view_span * 180.0 / M_PI, t.scatter * 1e3,
                        t.reason);
  }
  text += fmt::format("{} more tracks seen fewer than 5 times not mapped\n", s.rejected.size() - shown);
  text += fmt::format("time: front end {:.2f} s, batch {:.2f} s, covariance {:.2f} s\n", s.front_end_s,
                      s.batch_s, s.covariance_s);
  for (const std::string& w : s.warnings) text += "WARNING: " + w + "\n";
  return text;
}

void write_survey_report(const std::string& dir, const DriveSurveyResult& survey, const ReflectorMap& map) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw ConfigError(dir + ": cannot create the report folder: " + error.message());
  write_file(dir + "/report.txt", survey_report_text(survey));
  write_file(dir + "/survey.json", summary_json(survey, map).dump(2) + "\n");
  write_file(dir + "/reflectors.csv", reflectors_csv(survey));
  write_file(dir + "/rejected.csv", rejected_csv(survey));
  write_file(dir + "/trajectory.csv", trajectory_csv(survey));
  write_file(dir + "/occluders.csv", occluders_csv(map));
  write_file(dir + "/observations.csv", observations_csv(survey));
}

int draw_survey_report(const std::string& dir, const std::string& truth_map) {
  // The script's #!/usr/bin/python3 is Debian's, where python3-matplotlib is installed.
  std::vector<std::string> argv = {shipped_path("tools/refloc-survey/survey_drive_plot.py"), "--report", dir,
                                   "--out", dir + "/survey.png"};
  if (!truth_map.empty()) argv.insert(argv.end(), {"--truth", truth_map});
  return run_child_program(argv);
}

}  // namespace refloc
