#pragma once
// The simulated robot's recent true poses, written by the simulation loop and
// read by the LMS100 emulator's server thread, which renders each beam from the
// pose at that beam's time (a moving robot skews the scan, as a real one does).

#include "common/se2.hpp"

#include <cstdint>
#include <mutex>
#include <vector>

namespace refloc {

class PoseHistory {
 public:
  /// Keeps the last capacity poses (at 1 kHz, 1000 = one second).
  explicit PoseHistory(size_t capacity);

  /// Append the pose at utime [us]; times must increase (older ones are ignored).
  void add(int64_t utime, const Pose2& pose);
  /// Pose at utime, interpolated between the neighbouring samples; clamped to the
  /// oldest / newest sample outside the kept span; identity when empty. Thread-safe.
  Pose2 at(int64_t utime) const;

 private:
  struct Sample {
    int64_t utime;
    Pose2 pose;
  };
  const Sample& sample(size_t i) const;  ///< i-th oldest; caller holds the lock

  mutable std::mutex mutex_;
  std::vector<Sample> ring_;
  size_t next_ = 0;   ///< where the next sample goes
  size_t count_ = 0;  ///< samples held
};

}  // namespace refloc
