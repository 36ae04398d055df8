#pragma once
// The anchor file of refloc-survey drive --anchors: reflectors whose map coordinates the user
// knows (from a drawing or a total station). A survey has no ids, so each anchor also says
// roughly where that reflector is in the survey's own frame (the one --start-pose defines):
// the surveyed reflector nearest to that point is the anchor. With --start-pose set to where
// the robot roughly started in the map, the map coordinates themselves are that point.
//
//   {"anchors": [{"id": 1, "x_m": 1.5, "y_m": 0.1},
//                {"id": 5, "x_m": 17.8, "y_m": 0.1, "near_x_m": 14.9, "near_y_m": -2.8}]}

#include "drive_survey.hpp"

#include <string>
#include <vector>

namespace refloc {

/// Throws ConfigError naming the file and key: fewer than 2 anchors, an id twice, bad numbers.
std::vector<SurveyAnchor> load_survey_anchors(const std::string& path);

}  // namespace refloc
