#pragma once
// Starting the filter where the laser sees only three reflectors. The solver calls such fixes
// DEGRADED (too few reflectors to estimate the range bias as well), and alone they never start
// the filter; but a pose_fusion restarted where the robot sees 2-3 reflectors would wait for an
// OK fix as long as the robot stays there (131 s once, in CI). Several such fixes that agree
// with each other through the odometry between them are evidence enough: each pending fix is
// carried forward by the odometry, and a new one starts the filter when enough of them lie
// within the gate of it.

#include "common/se2.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace refloc {

class UsableFixAgreement {
 public:
  /// needed: fixes that must agree, the new one included (0 or 1: never start from them);
  /// window_s: the oldest pending fix kept, before the newest [s]; gate_chi2: squared
  /// Mahalanobis distance of agreement (3 dof).
  UsableFixAgreement(int needed, double window_s, double gate_chi2)
      : needed_(needed), window_us_(static_cast<int64_t>(window_s * 1e6)), gate_chi2_(gate_chi2) {}

  /// Carries every pending fix along one odometry step (delta in the body frame, covariance q).
  void add_odometry(const Pose2& delta, const Eigen::Matrix3d& q);
  /// A fix taken at fix_utime, already carried to the latest odometry time: true when it and
  /// enough pending fixes agree (then the caller starts from it and clears); else it is kept.
  bool offer(int64_t fix_utime, const Pose2& map_T_robot_now, const Eigen::Matrix3d& covariance_now);
  void clear() { pending_.clear(); }
  /// How many fixes agreed in the last offer() that returned true (the new one included).
  int last_agreeing() const { return last_agreeing_; }
  /// Time from the oldest agreeing fix to the newest, of that offer [s].
  double last_span_s() const { return last_span_s_; }
  bool enabled() const { return needed_ > 1; }

 private:
  struct Pending {
    int64_t utime = 0;
    Pose2 map_T_robot;  ///< carried to the latest odometry time
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
  };
  static constexpr size_t kMaxPending = 100;

  int needed_;
  int64_t window_us_;
  double gate_chi2_;
  std::vector<Pending> pending_;
  int last_agreeing_ = 0;
  double last_span_s_ = 0.0;
};

}  // namespace refloc
