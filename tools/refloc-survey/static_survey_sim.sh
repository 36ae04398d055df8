#!/usr/bin/env bash
# refloc-survey static against the simulated sensor end to end: robot_sim's emulated LMS100
# (standing at robot_sim.json's initial pose, 3,3,0 in the demo hall) -> lms100_driver -> LCM ->
# refloc-survey static live; then every surveyed reflector against the world's true map: error,
# sigma (largest axis of its covariance) and error / sigma (Mahalanobis), and how many lie within 3.
# Runs in a private network namespace (tests/tools/run_in_netns.sh, needs root).
#   tools/refloc-survey/static_survey_sim.sh [--range-offset-mm N] [--scans N] [-- SURVEY OPTIONS...]
# --range-offset-mm N: the emulated LMS100 adds N mm to every range (render/sensor/range_offset).
# SURVEY OPTIONS go to refloc-survey static, e.g. --range-bias-mm 30 --range-bias-sigma-mm 2.
set -euo pipefail
root="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/../.." && pwd)"
bin="${REFLOC_BUILD:-$root/build}/bin"
offset_mm=0
scans=100
while [ $# -gt 0 ]; do
  case "$1" in
    --range-offset-mm) offset_mm="$2"; shift 2 ;;
    --scans) scans="$2"; shift 2 ;;
    --) shift; break ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "static_survey_sim: unknown argument '$1' (see --help)" >&2; exit 64 ;;
  esac
done
if [ "${REFLOC_IN_NETNS:-}" != "1" ]; then
  exec "$root/tests/tools/run_in_netns.sh" "$0" --range-offset-mm "$offset_mm" --scans "$scans" -- "$@"
fi
work="$(mktemp -d)"
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; wait; rm -rf "$work"; }
trap cleanup EXIT
# jq reads no comments: drop the full-line ones (as run_mission.sh does).
sed '/^ *\/\//d' "$root/deploy/config/robot_sim.json" |
  jq --argjson o "$(awk -v mm="$offset_mm" 'BEGIN { print mm / 1000 }')" --arg world "$root/deploy/config/world_demo.json" \
    '.render.sensor.range_offset = $o | .world_file = $world' >"$work/robot_sim.json"
pose="$(jq -r '.initial_pose | "\(.x_m),\(.y_m),\(.theta_rad)"' "$work/robot_sim.json")"
"$bin/robot_sim" --config "$work/robot_sim.json" --port 22111 >"$work/robot_sim.log" 2>&1 &
pids+=($!)
"$bin/lms100_driver" --config "$root/deploy/config/lms100_driver.json" --host 127.0.0.1 --port 22111 \
  >"$work/lms100_driver.log" 2>&1 &
pids+=($!)
"$bin/refloc-survey" static --scans "$scans" --pose "$pose" --timeout-s 20 --out "$work/map.json" "$@"
python3 - "$work/map.json" "$root/deploy/config/map_demo.json" <<'PY'
import json, math, sys
surveyed = json.load(open(sys.argv[1]))["reflectors"]
truth = [(r["id"], r["x"], r["y"]) for r in json.load(open(sys.argv[2]))["reflectors"]]
inside = 0
for r in surveyed:
    tid, tx, ty = min(truth, key=lambda t: math.hypot(t[1] - r["x"], t[2] - r["y"]))
    ex, ey = r["x"] - tx, r["y"] - ty
    xx, xy, yy = r["covariance_m2"]
    d = math.sqrt((yy * ex * ex - 2 * xy * ex * ey + xx * ey * ey) / (xx * yy - xy * xy))
    sigma = math.sqrt(0.5 * (xx + yy) + math.hypot(0.5 * (xx - yy), xy))
    inside += d <= 3
    print(f"id {r['id']} (true {tid}): error {1e3 * math.hypot(ex, ey):.2f} mm, sigma {1e3 * sigma:.2f} mm, {d:.2f} sigma")
print(f"inside 3 sigma: {inside} of {len(surveyed)}")
PY
