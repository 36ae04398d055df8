#include "trajectory_consistency.hpp"

#include "common/angles.hpp"

namespace refloc {

ConsistencySummary consistency_against_truth(const std::vector<StampedFix>& fixes, const Trajectory& truth,
                                             int64_t from_utime) {
  ConsistencyAccumulator accumulator;
  for (const auto& fix : fixes) {
    if (fix.utime < from_utime) continue;
    const auto map_T_true = truth.at(fix.utime);
    if (!map_T_true) continue;
    const Eigen::Vector3d error(fix.map_T_robot.x - map_T_true->x, fix.map_T_robot.y - map_T_true->y,
                                angle_diff(fix.map_T_robot.theta, map_T_true->theta));
    accumulator.add(error, fix.covariance);
  }
  return accumulator.summary();
}

}  // namespace refloc
