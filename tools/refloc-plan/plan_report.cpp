#include "plan_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace refloc {
namespace {

std::string summary_lines(const PlanSummary& s, const PlanConfig& config) {
  return fmt::format(
      "  cells {} ({:.1f} m2)\n"
      "  blind (< {} reflectors at some heading) {:.1f} %\n"
      "  fragile (exactly {}) {:.1f} %\n"
      "  ambiguous (relocalization AMBIGUOUS or wrong at some heading) {:.1f} %\n"
      "  lost (enough reflectors, no fix) {:.1f} %\n"
      "  above the CRLB limit {:.1f} mm (or no bound) {:.1f} %\n"
      "  bad (any of blind, ambiguous, lost, above the limit) {:.1f} %; bad (cell, heading) poses {:.1f} %\n"
      "  median worst-heading CRLB position sigma {:.2f} mm\n",
      s.cells, s.area_m2, config.matcher.min_matches, 100.0 * s.blind, config.matcher.min_matches,
      100.0 * s.fragile, 100.0 * s.ambiguous, 100.0 * s.lost, 1e3 * config.crlb_limit, 100.0 * s.above_limit,
      100.0 * s.bad, 100.0 * s.bad_poses, 1e3 * s.median_sigma_xy);
}

nlohmann::json summary_json(const PlanSummary& s) {
  return {{"cells", s.cells},
          {"area_m2", s.area_m2},
          {"blind", s.blind},
          {"fragile", s.fragile},
          {"ambiguous", s.ambiguous},
          {"lost", s.lost},
          {"above_limit", s.above_limit},
          {"bad", s.bad},
          {"bad_poses", s.bad_poses},
          {"median_sigma_xy_mm", 1e3 * s.median_sigma_xy}};
}

nlohmann::json cells_json(const std::vector<CellPlan>& cells, int min_matches) {
  nlohmann::json out = nlohmann::json::array();
  for (const CellPlan& c : cells) {
    nlohmann::json j = {
        {"x_m", c.map_p.x()},
        {"y_m", c.map_p.y()},
        {"visible_min", c.visible_min},
        {"visible_mean", c.visible_mean},
        {"class", cell_class(c, min_matches)},
        {"headings_ambiguous", c.headings_ambiguous},
        {"headings_lost", c.headings_lost},
        {"headings_bad", c.headings_bad},
        {"sigma_xy_mm", c.has_bound ? nlohmann::json(1e3 * c.sigma_xy_max) : nlohmann::json()},
        {"sigma_theta_mrad", c.has_bound ? nlohmann::json(1e3 * c.sigma_theta_max) : nlohmann::json()},
        {"rival", nlohmann::json()}};
    if (c.has_rival) {
      j["rival"] = {{"x_m", c.map_T_robot_rival.x},
                    {"y_m", c.map_T_robot_rival.y},
                    {"theta_rad", c.map_T_robot_rival.theta},
                    {"at_heading_rad", c.rival_heading}};
    }
    out.push_back(std::move(j));
  }
  return out;
}

nlohmann::json reflectors_json(const ReflectorMap& map) {
  nlohmann::json out = nlohmann::json::array();
  for (const MapReflector& r : map.reflectors) {
    out.push_back(
        {{"id", r.id}, {"x_m", r.map_p_center.x()}, {"y_m", r.map_p_center.y()}, {"radius_m", r.radius}});
  }
  return out;
}

}  // namespace

