#!/usr/bin/env bash
# The main job, run inside a private network namespace by deploy/demo.sh:
# start robot_sim and every service under supervisord (deploy/refloc start --sim),
# record an LCM log, drive the demo mission, print the true arrival error at each
# waypoint, the localization RMSE and NEES, stop everything.
#   deploy/run_mission.sh [--build-dir DIR] [--mission FILE] [--json FILE] [--no-motion-compensation]
#                         [--range-offset-mm N] [--log-dir DIR]
# --build-dir DIR: holds bin/ (default: the install prefix when run from one, else <repo>/build).
# --log-dir DIR: the run's logs, LCM log and edited configs (default <root>/logs/demo-<time>).
# --range-offset-mm N: the simulated LMS100 adds N mm (-1000..1000) to every range (its error
# model's render/sensor/range_offset in robot_sim.json); pose_solver estimates the bias.
# Relative paths are the caller's; runs from a checkout or an install (cmake --install).
set -euo pipefail
root="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)"
build_dir="$root/build"
[ -d "$root/bin" ] && build_dir="$root"
mission="$root/deploy/config/mission_demo.json"
json=""
run_dir=""
motion_compensation=true
range_offset_mm=""
range_offset_given=false
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build_dir="$2"; shift 2 ;;
    --mission) mission="$2"; shift 2 ;;
    --json) json="$2"; shift 2 ;;
    --log-dir) run_dir="$2"; shift 2 ;;
    --no-motion-compensation) motion_compensation=false; shift ;;
    --range-offset-mm) range_offset_given=true; range_offset_mm="${2-}"; shift $(($# > 1 ? 2 : 1)) ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "run_mission: unknown argument '$1' (see --help)" >&2; exit 64 ;;
  esac
done

if [ "$range_offset_given" = true ]; then
  if ! [[ "$range_offset_mm" =~ ^[-+]?[0-9]+([.][0-9]+)?$ ]] ||
    ! awk -v v="$range_offset_mm" 'BEGIN { exit !(v >= -1000 && v <= 1000) }'; then
    echo "run_mission: --range-offset-mm wants a number of millimetres in -1000..1000, got '$range_offset_mm'" >&2
    exit 64
  fi
fi

if [ -z "$run_dir" ]; then
  # An install under /opt/refloc is not the user's to write: their state directory then.
  logs="$root/logs"
  mkdir -p "$logs" 2>/dev/null && [ -w "$logs" ] || logs="${XDG_STATE_HOME:-$HOME/.local/state}/refloc"
  run_dir="$logs/demo-$(date +%Y%m%d-%H%M%S)"
fi
mkdir -p "$run_dir"
run_dir="$(cd "$run_dir" && pwd)"
[ -f "$mission" ] || { echo "run_mission: no mission file '$mission'" >&2; exit 2; }
mission="$(realpath "$mission")"
[ -d "$build_dir/bin" ] || { echo "run_mission: no $build_dir/bin (build first, or --build-dir)" >&2; exit 2; }
REFLOC_BUILD="$(realpath "$build_dir")"
export REFLOC_BUILD
export REFLOC_LOG_DIR="$run_dir"
export REFLOC_RUN_DIR="$run_dir/supervisor"
if [ "$motion_compensation" = false ] || [ -n "$range_offset_mm" ]; then
  # Same configs, edited in the run's copy.
  export REFLOC_CONFIG_DIR="$run_dir/config"
  mkdir -p "$REFLOC_CONFIG_DIR"
  cp -r "$root/deploy/config/." "$REFLOC_CONFIG_DIR/"
fi
if [ "$motion_compensation" = false ]; then
  # The extractor leaves detections where their beams saw them.
  sed -i 's/"motion_compensation": true/"motion_compensation": false/' "$REFLOC_CONFIG_DIR/reflector_extractor.json"
  grep -q '"motion_compensation": false' "$REFLOC_CONFIG_DIR/reflector_extractor.json"
fi
if [ -n "$range_offset_mm" ]; then
  # The simulated sensor's systematic range offset (robot_sim.json render/sensor/range_offset [m]).
  sim_config="$REFLOC_CONFIG_DIR/robot_sim.json"
  # Its // comments stand on lines of their own; jq 1.6 reads no comments, so sed drops them.
  sed '/^[[:space:]]*\/\//d' "$sim_config" |
    jq --argjson mm "${range_offset_mm#+}" '.render.sensor.range_offset = ($mm / 1000)' >"$sim_config.new"
  mv "$sim_config.new" "$sim_config"
  echo "== simulated LMS100 range offset: $range_offset_mm mm ($sim_config)"
fi
export LCM_DEFAULT_URL="${LCM_DEFAULT_URL:-udpm://239.255.76.67:7667?ttl=0&recv_buf_size=2097152}"
refloc="$root/deploy/refloc"
stop_stack() { "$refloc" stop >/dev/null 2>&1 || true; }
trap stop_stack EXIT

echo "== starting the refloc stack (logs and LCM log in $run_dir)"
# --sim: robot_sim runs and the driver dials its emulator on 127.0.0.1.
"$refloc" start --sim >/dev/null
"$refloc" status || true

mission_args=(--mission "$mission" --log-file "$run_dir/refloc.0" --trace "$run_dir/path_trace.csv")
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
# The path and the errors over time drawn into the run's folder (path.png, path.svg) from the
# trace refloc-mission wrote; a by-product: without matplotlib (or a trace) the exit code stays.
config_dir="${REFLOC_CONFIG_DIR:-$root/deploy/config}"
world_file="$config_dir/$(sed '/^[[:space:]]*\/\//d' "$config_dir/robot_sim.json" | jq -r '.world_file' 2>/dev/null ||
  echo world_demo.json)"
plot_cmd=("$root/tools/refloc-plot/refloc-plot.py" mission --trace "$run_dir/path_trace.csv"
  --world "$world_file" --title "refloc demo mission ($(basename "$run_dir"))")
if [ -s "$run_dir/path_trace.csv" ] &&
  "${plot_cmd[@]}" --out "$run_dir/path.png" --out "$run_dir/path.svg" >/dev/null; then
  echo "== path plot: $run_dir/path.png (and .svg); redraw: $(printf '%q ' "${plot_cmd[@]}")--out F.png"
else
  echo "== no path plot (python3-matplotlib missing or no trace; deploy/install-deps.sh installs it)" >&2
fi
exit $rc
