#pragma once
// The reflector_extractor service without LCM: odometry and scans in, in time order;
// per scan the detections (motion-compensated when odometry is fresh), the extraction
// statistics and the heartbeat counters to bump. main.cpp and refloc-eval both run this.

#include "reflector_extractor/extractor.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "reflector_extractor/motion_compensator.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace refloc {

struct ExtractorOutput {
  int64_t utime = 0;  ///< the scan's (first beam) [us]
  uint32_t scan_counter = 0;
  std::vector<ReflectorDetection> detections;  ///< in the laser frame at utime
  ExtractionStats stats;
  CompensationOutcome compensation = CompensationOutcome::kOff;

  /// Calls bump(name, increment) for each heartbeat counter this scan touches (a counter
  /// first appears when first touched, so the set touched matters, not only the sums).
  template <class Bump>
  void for_each_counter(Bump&& bump) const {
    if (compensation == CompensationOutcome::kNoFreshOdometry) bump("scans_without_fresh_odometry", 1);
    bump("rejected_too_few_beams", stats.rejected_too_few_beams);
    bump("rejected_shape", stats.rejected_too_wide + stats.rejected_too_narrow + stats.rejected_not_round +
                               stats.rejected_radius + stats.rejected_fit_failed);
    bump("rejected_occluded", stats.rejected_occluded);
    if (detections.empty()) bump("scans_without_reflectors", 1);
  }
};

/// The heartbeat state: STARTING until any message came in, then OK.
struct ExtractorHealth {
  bool starting = true;
  std::string detail;
};
ExtractorHealth extractor_health(int64_t messages_in, const std::string& input_channel);

class ExtractorNode {
 public:
  /// robot_T_laser: the laser mount (only motion compensation uses it).
  ExtractorNode(const ExtractorServiceConfig& config, const Pose2& robot_T_laser);

  void on_odometry(const OdometrySample& sample) { compensator_.on_odometry(sample); }
  /// One scan; the reference stays valid until the next call.
  const ExtractorOutput& on_scan(const LaserScan& scan);

  const ReflectorExtractor& extractor() const { return extractor_; }

 private:
  ReflectorExtractor extractor_;
  MotionCompensator compensator_;
  ExtractorOutput output_;
};

}  // namespace refloc
