#!/usr/bin/env bash
# The motion services over real LCM (run inside tests/tools/run_in_netns.sh):
# robot_sim (no laser) -> mecanum_odometry -> pose_fusion -> navigator -> robot_sim,
# with motion_loop_harness standing in for the laser pipeline.
#   motion_loop_test.sh BIN_DIR SOURCE_DIR
set -euo pipefail
bin=$1
config=$2/deploy/config
tmp=$(mktemp -d)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT
# Start near the int32 limit so the encoder counts wrap during the run.
echo '{"initial_pose": {"x_m": 0.0, "y_m": 0.0, "theta_rad": 0.0}, "encoder_start_ticks": 2147470000}' > "$tmp/sim.json"
"$bin/robot_sim" --robot "$config/robot.json" --config "$tmp/sim.json" --no-laser & pids+=($!)
"$bin/mecanum_odometry" --robot "$config/robot.json" --config "$config/mecanum_odometry.json" & pids+=($!)
"$bin/pose_fusion" --robot "$config/robot.json" --config "$config/pose_fusion.json" & pids+=($!)
"$bin/navigator" --config "$config/navigator.json" & pids+=($!)
"$bin/motion_loop_harness"
