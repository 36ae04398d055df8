#pragma once
// POSE is published once per ODOMETRY message, so a dead or restarting
// odometry service would silence POSE too, although laser fixes keep coming.
// While ODOMETRY is silent, each usable fix is published as a DEGRADED POSE
// instead: consumers keep seeing where the robot is, and that it is degraded
// (the navigator does not drive on it; the matcher does not track from it).

#include <cstdint>

namespace refloc {

class OdometrySilence {
 public:
  /// timeout [s]: no ODOMETRY this long is silence.
  explicit OdometrySilence(double timeout);

  /// An ODOMETRY message arrived at now_mono_us [monotonic us]; its POSE has utime pose_utime [us].
  void on_odometry(int64_t now_mono_us, int64_t pose_utime);
  /// Whether a fix referring to fix_utime [us], arriving at now_mono_us, is to be published
  /// as POSE (odometry silent, and the fix newer than every POSE so far). Records it if so.
  bool publish_fix(int64_t now_mono_us, int64_t fix_utime);

 private:
  int64_t timeout_us_;
  int64_t last_odometry_mono_us_ = -1;
  int64_t last_pose_utime_ = -1;
};

}  // namespace refloc
