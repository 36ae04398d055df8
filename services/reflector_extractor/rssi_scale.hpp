#pragma once
// Which scale the 16-bit RSSI channel really carries. Some sensors (and firmware settings)
// send 8-bit values (never above 255) in the 16-bit channel: divided by 257 as 16-bit
// values, nothing reaches the 8-bit threshold and the extractor silently finds nothing.
//
// Verdict rule (mode auto): a 16-bit stream whose echoes stayed <= 255 over at least
// min_scans scans and min_echoes echoes holds 8-bit values. On the true 16-bit scale a raw
// 255 is 1 on the 8-bit scale, darker than any surface that still returns an echo, so a
// thousand such echoes in a row do not happen on a real 16-bit channel. The first echo above
// 255 afterwards switches back to the 16-bit scale (said so) and the evidence starts over.
// 8-bit streams (rssi_bits 8) and scans without RSSI are never touched.

#include "common/laser_scan.hpp"
#include "common/node_event.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace refloc {

/// How the extractor reads a 16-bit RSSI channel.
enum class RssiScale : uint8_t {
  kNative,       ///< as rssi_bits says: 16-bit values / 257
  k8bitIn16bit,  ///< 8-bit values in the 16-bit channel: used as they are
};

struct RssiScaleConfig {
  enum class Mode { kAuto, kNative, k8bitIn16bit };
  Mode mode = Mode::kAuto;
  /// Scans with echoes before an 8-bit verdict: the first one is lost to it (20 ms at 50 Hz).
  /// Two, not one: a true 16-bit stream flapping in and out of the verdict needs two dark
  /// scans in a row each time. A wrong verdict costs little: it only lasts while no echo is
  /// above raw 255, i.e. while no reflector is in view.
  int min_scans = 2;
  /// Echoes before an 8-bit verdict: a scan of open space with a few echoes proves little.
  int min_echoes = 300;
};

class RssiScaleDetector {
 public:
  explicit RssiScaleDetector(RssiScaleConfig config = {});

  /// Judge one accepted scan before it is read; a verdict or a switch back appends an event
  /// (counter rssi_scale_changes, a log line saying why).
  void observe(const LaserScan& scan, std::vector<NodeEvent>& events);

  /// The scale to read the next scans with (the one just observed included).
  RssiScale scale() const { return scale_; }
  /// Why: "8-bit values in the 16-bit RSSI channel (max 250 over 1234 echoes)", or empty.
  std::string detail() const;

 private:
  RssiScaleConfig config_;
  RssiScale scale_ = RssiScale::kNative;
  int scans_ = 0;        ///< 16-bit scans with echoes since the evidence started
  int64_t echoes_ = 0;   ///< their echoes with RSSI
  int32_t max_raw_ = 0;  ///< their largest raw RSSI
};

}  // namespace refloc
