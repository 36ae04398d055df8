#pragma once
// What refloc-survey drive hands the user: the v2 map (source "surveyed", each reflector with
// its covariance, the traced occluders), the printed report (per reflector id, position, sigma,
// times seen, residual RMS; the range bias with its sigma; what was not mapped and why) and a
// report folder with the same as CSV/JSON plus a picture drawn by survey_drive_plot.py.

#include "drive_survey.hpp"

#include "common/reflector_map.hpp"

#include <string>
#include <vector>

namespace refloc {

/// The map file's content: format 2, version 1, created now (UTC), source "surveyed".
ReflectorMap surveyed_map(const DriveSurveyResult& survey, const std::vector<MapOccluder>& occluders,
                          const std::string& map_id, double reflector_radius);

/// The report as printed: one line per reflector, the range bias, the rejected tracks.
std::string survey_report_text(const DriveSurveyResult& survey);

/// report.txt, survey.json, trajectory.csv, reflectors.csv, rejected.csv, occluders.csv in dir
/// (created if missing); throws ConfigError naming a file that cannot be written.
void write_survey_report(const std::string& dir, const DriveSurveyResult& survey, const ReflectorMap& map);

/// Draws dir/survey.png from those files with tools/refloc-survey/survey_drive_plot.py
/// (/usr/bin/python3, matplotlib); truth_map: a map file drawn beside (may be empty).
/// Returns the script's exit status, -1 when it could not be started.
int draw_survey_report(const std::string& dir, const std::string& truth_map);

}  // namespace refloc
