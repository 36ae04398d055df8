#!/usr/bin/env bash
# Load test of the whole refloc stack: robot_sim (LMS100 emulator at 50 Hz) and
# every service under supervisord, as deploy/run_mission.sh starts them, in a
# private network namespace, with the robot driving the demo mission over and
# over. Measures for --duration seconds:
#   - scans: LMS100_SCAN published vs expected (50 Hz x duration), dropped scans
#     (scan-counter gaps + scans that never became a LASER_POSE), REFLECTORS and
#     LASER_POSE counts (refloc-log --scans);
#   - scan-to-LASER_POSE latency p50/p99/max from the LCM log (refloc-log --latency);
#   - per service: CPU% (utime+stime over the run from /proc/<pid>/stat; 100% =
#     one core), RSS mean/end and peak (VmRSS, VmHWM), HEARTBEAT handler p99
#     (worst window), decode errors, restarts.
# The verdict is refloc-log --load-test's (tools/refloc-log/load_verdict.hpp), over the
# LCM log and the samples this script writes (load_samples.txt in the run dir).
# Exit status: 0 pass; 1 a scan was dropped, p99 > --max-p99-ms, a service is
# missing from the report or restarted; 2 the stack did not come up (or refloc-log
# could not read its input); 64 usage.
#
#   deploy/load_test.sh [--duration S] [--build-dir DIR] [--json FILE] [--run-dir DIR]
#                       [--max-p99-ms MS] [--warmup-timeout S] [--mission FILE]
#                       [--console-clients N]
#
#   --duration S        measured time [600]
#   --build-dir DIR     build with bin/ (relative to the repo root) [build]
#   --json FILE         write the whole report as JSON
#   --run-dir DIR       LCM log, supervisor and program logs [logs/load-<date>]
#   --max-p99-ms MS     scan-to-pose p99 limit; 0 = report only (sanitizer builds) [5]
#   --warmup-timeout S  wait this long for the first LASER_POSE [60]
#   --mission FILE      mission repeated to keep the robot driving [deploy/config/mission_demo.json]
#   --console-clients N N WebSocket readers on web_console throughout (deploy/console_clients.py,
#                       python3-websocket), one of them stalling after 5 s; their summary is
#                       console_clients.json in the run dir [0]
# Environment: REFLOC_CONFIG_DIR (service configs, as for deploy/refloc), LCM_DEFAULT_URL.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

duration=600
build_dir=build
json=""
run_dir=""
max_p99_ms=5
warmup_timeout=60
mission=deploy/config/mission_demo.json
console_clients=0
while [ $# -gt 0 ]; do
  case "$1" in
    --duration) duration="$2"; shift 2 ;;
    --build-dir) build_dir="$2"; shift 2 ;;
    --json) json="$2"; shift 2 ;;
    --run-dir) run_dir="$2"; shift 2 ;;
    --max-p99-ms) max_p99_ms="$2"; shift 2 ;;
    --warmup-timeout) warmup_timeout="$2"; shift 2 ;;
    --mission) mission="$2"; shift 2 ;;
    --console-clients) console_clients="$2"; shift 2 ;;
    -h|--help) sed -n '2,33p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "load_test: unknown argument '$1' (see --help)" >&2; exit 64 ;;
  esac
done
[[ "$duration" =~ ^[0-9]+$ && "$duration" -ge 1 ]] || { echo "load_test: --duration must be whole seconds >= 1" >&2; exit 64; }
[[ "$console_clients" =~ ^[0-9]+$ && "$console_clients" -le 256 ]] ||
  { echo "load_test: --console-clients must be a whole number 0..256" >&2; exit 64; }
[ -z "$json" ] || json="$(realpath -m "$json")"

# LCM traffic of the test must not meet anything else: private network namespace.
if [ "${REFLOC_IN_NETNS:-}" != "1" ]; then
  args=(--duration "$duration" --build-dir "$build_dir" --max-p99-ms "$max_p99_ms"
        --warmup-timeout "$warmup_timeout" --mission "$mission" --console-clients "$console_clients")
  [ -n "$json" ] && args+=(--json "$json")
  [ -n "$run_dir" ] && args+=(--run-dir "$run_dir")
  exec "$root/tests/tools/run_in_netns.sh" "$0" "${args[@]}"
fi

for tool in jq supervisord lcm-logger; do
  command -v "$tool" >/dev/null || { echo "load_test: $tool not installed (deploy/install-deps.sh)" >&2; exit 2; }
done
export REFLOC_BUILD="$(realpath -m "$build_dir")"
for bin in refloc-log refloc-mission refloc-status robot_sim; do
  [ -x "$REFLOC_BUILD/bin/$bin" ] || { echo "load_test: $REFLOC_BUILD/bin/$bin not built" >&2; exit 2; }
