#!/usr/bin/env bash
# The example motor bridge over real LCM (run inside tests/tools/run_in_netns.sh):
# motor_bridge_harness sends CMD_VEL and judges WHEEL_ENCODERS from the bridge and
# ODOMETRY from the real mecanum_odometry fed by it.
#   motor_bridge_test.sh BIN_DIR SOURCE_DIR
set -euo pipefail
bin=$1
config=$2/deploy/config
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
}
trap cleanup EXIT
# Counts start 3,000 ticks below the int32 limit, so they wrap within the first 0.2 s of driving.
"$bin/refloc-motor-bridge-example" --robot "$config/robot.json" --start-ticks 2147480647 & pids+=($!)
"$bin/mecanum_odometry" --robot "$config/robot.json" --config "$config/mecanum_odometry.json" & pids+=($!)
"$bin/motor_bridge_harness" "$config/robot.json"
