#pragma once
// What the localization should do at one robot pose, predicted from the map alone: which
// reflectors the laser sees (the matcher's visibility rule, then the extractor's energy
// threshold and min_beams on the beams the LMS100 model makes bright), the beam-spot Cramér-Rao
// bound of a single-scan fix (refloc-eval's), what the matcher's global relocalization makes of
// those reflectors seen exactly (its own rival rule: OK, AMBIGUOUS with a rival elsewhere, or OK
// at the wrong place), and whether the solver makes a pose of its matches.

#include "bright_beams.hpp"
#include "plan_config.hpp"

#include "pose_solver/pose_solver.hpp"

#include "reflector_matcher/global_relocalizer.hpp"
#include "reflector_matcher/map_grid.hpp"
#include "reflector_matcher/map_triangle_index.hpp"
#include "reflector_matcher/occluder_grid.hpp"

#include "common/reflector_map.hpp"
#include "common/se2.hpp"

#include <memory>
#include <vector>

namespace refloc {

/// What the matcher's relocalization from scratch gives on the visible reflectors.
enum class Relocalization : signed char {
  kNotTried,   ///< fewer visible than min_matches, or the check is off
  kUnique,     ///< OK at the true pose
  kAmbiguous,  ///< AMBIGUOUS: a rival pose elsewhere explains them nearly as well
  kWrong,      ///< OK at another pose: the layout there is a copy of this one
  kLost,       ///< enough reflectors, but no hypothesis explains them (e.g. too close together)
  /// OK at the true pose, but the solver makes no pose of the matches: its linear start
  /// (paper eq. 4-5) is singular for reflectors on one line, e.g. three on a wall.
  kNoPose,
};

const char* to_string(Relocalization r);

struct PosePrediction {
  int visible = 0;           ///< reflectors the laser sees [-]
  bool has_bound = false;    ///< the beams determine the pose
  double sigma_xy = 0.0;     ///< CRLB position sigma, sqrt(var x + var y) [m]
  double sigma_theta = 0.0;  ///< CRLB heading sigma [rad]
  Relocalization relocalization = Relocalization::kNotTried;
  Pose2 map_T_robot_rival;  ///< the pose confused with this one (kAmbiguous, kWrong)
};

/// The map and the matcher's look-up structures over it, built once and only read afterwards,
/// so the predictors of one plan (one per thread) share them: the grid, the occluder grid and
/// the triangle index (on a 1000-reflector 100 x 100 m map 5 million triangles, 2 s, 250 MB).
class PlanMapIndex {
 public:
  /// Copies map; the triangle index only with config.check_ambiguity.
  PlanMapIndex(ReflectorMap map, const PlanConfig& config);
  PlanMapIndex(const PlanMapIndex&) = delete;  // grid and triangles refer to map
  PlanMapIndex& operator=(const PlanMapIndex&) = delete;

  const ReflectorMap map;
  const MapGrid grid;  ///< the matcher's cell size, half its max_range
  const OccluderGrid occluders;
  const std::unique_ptr<const MapTriangleIndex> triangles;  ///< null without the ambiguity check
};

class PosePredictor {
 public:
  /// Copies map; builds the matcher's grid, occluder grid and triangle index once.
  PosePredictor(ReflectorMap map, const PlanConfig& config);
  /// On a shared map index (built with the same config): each thread has its own predictor,
  /// which only reads the index.
  PosePredictor(std::shared_ptr<const PlanMapIndex> index, const PlanConfig& config);
  PosePredictor(const PosePredictor&) = delete;
  PosePredictor& operator=(const PosePredictor&) = delete;

  PosePrediction predict(const Pose2& map_T_robot);

  /// Map indices of the reflectors visible in the last predict() [-].
  const std::vector<int>& visible() const { return visible_; }
  const ReflectorMap& map() const { return shared_->map; }

 private:
  /// Beams of the scan whose axis meets the reflector seen at range, bearing [m, rad].
  void add_beams(int map_index, double range, double bearing);
  /// What a relocalization result means at the true map_T_laser; sets the rival's pose.
  Relocalization classify(const MatchResult& match, const Pose2& map_T_laser, Pose2& map_T_robot_rival) const;
  /// An AMBIGUOUS (or wrong) verdict on exact detections sits on the rival rule's margin more
  /// often than not: relocalizes config.rival_noise_samples copies with the range noise added
  /// and keeps "ambiguous" only when the copies are ambiguous as often as they fix here.
  void confirm_rival(const Pose2& map_T_laser, PosePrediction& out);

  std::shared_ptr<const PlanMapIndex> shared_;
  const ReflectorMap& map_;
  PlanConfig config_;
  std::unique_ptr<GlobalRelocalizer> relocalizer_;
  BrightBeamCounter bright_beams_;
  PoseSolver solver_;
  PoseSolution solution_;
  std::vector<int> scratch_;
  std::vector<PredictedReflector> predicted_;
  std::vector<int> visible_;
  std::vector<ReflectorBeam> beams_;
  std::vector<ReflectorDetection> detections_;
  std::vector<ReflectorDetection> noisy_;
  MatchResult match_;
  MatchResult noisy_match_;
};

}  // namespace refloc
