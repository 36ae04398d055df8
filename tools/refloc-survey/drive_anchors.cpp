#include "drive_anchors.hpp"

#include "common/json_config.hpp"

#include <limits>
#include <set>
#include <string>

namespace refloc {

std::vector<SurveyAnchor> load_survey_anchors(const std::string& path) {
  const JsonConfig file = JsonConfig::load_file(path);
  const size_t n = file.array_size({"/anchors", "", "the anchor reflectors, 2 or more"});
  if (n < 2)
    file.fail("/anchors", "2 or more anchors are needed to fix the map frame, got " + std::to_string(n));
  std::vector<SurveyAnchor> anchors;
  std::set<long long> ids;
  constexpr double kMaxCoordinate = 1e5;  // as the map loader: 100 km
  for (size_t i = 0; i < n; ++i) {
    const std::string p = "/anchors/" + std::to_string(i);
    SurveyAnchor a;
    const long long id = file.required_integer({p + "/id", "", "the id the reflector gets in the map"}, 0,
                                               std::numeric_limits<int>::max());
    if (!ids.insert(id).second) file.fail(p + "/id", "id " + std::to_string(id) + " is given twice");
    a.id = static_cast<int>(id);
    a.map_p.x() = file.required_number({p + "/x_m", "m", "the reflector's x in the map"}, -kMaxCoordinate,
                                       kMaxCoordinate);
    a.map_p.y() = file.required_number({p + "/y_m", "m", "the reflector's y in the map"}, -kMaxCoordinate,
                                       kMaxCoordinate);
    a.near.x() =
        file.number({p + "/near_x_m", "m", "roughly where it is in the survey's frame (default x_m)"},
                    a.map_p.x(), -kMaxCoordinate, kMaxCoordinate);
    a.near.y() =
        file.number({p + "/near_y_m", "m", "roughly where it is in the survey's frame (default y_m)"},
                    a.map_p.y(), -kMaxCoordinate, kMaxCoordinate);
    anchors.push_back(a);
  }
  file.reject_unknown_keys();
  return anchors;
}

}  // namespace refloc
