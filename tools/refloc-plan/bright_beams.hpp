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

#include "plan_config.hpp"

#include "world_renderer/scan_render_beam.hpp"
#include "world_renderer/world.hpp"

#include "common/reflector_map.hpp"
#include "common/se2.hpp"

namespace refloc {

/// The map as the beam model sees it: its reflectors, and its occluders as diffuse walls of
/// WorldSegment's default remission (a map does not say how bright its walls are).
sim::World beam_world_of(const ReflectorMap& map);

class BrightBeamCounter {
 public:
  explicit BrightBeamCounter(const ReflectorMap& map, const PlanConfig& config);

  /// Beams of the scan from map_T_laser whose noise-free echo is reflector map_index's at or
  /// above config.extractor.energy_threshold_8bit; 0 when the extractor would reject them as
  /// occluded (reject_occluded, occlusion_margin) [-].
  int count(const Pose2& map_T_laser, int map_index) const;

 private:
  const ReflectorMap& map_;
  PlanScanGeometry scan_;
  sim::Lms100ErrorModel sensor_;
  double energy_threshold_8bit_;
  bool reject_occluded_;
  double occlusion_margin_;
  sim::World world_;
  sim::BeamProfile profile_;
};

}  // namespace refloc