std::string plan_summary_text(const PlanReport& r) {
  const PlanConfig& c = r.config;
  std::string text = fmt::format(
      "refloc-plan: {}\n{} reflectors, {} occluders; grid {} m, {} headings; a reflector seen with {} beams "
      "of RSSI >= {:.0f}; "
      "range {}-{} m, field of view {:.0f} deg; CRLB limit {:.1f} mm; {:.1f} s on {} thread{}\n",
      r.map_name, r.map.reflectors.size(), r.map.occluders.size(), c.resolution, c.headings,
      c.extractor.min_beams, c.extractor.energy_threshold_8bit, c.matcher.sensor.min_range,
      c.matcher.sensor.max_range, c.matcher.sensor.field_of_view * 180.0 / M_PI, 1e3 * c.crlb_limit,
      r.runtime_s, std::max(c.threads, 1), c.threads > 1 ? "s" : "");
  text += "area fractions (worst heading):\n" + summary_lines(r.plan.summary, c);
  if (!r.suggestions.empty()) {
    text += fmt::format("suggested reflectors ({}):\n", r.suggestions.size());
    for (const Suggestion& s : r.suggestions) {
      text += fmt::format(
          "  id {} at ({:.2f}, {:.2f}) m: ambiguous poses {:.1f} % -> {:.1f} %, bad poses {:.1f} % -> {:.1f} "
          "% "
          "(suggestion grid)\n",
          s.reflector.id, s.reflector.map_p_center.x(), s.reflector.map_p_center.y(),
          100.0 * s.ambiguous_poses_before, 100.0 * s.ambiguous_poses_after, 100.0 * s.bad_poses_before,
          100.0 * s.bad_poses_after);
    }
    text += "after adding them:\n" + summary_lines(r.plan_after.summary, c);
  }
  text += r.measured;
  if (!r.measured_after.empty()) text += "with the suggestions: " + r.measured_after;
  return text;
}

std::string plan_json_text(const PlanReport& r) {
  const PlanConfig& c = r.config;
  nlohmann::json j;
  j["map"] = r.map_name;
  j["resolution_m"] = c.resolution;
  j["headings"] = c.headings;
  j["crlb_limit_mm"] = 1e3 * c.crlb_limit;
  j["min_matches"] = c.matcher.min_matches;
  j["min_beams"] = c.extractor.min_beams;
  j["energy_threshold_8bit"] = c.extractor.energy_threshold_8bit;
  j["runtime_s"] = r.runtime_s;
  j["threads"] = std::max(c.threads, 1);
  j["reflectors"] = reflectors_json(r.map);
  j["occluders"] = nlohmann::json::array();
  for (const MapOccluder& o : r.map.occluders) {
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : o.map_points) points.push_back({p.x(), p.y()});
    j["occluders"].push_back({{"name", o.name}, {"closed", o.closed}, {"points", points}});
  }
  j["drivable_areas"] = nlohmann::json::array();
  for (const auto& a : r.drivable) {
    j["drivable_areas"].push_back(
        {{"x_min", a.x_min}, {"y_min", a.y_min}, {"x_max", a.x_max}, {"y_max", a.y_max}});
  }
  j["summary"] = summary_json(r.plan.summary);
  j["cells"] = cells_json(r.plan.cells, c.matcher.min_matches);
  j["suggestions"] = nlohmann::json::array();
  for (const Suggestion& s : r.suggestions) {
    j["suggestions"].push_back({{"id", s.reflector.id},
                                {"x_m", s.reflector.map_p_center.x()},
                                {"y_m", s.reflector.map_p_center.y()},
                                {"radius_m", s.reflector.radius},
                                {"bad_poses_before", s.bad_poses_before},
                                {"bad_poses_after", s.bad_poses_after},
                                {"ambiguous_poses_before", s.ambiguous_poses_before},
                                {"ambiguous_poses_after", s.ambiguous_poses_after}});
  }
  if (!r.suggestions.empty()) {
    j["summary_after"] = summary_json(r.plan_after.summary);
    j["cells_after"] = cells_json(r.plan_after.cells, c.matcher.min_matches);
  }
  return j.dump(1);
}

void write_text_file(const std::string& path, const std::string& text) {
  std::error_code error;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (!folder.empty()) std::filesystem::create_directories(folder, error);
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
}

void write_plan_report(const PlanReport& report, const std::string& out_dir) {
  write_text_file(out_dir + "/grid.json", plan_json_text(report));
  write_text_file(out_dir + "/summary.txt", plan_summary_text(report));
}

}  // namespace refloc
