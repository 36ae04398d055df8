#pragma once
// Which world primitives each beam of a scan can possibly hit, so a beam tests a
// handful of reflectors and segments instead of the whole world.
//
// Built once per scan from the sensor poses of all its beams: every primitive's
// bearing interval is taken from a reference pose (the middle beam's) and widened
// by the most the pose turns during the scan, by asin(R / distance) for the most it
// moves (R, plus the spot's exit radius), and by the beam's half divergence. Any
// beam outside a primitive's widened interval provably misses it, so the rendered
// scan is identical to testing everything (a test checks this).
//
// On a large map, building it still visits every reflector; the second build() takes the
// reflectors near the sensor (e.g. from a grid query) and costs what is in reach, not the map.

#include "common/se2.hpp"
#include "world_renderer/scan_render_beam.hpp"
#include "world_renderer/world.hpp"

#include <cstdint>
#include <vector>

namespace refloc::sim {

class BeamCandidateIndex {
 public:
  /// Index the world for beams i = 0..n-1 at laser-frame angles start_angle + i * angle_increment
  /// [rad] cast from beam_poses[i] (map_T_laser); max_range bounds what can be hit [m].
  void build(const World& world, const std::vector<Pose2>& beam_poses, double start_angle,
             double angle_increment, const BeamProfile& profile, double max_range);

  /// The same, indexing only the reflectors listed (indices into world.reflectors.reflectors,
  /// ascending, so the candidates keep World's order): the caller guarantees that every other
  /// reflector's centre is farther than max_range + its radius + half_exit_diameter from every
  /// beam pose, so the candidates are exactly build()'s. Segments are all indexed.
  void build(const World& world, const std::vector<int>& reflectors, const std::vector<Pose2>& beam_poses,
             double start_angle, double angle_increment, const BeamProfile& profile, double max_range);

  /// Primitives beam i may hit (encoding in BeamCandidates).
  BeamCandidates candidates(size_t beam) const {
    return {entries_.data() + offsets_[beam], entries_.data() + offsets_[beam + 1]};
  }
  /// Total candidate entries of the last build (a cost measure).
  size_t size() const { return entries_.size(); }

 private:
  void add_interval(int32_t code, double lo, double hi);
  void add_all(int32_t code);
  /// Shared by both builds: reflectors (null: all of them), every segment, then the lists.
  void build_from(const World& world, const std::vector<int>* reflectors,
                  const std::vector<Pose2>& beam_poses, double start_angle, double angle_increment,
                  const BeamProfile& profile, double max_range);

  struct Span {
    int32_t code;
    int32_t first_beam;
    int32_t last_beam;
  };
  size_t num_beams_ = 0;
  double start_angle_ = 0.0;
  double angle_increment_ = 0.0;
  std::vector<Span> spans_;
  std::vector<uint32_t> offsets_;
  std::vector<int32_t> entries_;
};

}  // namespace refloc::sim