done
run_dir="$(realpath -m "${run_dir:-$root/logs/load-$(date +%Y%m%d-%H%M%S)}")"
mkdir -p "$run_dir"
export REFLOC_LOG_DIR="$run_dir"
export REFLOC_RUN_DIR="$run_dir/supervisor"
export REFLOC_LOG_SPLIT_MB=100000  # one log file however long the run
export LCM_DEFAULT_URL="${LCM_DEFAULT_URL:-udpm://239.255.76.67:7667?ttl=0&recv_buf_size=2097152}"
export REFLOC_ARGS_lms100_driver="${REFLOC_ARGS_lms100_driver:---host 127.0.0.1}"

mapfile -t services < <(deploy/refloc list --services)  # deploy/services.list
programs=("${services[@]}" lcm-logger)
mission_loop_pid=""
clients_pid=""

cleanup() {
  [ -z "$clients_pid" ] || kill "$clients_pid" 2>/dev/null || true
  if [ -n "$mission_loop_pid" ]; then
    kill -- "$mission_loop_pid" 2>/dev/null || true
    wait "$mission_loop_pid" 2>/dev/null || true
  fi
  deploy/refloc stop >/dev/null 2>&1 || true
}
trap cleanup EXIT

load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
echo "== load test: ${duration} s, build $REFLOC_BUILD, $(nproc) cores, load average $load_before"
echo "== run dir $run_dir"
if ! deploy/refloc start --sim "${services[@]}" >/dev/null; then
  echo "load_test: not every service started; see $REFLOC_RUN_DIR" >&2
  exit 2
fi

# Warm: every service beats and the solver has published poses.
echo "== waiting for the first LASER_POSE (at most ${warmup_timeout} s)"
warm=false
deadline=$((SECONDS + warmup_timeout))
while [ $SECONDS -lt $deadline ]; do
  status="$("$REFLOC_BUILD/bin/refloc-status" --once --wait 1.5 --json 2>/dev/null || true)"
  if jq -e --argjson n "${#services[@]}" \
      '[.services[] | select(.present)] | length >= $n and (map(select(.service == "pose_solver" and .messages_out > 0)) | length == 1)' \
      >/dev/null 2>&1 <<<"$status"; then
    warm=true
    break
  fi
done
if [ "$warm" != true ]; then
  echo "load_test: the stack did not produce LASER_POSE within ${warmup_timeout} s" >&2
  deploy/refloc status >&2 || true
  exit 2
fi

# Keep the robot driving: the demo mission ends where it starts, so repeat it.
(
  child=""
  trap 'kill -- "$child" 2>/dev/null; exit 0' TERM
  i=0
  while true; do
    "$REFLOC_BUILD/bin/refloc-mission" --mission "$mission" --json "$run_dir/mission.$i.json" \
      >>"$run_dir/mission.log" 2>&1 &
    child=$!
    wait "$child" || true
    i=$((i + 1))
    sleep 0.2
  done
) &
mission_loop_pid=$!

# The pid supervisord runs each program under (deploy/refloc exec replaces itself
# with the binary). supervisorctl is asked again only when that process is gone:
# it is a Python start-up each time, which would load the machine under test.
declare -A pid cpu0 cpu_banked cpu_ticks rss_sum rss_end hwm samples pid_changes
ctl() { supervisorctl -c deploy/supervisord.conf -s "unix://$REFLOC_RUN_DIR/supervisor.sock" "$@"; }
cpu_of() {  # utime + stime [ticks] of a pid; the fields after the ')' that ends comm
  local stat rest f
  read -r stat <"/proc/$1/stat" 2>/dev/null || return 1
  rest="${stat##*) }"
  read -r -a f <<<"$rest"
  echo $((f[11] + f[12]))
}
read_memory() {  # sets rss_kb and hwm_kb of a pid
  local key value unit
  rss_kb=""; hwm_kb=""
  while read -r key value unit; do
    case "$key" in VmRSS:) rss_kb=$value ;; VmHWM:) hwm_kb=$value ;; esac
  done <"/proc/$1/status" 2>/dev/null || true
}
while read -r name state _ number _; do
  [ "$state" = RUNNING ] && pid[$name]="${number%,}"
