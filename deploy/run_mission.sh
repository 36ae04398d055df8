#!/usr/bin/env bash
# The main job, run inside a private network namespace by deploy/demo.sh:
# start robot_sim and every service under supervisord (deploy/refloc), record
# an LCM log, drive the demo mission, print the true arrival error at each
# waypoint and the localization RMSE, stop everything.
#   deploy/run_mission.sh [--build-dir DIR] [--mission FILE] [--json FILE] [--no-motion-compensation]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
build_dir=build
mission=deploy/config/mission_demo.json
json=""
motion_compensation=true
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build_dir="$2"; shift 2 ;;
    --mission) mission="$2"; shift 2 ;;
    --json) json="$2"; shift 2 ;;
    --no-motion-compensation) motion_compensation=false; shift ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "run_mission: unknown argument '$1' (see --help)" >&2; exit 64 ;;
  esac
done

run_dir="$root/logs/demo-$(date +%Y%m%d-%H%M%S)"
mkdir -p "$run_dir"
export REFLOC_BUILD="$root/$build_dir"
export REFLOC_LOG_DIR="$run_dir"
export REFLOC_RUN_DIR="$run_dir/supervisor"
if [ "$motion_compensation" = false ]; then
  # Same configs, but the extractor leaves detections where their beams saw them.
  export REFLOC_CONFIG_DIR="$run_dir/config"
  cp -r "$root/deploy/config" "$REFLOC_CONFIG_DIR"
  sed -i 's/"motion_compensation": true/"motion_compensation": false/' "$REFLOC_CONFIG_DIR/reflector_extractor.json"
  grep -q '"motion_compensation": false' "$REFLOC_CONFIG_DIR/reflector_extractor.json"
fi
export LCM_DEFAULT_URL="${LCM_DEFAULT_URL:-udpm://239.255.76.67:7667?ttl=0&recv_buf_size=2097152}"
# The simulator's LMS100 emulator listens on loopback.
export REFLOC_ARGS_lms100_driver="${REFLOC_ARGS_lms100_driver:---host 127.0.0.1}"

stop_stack() { deploy/refloc stop >/dev/null 2>&1 || true; }
trap stop_stack EXIT

echo "== starting the refloc stack (logs and LCM log in $run_dir)"
deploy/refloc start >/dev/null
deploy/refloc status || true

mission_args=(--mission "$mission" --log-file "$run_dir/refloc.0")
[ -n "$json" ] && mission_args+=(--json "$json")
set +e
"$REFLOC_BUILD/bin/refloc-mission" "${mission_args[@]}"
rc=$?
set -e

echo "== service health at the end of the mission"
"$REFLOC_BUILD/bin/refloc-status" --once 2>/dev/null || true
stop_stack
trap - EXIT
echo "== LCM log: $(ls "$run_dir"/refloc.* 2>/dev/null | tr '\n' ' ')"
exit $rc
