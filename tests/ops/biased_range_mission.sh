#!/usr/bin/env bash
# The demo mission with a +30 mm systematic range offset (the LMS100's specified limit) in the
# simulated sensor, through deploy/run_mission.sh --range-offset-mm 30, in a private netns
# (tests/tools/run_in_netns.sh): pose_solver has to estimate the bias for the robot to arrive.
#   biased_range_mission.sh REPO_ROOT BUILD_DIR [OFFSET_MM]
# Asserted from refloc-mission's --json:
#   every waypoint (7/7) reached, the largest true arrival error < 20 mm;
#   POSE position NEES mean < 4, i.e. the fused pose's errors on average at most sqrt(2) times
#   the sigma it publishes (honest: 2; Release runs at -30/0/+30 mm gave 1.13-1.28, a range bias
#   left unestimated gave 76-81 in refloc-eval's study; the factor 3 is room for a loaded host);
#   pose_solver's range bias estimate within 10 mm of the offset.
set -euo pipefail
repo="$1"
build="$2"
offset_mm="${3:-30}"
tmp="$(mktemp -d /tmp/refloc_biased_mission.XXXXXX)"
passed=false
cleanup() { if [ "$passed" = true ]; then rm -rf "$tmp"; else echo "kept $tmp for inspection" >&2; fi; }
trap cleanup EXIT
command -v jq >/dev/null || { echo "SKIP: no jq" >&2; exit 77; }

set +e
"$repo/deploy/run_mission.sh" --build-dir "$build" --range-offset-mm "$offset_mm" --log-dir "$tmp/run" \
  --json "$tmp/mission.json" >"$tmp/mission.out" 2>&1
rc=$?
set -e
cat "$tmp/mission.out"
[ -s "$tmp/mission.json" ] || { echo "FAIL: no mission JSON (run_mission exit $rc)" >&2; exit 1; }

failures=()
check() {  # check "what" JQ_EXPRESSION: the expression must be true on the mission JSON
  jq -e "$2" "$tmp/mission.json" >/dev/null || failures+=("$1: $(jq -c "$3" "$tmp/mission.json")")
}
check "every waypoint reached" '.waypoints_reached == .waypoints_total and .waypoints_total == 7' \
  '{waypoints_reached, waypoints_total, abort_reason}'
check "max true arrival error < 20 mm" '.max_waypoint_error_mm < 20' '.max_waypoint_error_mm'
check "POSE position NEES mean < 4" '.pose_nees.nees_fixes > 100 and .pose_nees.position_nees_mean < 4' '.pose_nees'
check "range bias estimated within 10 mm" \
  ".range_bias_mm != null and ((.range_bias_mm - $offset_mm) | fabs) < 10" '{range_bias_mm, range_bias_sigma_mm}'
if [ ${#failures[@]} -gt 0 ]; then
  printf 'FAIL: %s\n' "${failures[@]}" >&2
  exit 1
fi
[ "$rc" = 0 ] || { echo "FAIL: run_mission exit $rc" >&2; exit 1; }
echo "PASS: $(jq -c '{waypoints_reached, max_waypoint_error_mm, pose_rmse_mm, laser_pose_rmse_mm,
  pose_nees_mean: .pose_nees.position_nees_mean, range_bias_mm}' "$tmp/mission.json")"
passed=true
