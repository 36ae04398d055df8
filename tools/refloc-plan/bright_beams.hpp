#pragma once
// How many beams of a scan the extractor would keep on one reflector: each beam across the
// cylinder traced noise-free with the LMS100 model (world_renderer's spot, partial hits and
// RSSI) through the map's reflectors and occluders, and counted when its echo comes from that
// reflector at or above the extractor's energy threshold. A far reflector's beams straddle its
// edge or cover it only partly, so fewer are bright than cross it: at 5.5-6.5 m often one, which
// the extractor's min_beams (2) rejects although two beam axes cross the cylinder on average.
// The extractor's occlusion rule is applied to the traced beams too: a reflector half behind a
// pillar's corner shows its bright part (the matcher's line of sight calls it "partial"), and
// is rejected only when the beam next to its bright run returns from nearer by the margin.
// A beam tests only its candidates: world_renderer's BeamCandidateIndex, built once per laser
// pose from the reflectors within the beam's reach (a MapGrid query), so a 1000-reflector map
// costs what is near the laser; the echoes are the same as testing everything (a test checks).

#include "plan_config.hpp"

#include "world_renderer/scan_render_beam.hpp"
#include "world_renderer/scan_render_index.hpp"
#include "world_renderer/world.hpp"

#include "reflector_matcher/map_grid.hpp"

#include "common/reflector_map.hpp"
#include "common/se2.hpp"

#include <vector>

namespace refloc {

/// The map as the beam model sees it: its reflectors, and its occluders as diffuse walls of
/// WorldSegment's default remission (a map does not say how bright its walls are).
sim::World beam_world_of(const ReflectorMap& map);

class BrightBeamCounter {
 public:
  /// brute_force: every beam tests the whole map (no candidate index; for tests).
  BrightBeamCounter(const ReflectorMap& map, const PlanConfig& config, bool brute_force = false);
  BrightBeamCounter(const BrightBeamCounter&) = delete;  // grid_ points into world_
  BrightBeamCounter& operator=(const BrightBeamCounter&) = delete;

  /// Beams of the scan from map_T_laser whose noise-free echo is reflector map_index's at or
  /// above config.extractor.energy_threshold_8bit; 0 when the extractor would reject them as
  /// occluded (reject_occluded, occlusion_margin) [-]. Rebuilds the candidate index when
  /// map_T_laser differs from the last call's.
  int count(const Pose2& map_T_laser, int map_index);

 private:
  /// Indexes the beams of the scan from map_T_laser, unless it is the last one indexed.
  void index_scan(const Pose2& map_T_laser);

  const ReflectorMap& map_;
  PlanScanGeometry scan_;
  sim::Lms100ErrorModel sensor_;
  double energy_threshold_8bit_;
  bool reject_occluded_;
  double occlusion_margin_;
  sim::World world_;
  sim::BeamProfile profile_;
  bool brute_force_;
  double reach_;                 ///< farthest a return can matter: trace_beam's, the renderer's [m]
  MapGrid grid_;                 ///< over world_.reflectors (the map's, same order)
  double largest_radius_ = 0.0;  ///< of the map's reflectors [m]
  sim::BeamCandidateIndex index_;
  bool indexed_ = false;
  Pose2 indexed_pose_;
  std::vector<int> nearby_;
  std::vector<Pose2> beam_poses_;
};

}  // namespace refloc
