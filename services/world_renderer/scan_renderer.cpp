#include "world_renderer/scan_renderer.hpp"

#include "common/angles.hpp"
#include "common/json_config.hpp"

#include <algorithm>
#include <cmath>

namespace refloc::sim {

ScanRenderer::ScanRenderer(ScanRenderConfig config)
    : config_(config), profile_(make_beam_profile(config_.sensor)) {}

void ScanRenderer::render(const World& world, const PoseAtTime& map_T_laser_at, int64_t first_beam_utime,
                          std::mt19937_64& rng, LaserScan& out) {
  const ScanGeometry& g = config_.geometry;
  const size_t n = static_cast<size_t>(std::max(g.num_beams, 0));
  out.utime = first_beam_utime;
  out.start_angle = g.start_angle;
  out.angle_increment = g.angle_increment;
  out.time_increment = g.time_increment;
  out.scan_period = g.scan_period;
  out.range_min = config_.sensor.range_min;
  out.range_max = config_.sensor.range_max;
  out.rssi_bits = config_.rssi_bits;
  out.ranges.resize(n);
  out.rssi.resize(config_.rssi_bits == 0 ? 0 : n);
  truth_.resize(n);
  beam_poses_.resize(n);
  for (size_t i = 0; i < n; ++i) beam_poses_[i] = map_T_laser_at(out.beam_utime(i));
  const double reach = config_.sensor.range_max + config_.sensor.echo_merge_distance + 0.1;
  if (!brute_force_) index_.build(world, beam_poses_, g.start_angle, g.angle_increment, profile_, reach);
  for (size_t i = 0; i < n; ++i) {
    const BeamCandidates candidates = brute_force_ ? BeamCandidates{} : index_.candidates(i);
    const BeamEcho echo = render_beam(world, profile_, config_.sensor, beam_poses_[i], out.beam_angle(i), rng,
                                      brute_force_ ? nullptr : &candidates);
    out.ranges[i] = static_cast<float>(echo.range);
    // The 8-bit-in-16-bit quirk is in the 16-bit channel; the 8-bit channel stays / 257.
    const double rssi = config_.rssi_bits == 16 ? reported_rssi16(config_.sensor, echo.rssi) : echo.rssi;
    if (config_.rssi_bits != 0) out.rssi[i] = rssi_for_bits(rssi, config_.rssi_bits);
    truth_[i] = echo.truth;
  }
}

void ScanRenderer::render(const World& world, const Pose2& map_T_laser, int64_t first_beam_utime,
                          std::mt19937_64& rng, LaserScan& out) {
  render(
      world, [&map_T_laser](int64_t) { return map_T_laser; }, first_beam_utime, rng, out);
}

void render_scan(const World& world, const PoseAtTime& map_T_laser_at, int64_t first_beam_utime,
                 const ScanRenderConfig& config, std::mt19937_64& rng, LaserScan& out) {
  ScanRenderer(config).render(world, map_T_laser_at, first_beam_utime, rng, out);
}

void render_scan(const World& world, const Pose2& map_T_laser, int64_t first_beam_utime,
                 const ScanRenderConfig& config, std::mt19937_64& rng, LaserScan& out) {
  ScanRenderer(config).render(world, map_T_laser, first_beam_utime, rng, out);
}

int32_t rssi_for_bits(double rssi16, int rssi_bits) {
  if (rssi_bits == 0 || rssi16 <= 0.0) return 0;
  if (rssi_bits == 8) {
    if (rssi16 >= 65535.0) return 255;  // dazzled
    return static_cast<int32_t>(std::clamp(std::round(rssi16 / 257.0), 1.0, 254.0));
  }
  return static_cast<int32_t>(std::clamp(std::round(rssi16), 0.0, 65535.0));
}

ScanRenderConfig parse_scan_render_config(const JsonConfig& config, const std::string& p) {
  ScanRenderConfig c;
  ScanGeometry& g = c.geometry;
  g.num_beams = static_cast<int>(config.integer({p + "/num_beams", "count",
                                                 "beams per scan (541: 270 deg at 0.5 deg); the emulator "
                                                 "renders the count its scan setup asks for instead"},
                                                g.num_beams, 1, 10000));
  g.start_angle = config.number({p + "/start_angle_deg", "deg",
                                 "angle of beam 0 in the laser frame (0 ahead, counter-clockwise); the "
                                 "emulator uses its scan setup's"},
                                g.start_angle / kDegToRad, -180.0, 180.0) *
                  kDegToRad;
  g.angle_increment = config.number({p + "/angle_increment_deg", "deg",
                                     "angle between neighbouring beams; the emulator uses its scan setup's "
                                     "(emulator/angular_resolution_deg)"},
                                    g.angle_increment / kDegToRad, 0.01, 10.0) *
                      kDegToRad;
  g.scan_period = 1.0 / config.number({p + "/scan_frequency_hz", "Hz",
                                       "scans per second, stamped into rendered scans; the emulator's rate "
                                       "is emulator/scan_frequency_hz"},
                                      1.0 / g.scan_period, 1.0, 100.0);
  g.time_increment = 1.0 / config.number({p + "/beam_rate_hz", "Hz",
                                          "beams measured per second (sets each beam's time, the skew of a "
                                          "moving scan); the emulator uses the LMS100's 36 kHz"},
                                         1.0 / g.time_increment, 100.0, 1e6);
  const long long bits = config.integer({p + "/rssi_bits", "bit",
                                         "RSSI channel of rendered scans: 16, 8 (16-bit / 257) or 0 (none); "
                                         "the emulator sends what the driver requests"},
                                        c.rssi_bits, 0, 16);
  if (bits != 0 && bits != 8 && bits != 16) config.fail(p + "/rssi_bits", "expected 0, 8 or 16");
  c.rssi_bits = static_cast<int>(bits);
  if (g.time_increment * g.num_beams > g.scan_period) {
    config.fail(p + "/beam_rate_hz", "the beams of one scan take longer than the scan period");
  }
  c.sensor = parse_lms100_error_model(config, p + "/sensor");
  return c;
}

}  // namespace refloc::sim
