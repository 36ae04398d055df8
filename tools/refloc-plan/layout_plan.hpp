#pragma once
// refloc-plan's figures for every cell of a grid: each cell predicted at every heading
// (PosePredictor), folded into the worst heading's class, and the hall's area fractions.

#include "plan_config.hpp"
#include "plan_grid.hpp"
#include "pose_prediction.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace refloc {

struct CellPlan {
  Eigen::Vector2d map_p = Eigen::Vector2d::Zero();  ///< cell centre [m]
  int visible_min = 0;                              ///< over headings [-]
  double visible_mean = 0.0;                        ///< over headings [-]
  int headings_ambiguous = 0;                       ///< AMBIGUOUS or OK at a wrong pose [-]
  int headings_lost = 0;                            ///< >= min_matches visible, no fix [-]
  int headings_unique = 0;                          ///< relocalized OK at the true pose [-]
  int headings_bad = 0;          ///< blind, ambiguous, lost, no bound or above the CRLB limit [-]
  bool has_bound = false;        ///< every heading's beams determine the pose
  double sigma_xy_max = 0.0;     ///< worst heading's CRLB position sigma [m]
  double sigma_theta_max = 0.0;  ///< worst heading's CRLB heading sigma [rad]
  bool has_rival = false;
  Pose2 map_T_robot_rival;     ///< the first confusing heading's rival pose
  double rival_heading = 0.0;  ///< robot heading at which it confuses [rad]
};

/// The cell's class, worst heading first: "blind" (fewer than min_matches visible at some
/// heading), "ambiguous" (a heading relocalizes AMBIGUOUS or at a wrong pose), "lost" (enough
/// reflectors, no fix), "fragile" (exactly min_matches at some heading), else "ok".
const char* cell_class(const CellPlan& cell, int min_matches);

struct PlanSummary {
  size_t cells = 0;
  double area_m2 = 0.0;
  double blind = 0.0;        ///< fraction of the area [-]
  double fragile = 0.0;      ///< [-]
  double ambiguous = 0.0;    ///< [-]
  double lost = 0.0;         ///< [-]
  double above_limit = 0.0;  ///< no bound or worst-heading CRLB above crlb_limit [-]
  double bad = 0.0;          ///< cells blind, ambiguous, lost or above the limit at some heading [-]
  /// Of all (cell, heading) poses, the bad ones: what suggestions reduce. A cell is "bad" while
  /// any heading is, and one new reflector is never seen at every heading (270 deg view) [-].
  double bad_poses = 0.0;
  double median_sigma_xy = 0.0;  ///< of the cells with a bound [m]
};

struct LayoutPlan {
  PlanGrid grid;
  std::vector<CellPlan> cells;
  PlanSummary summary;
};

/// Called with (cells done, cells in all).
using PlanProgress = std::function<void(size_t, size_t)>;

/// Predicts every cell of grid at config.headings headings.
LayoutPlan plan_layout(const ReflectorMap& map, const PlanGrid& grid, const PlanConfig& config,
                       const PlanProgress& progress = {});

/// Whether a cell counts in PlanSummary::bad.
bool is_bad_cell(const CellPlan& cell, const PlanConfig& config);

PlanSummary summarize(const std::vector<CellPlan>& cells, double resolution, const PlanConfig& config);

}  // namespace refloc
