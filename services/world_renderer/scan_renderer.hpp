#pragma once
// Renders whole LMS100 scans of a World into refloc::LaserScan. Every beam is
// cast at its own time from the sensor pose at that time, so a moving robot's
// scan is skewed exactly as a real one (541 beams over 15 ms at 50 Hz).

#include "common/angles.hpp"
#include "common/laser_scan.hpp"
#include "common/se2.hpp"
#include "world_renderer/lms100_error_model.hpp"
#include "world_renderer/scan_render_beam.hpp"
#include "world_renderer/scan_render_index.hpp"
#include "world_renderer/world.hpp"

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace refloc {
class JsonConfig;
}

namespace refloc::sim {

/// Which beams a scan has and when they are measured (defaults: LMS100 at 50 Hz, 0.5 deg).
struct ScanGeometry {
  int num_beams = 541;
  double start_angle = -135.0 * kDegToRad;   ///< beam 0 in the laser frame [rad]
  double angle_increment = 0.5 * kDegToRad;  ///< [rad]
  double scan_period = 0.02;                 ///< time between scans [s]
  double time_increment = 1.0 / 36000.0;     ///< time between beams [s] (36 kHz)
};

struct ScanRenderConfig {
  ScanGeometry geometry;
  Lms100ErrorModel sensor;
  /// 16, 8 (16-bit value / 257) or 0 (no RSSI); sensor.rssi_scale applies to the 16-bit channel.
  int rssi_bits = 16;
};

/// map_T_laser at a host time [us].
using PoseAtTime = std::function<Pose2(int64_t utime)>;

/// Renders scans; keeps the beam profile and the per-beam ground truth buffer,
/// so rendering into a reused LaserScan does not allocate.
class ScanRenderer {
 public:
  explicit ScanRenderer(ScanRenderConfig config = {});

  /// Render one scan whose beam 0 is measured at first_beam_utime [us]; beam i is
  /// cast from map_T_laser_at(first_beam_utime + i * time_increment).
  void render(const World& world, const PoseAtTime& map_T_laser_at, int64_t first_beam_utime,
              std::mt19937_64& rng, LaserScan& out);
  /// Same for a sensor standing still at map_T_laser.
  void render(const World& world, const Pose2& map_T_laser, int64_t first_beam_utime, std::mt19937_64& rng,
              LaserScan& out);

  /// What each beam of the last render hit (noise-free).
  const std::vector<BeamTruth>& truth() const { return truth_; }
  const ScanRenderConfig& config() const { return config_; }
  /// Change which beams the next renders produce (e.g. to follow an emulator's request).
  void set_geometry(const ScanGeometry& geometry) { config_.geometry = geometry; }
  /// Test every primitive with every beam instead of the per-scan candidate index
  /// (same result, slower; for tests and benchmarks).
  void set_brute_force(bool brute_force) { brute_force_ = brute_force; }
  const BeamProfile& profile() const { return profile_; }

 private:
  ScanRenderConfig config_;
  BeamProfile profile_;
  std::vector<BeamTruth> truth_;
  std::vector<Pose2> beam_poses_;
  BeamCandidateIndex index_;
  bool brute_force_ = false;
};

/// Convenience: render one scan with a throw-away renderer.
void render_scan(const World& world, const PoseAtTime& map_T_laser_at, int64_t first_beam_utime,
                 const ScanRenderConfig& config, std::mt19937_64& rng, LaserScan& out);
/// Convenience: render one scan from a static pose.
void render_scan(const World& world, const Pose2& map_T_laser, int64_t first_beam_utime,
                 const ScanRenderConfig& config, std::mt19937_64& rng, LaserScan& out);

/// RSSI as the sensor reports it for rssi_bits (16: as is, 8: / 257, 0: none).
int32_t rssi_for_bits(double rssi16, int rssi_bits);

/// Read {"num_beams", "start_angle_deg", "angle_increment_deg", "scan_frequency_hz",
/// "beam_rate_hz", "rssi_bits", "sensor": {Lms100ErrorModel keys}} at pointer;
/// absent keys keep the defaults.
ScanRenderConfig parse_scan_render_config(const JsonConfig& config, const std::string& pointer);

}  // namespace refloc::sim
