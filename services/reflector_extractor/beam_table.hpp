#pragma once
// The raw scan read once: for every beam its kind (echo / no echo / dazzled), its point in
// the laser frame and its RSSI on the paper's 8-bit scale. Every later step of the extractor
// (energy screening, clustering, occlusion, the fits) reads this table, never the raw
// sentinel ranges (0, 0.001) or the sensor's RSSI width.

#include "common/laser_scan.hpp"
#include "reflector_extractor/rssi_scale.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace refloc {

/// What the sensor says a beam saw.
enum class BeamKind : uint8_t {
  kEcho,     ///< range inside [range_min, range_max]
  kNoEcho,   ///< sensor code 0 (nothing within range), or beyond range_max
  kDazzled,  ///< 0 < range < range_min: sensor code 1, blinded by a too bright return
};

struct TableBeam {
  BeamKind kind = BeamKind::kNoEcho;
  double range = 0.0;                                    ///< [m], as reported
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  ///< unit vector of the beam, laser frame
  Eigen::Vector2d point = Eigen::Vector2d::Zero();       ///< range * direction [m]
  double rssi_8bit = 0.0;  ///< energy on the 8-bit scale (16-bit / 257 unless read as 8-bit); 0 without RSSI
};

struct BeamTable {
  std::vector<TableBeam> beams;
  bool has_rssi = false;         ///< one RSSI per beam: energy screening is possible
  double start_angle = 0.0;      ///< [rad]
  double angle_increment = 0.0;  ///< [rad]
  int64_t utime = 0;             ///< host time of beam 0 [us]
  double time_increment = 0.0;   ///< [s]

  size_t size() const { return beams.size(); }
  bool is_echo(size_t i) const { return beams[i].kind == BeamKind::kEcho; }
  /// Host time of beam i [us], as LaserScan::beam_utime.
  int64_t beam_utime(size_t i) const {
    return utime + static_cast<int64_t>(static_cast<double>(i) * time_increment * 1e6 + 0.5);
  }
};

/// RSSI as reported, on the 8-bit scale: 65535 / 255 = 257 maps full scale onto full scale;
/// k8bitIn16bit: the 16-bit channel holds 8-bit values, used as they are.
double rssi_to_8bit(int32_t raw, int rssi_bits, RssiScale scale = RssiScale::kNative);
/// The inverse: an 8-bit-scale energy on the scan's own RSSI scale (where a plot of the raw
/// channel draws the threshold).
double rssi_from_8bit(double energy_8bit, int rssi_bits, RssiScale scale = RssiScale::kNative);

/// Fill table from scan (its storage reused: no allocation once grown to the largest scan),
/// reading a 16-bit RSSI channel on scale (RssiScaleDetector's verdict).
void make_beam_table(const LaserScan& scan, BeamTable& table, RssiScale scale = RssiScale::kNative);

}  // namespace refloc