done < <(ctl status "${services[@]}" || true)
# The log, and with it the measurement, starts now.
deploy/refloc start --sim lcm-logger >/dev/null
t0=$(date +%s.%N)
pid[lcm-logger]="$(ctl pid lcm-logger)"
for p in "${programs[@]}"; do
  [ -n "${pid[$p]:-}" ] || { echo "load_test: $p is not running" >&2; exit 2; }
  cpu0[$p]="$(cpu_of "${pid[$p]}" || echo 0)"
  cpu_banked[$p]=0; cpu_ticks[$p]=0; rss_sum[$p]=0; rss_end[$p]=0; hwm[$p]=0; samples[$p]=0; pid_changes[$p]=0
done
if [ "$console_clients" -gt 0 ]; then
  # The console's address from its config (deploy/config/web_console.json unless overridden).
  console_config="${REFLOC_CONFIG_DIR:-deploy/config}/web_console.json"
  [ -f "$console_config" ] || console_config=deploy/config/web_console.json
  console_port="$(grep -v '^ *//' "$console_config" | jq -r '.server.port // 8080')"
  /usr/bin/python3 deploy/console_clients.py --url "ws://127.0.0.1:$console_port/" --clients "$console_clients" \
    --duration "$duration" --stall-one --json "$run_dir/console_clients.json" >"$run_dir/console_clients.log" 2>&1 &
  clients_pid=$!
  echo "== $console_clients WebSocket readers on web_console (one stops reading after 5 s)"
fi
echo "== measuring for ${duration} s (robot driving $mission in a loop)"

sample() {
  local p now ticks rss_kb hwm_kb
  for p in "${programs[@]}"; do
    if ! ticks="$(cpu_of "${pid[$p]}")"; then
      now="$(ctl pid "$p" 2>/dev/null || echo 0)"
      [ "$now" != "${pid[$p]}" ] || continue
      # Restarted: keep what the old process used, count the new one from zero.
      pid_changes[$p]=$((pid_changes[$p] + 1))
      cpu_banked[$p]=${cpu_ticks[$p]}
      pid[$p]="$now"
      cpu0[$p]=0
      ticks="$(cpu_of "$now")" || continue
    fi
    cpu_ticks[$p]=$((cpu_banked[$p] + ticks - cpu0[$p]))
    read_memory "${pid[$p]}"
    [ -n "$rss_kb" ] || continue
    rss_sum[$p]=$((rss_sum[$p] + rss_kb)); rss_end[$p]=$rss_kb; samples[$p]=$((samples[$p] + 1))
    if [ "${hwm_kb:-0}" -gt "${hwm[$p]}" ]; then hwm[$p]=$hwm_kb; fi
  done
}
end=$((SECONDS + duration))
while [ $SECONDS -lt $end ]; do
  sample
  left=$((end - SECONDS))
  if [ $left -gt 0 ]; then sleep "$((left < 5 ? left : 5))"; fi
done
sample
if [ -n "$clients_pid" ]; then
  wait "$clients_pid" 2>/dev/null || true
  clients_pid=""
  jq -c '{clients, frames_per_s_mean, kbytes_per_s_mean, ends: [.per_client[].end] | group_by(.) | map({(.[0]): length}) | add}' \
    "$run_dir/console_clients.json" 2>/dev/null || echo "load_test: no console_clients.json (see console_clients.log)" >&2
fi
deploy/refloc stop lcm-logger >/dev/null
t1=$(date +%s.%N)
kill -- "$mission_loop_pid" 2>/dev/null || true
wait "$mission_loop_pid" 2>/dev/null || true
mission_loop_pid=""
deploy/refloc stop >/dev/null
trap - EXIT
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"

log="$(ls "$run_dir"/refloc.* | head -1)"
# What the log cannot tell, for refloc-log's verdict (format: tools/refloc-log/load_test_samples.hpp).
samples_file="$run_dir/load_samples.txt"
{
  echo "# deploy/load_test.sh /proc samples, $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "duration_s $duration"
  echo "measured_s $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }')"
  echo "cores $(nproc)"
  echo "clock_ticks_per_s $(getconf CLK_TCK)"
  echo "max_p99_ms $max_p99_ms"
  echo "build $REFLOC_BUILD"
  echo "log $log"
  echo "load_average_before $load_before"
  echo "load_average_after $load_after"
  for p in "${programs[@]}"; do
    echo "process $p ${cpu_ticks[$p]} ${samples[$p]} ${rss_sum[$p]} ${rss_end[$p]} ${hwm[$p]} ${pid_changes[$p]}"
  done
} >"$samples_file"
echo "== analysing $log"
set +e
"$REFLOC_BUILD/bin/refloc-log" "$log" --load-test "$samples_file" --report "$run_dir/load_test.json"
rc=$?
set -e
[ -z "$json" ] || cp "$run_dir/load_test.json" "$json"
echo "== report: $run_dir/load_test.json"
exit $rc
