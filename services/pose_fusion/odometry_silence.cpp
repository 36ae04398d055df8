#include "pose_fusion/odometry_silence.hpp"

#include <algorithm>

namespace refloc {

OdometrySilence::OdometrySilence(double timeout) : timeout_us_(static_cast<int64_t>(timeout * 1e6)) {}

void OdometrySilence::on_odometry(int64_t now_mono_us, int64_t pose_utime) {
  last_odometry_mono_us_ = now_mono_us;
  last_pose_utime_ = std::max(last_pose_utime_, pose_utime);
}

bool OdometrySilence::publish_fix(int64_t now_mono_us, int64_t fix_utime) {
  const bool silent = last_odometry_mono_us_ < 0 || now_mono_us - last_odometry_mono_us_ > timeout_us_;
  if (!silent || fix_utime <= last_pose_utime_) return false;
  last_pose_utime_ = fix_utime;
  return true;
}

}  // namespace refloc
