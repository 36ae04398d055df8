#!/usr/bin/env bash
# Hostile bus (issue 11), in a private netns (tests/tools/run_in_netns.sh): the whole stack under
# supervisord (deploy/refloc) drives tests/ops/data/restart_mission.json while ops_hostile_peer
# sends, phase after phase in bursts of 4 at 10 a second, lying array and string lengths (-1,
# 2^31-1, 50,000,000, one more than the bytes left; every subscribed type cut one byte short),
# stamps +1 h / INT64_MAX / -1 h / 0, absurd twists (1e308 m/s, 1e6 rad/s) and NaN / inf /
# 1e300 in every numeric field, each built from the latest real message of its channel.
# The simulated LMS100 ranges OFFSET_MM (default 30, the LMS100's specified limit; 0: none) long
# the whole time, so pose_solver and pose_fusion have to estimate the bias while the bus is
# attacked (this test also took over the old ops_biased_range_mission: one 75 s mission for both,
# CI's 30 minutes being short).
#   hostile_bus_mission.sh REPO_ROOT BUILD_DIR [OFFSET_MM]
# Asserted, and every failure printed before the exit (the list is the point):
#   mission    refloc-mission reaches every waypoint within tolerance (its own GROUND_TRUTH check),
#              max true error < 20 mm as in restart_under_load.sh;
#   alive      every program has the pid it started with and is RUNNING at the end;
#   rss        peak RSS (VmHWM) of every service < 50 MB (150 MB in a sanitized build);
#   log        ops_hostile_log_check on the LCM log: no non-finite number on any channel
#              (the peer's own datagrams excluded by the hashes it records: it writes to the
#              stack's input channels, so the channel cannot tell), no OK POSE/LASER_POSE
#              > 0.1 m from GROUND_TRUTH, every hostile datagram counted in the receiving
#              service's HEARTBEAT (decode_errors + rejection counters) per phase;
#   bias       with an offset: POSE position NEES mean < 4 (the fused pose's errors on average
#              at most sqrt(2) times the sigma it publishes; honest is 2, a bias left unestimated
#              gave 76-81 in refloc-eval's study, the factor 2 is room for a loaded host) and
#              pose_solver's range bias estimate within 10 mm of the offset (refloc-mission's JSON).
# Not attacked: GROUND_TRUTH and NAV_STATUS (only refloc-mission reads them: it is the referee),
# HEARTBEAT is attacked too: every service's runtime reads it (a second instance of itself).
set -euo pipefail
repo="$1"
build="$2"
offset_mm="${3:-30}"
[[ "$offset_mm" =~ ^[-+]?[0-9]+$ ]] || { echo "hostile_bus_mission: OFFSET_MM wants whole millimetres, got '$offset_mm'" >&2; exit 64; }
offset_mm="${offset_mm#+}"
tmp="$(mktemp -d /tmp/refloc_hostile_test.XXXXXX)"
export REFLOC_BUILD="$build" REFLOC_RUN_DIR="$tmp/run" REFLOC_LOG_DIR="$tmp/logs"
export REFLOC_CONFIG_DIR="$repo/deploy/config" REFLOC_LOG_SPLIT_MB=2000
if [ "$offset_mm" != 0 ]; then
  # The shipped configs, robot_sim.json's render/sensor/range_offset [m] edited in the copy
  # (deploy/run_mission.sh --range-offset-mm does the same). Its // comments stand on lines of
  # their own; jq 1.6 reads no comments, so sed drops them.
  export REFLOC_CONFIG_DIR="$tmp/config"
  mkdir -p "$REFLOC_CONFIG_DIR"
  cp -r "$repo/deploy/config/." "$REFLOC_CONFIG_DIR/"
  sed '/^[[:space:]]*\/\//d' "$repo/deploy/config/robot_sim.json" |
    jq --argjson mm "$offset_mm" '.render.sensor.range_offset = ($mm / 1000)' >"$REFLOC_CONFIG_DIR/robot_sim.json"
  echo "simulated LMS100 range offset: $offset_mm mm"
fi
# The product's default URL: lcm-logger (LCM's, not ours) gets no receive buffer otherwise and
# lost 3 of 348 hostile datagrams on a loaded CI host.
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=2097152"
export REFLOC_ARGS_lms100_driver="--host 127.0.0.1"
unset REFLOC_PROGRAMS
refloc="$repo/deploy/refloc"
mapfile -t programs < <("$refloc" list)
mapfile -t services < <("$refloc" list --services)
rss_limit_kb=$((50 * 1024))
# AddressSanitizer's shadow memory and quarantine add tens of MB to every process (CI builds
# sanitized): there the bound is 150 MB, still far below what a decoded lie allocated (4 GB).
# The 50 MB figure is measured on a Release build (issue 11's note).
# Not `ldd | grep -q`: under pipefail grep's early exit fails ldd with SIGPIPE (seen in ctest).
if [[ "$(ldd "$build/bin/pose_solver" 2>/dev/null)" == *libasan* ]]; then
  rss_limit_kb=$((150 * 1024))
  # ASan keeps freed memory in a quarantine (256 MB by default) to catch use after free: a
  # service that allocates a lot per message (web_console builds a JSON frame for each) fills
  # it under this test's traffic and its RSS reads 370 MB without growing. 32 MB keeps the
  # check about growth; a real leak still crosses the bound.
  export ASAN_OPTIONS="${ASAN_OPTIONS:-}${ASAN_OPTIONS:+:}quarantine_size_mb=32"
  echo "sanitized build: peak RSS bound 150 MB instead of 50 MB, ASan quarantine 32 MB"
fi
mission_pid="" peer_pid="" passed=false
failures=()

cleanup() {
  [ -n "$peer_pid" ] && kill "$peer_pid" 2>/dev/null || true
  [ -n "$mission_pid" ] && kill "$mission_pid" 2>/dev/null || true
  if [ -f "$REFLOC_RUN_DIR/supervisord.pid" ]; then "$refloc" stop >/dev/null 2>&1 || true; fi
  if [ "$passed" = true ]; then rm -rf "$tmp"; else echo "kept $tmp for inspection" >&2; fi
}
trap cleanup EXIT
fatal() { echo "FAIL: $*" >&2; exit 1; }
all_pids() {
  "$refloc" status 2>/dev/null | awk '{pid = ""} $2 == "RUNNING" {pid = $4; sub(",", "", pid)} {print $1, pid}' || true
}
pid_in() { awk -v n="$1" '$1 == n {print $2}' <<<"$2"; }

for b in "${services[@]}" refloc-mission ops_hostile_peer ops_hostile_log_check; do
  [ -x "$build/bin/$b" ] || fatal "$build/bin/$b not built"
done
command -v supervisord >/dev/null && command -v lcm-logger >/dev/null || fatal "no supervisord/lcm-logger"
command -v jq >/dev/null || fatal "no jq (deploy/install-deps.sh)"

"$refloc" start --sim >/dev/null || fatal "deploy/refloc start"
for _ in $(seq 300); do
  missing=0
  start_pids="$(all_pids)"
  for p in "${programs[@]}"; do [ -n "$(pid_in "$p" "$start_pids")" ] || missing=1; done
  [ $missing = 0 ] && break
  sleep 0.1
done
[ $missing = 0 ] || fatal "not everything RUNNING: $("$refloc" status || true)"

"$build/bin/refloc-mission" --mission "$repo/tests/ops/data/restart_mission.json" --json "$tmp/mission.json" \
  --log-file "$tmp/logs/refloc.0" --trace "$tmp/path_trace.csv" >"$tmp/mission.out" 2>&1 &
mission_pid=$!
for _ in $(seq 600); do
  grep -q "^sent mission" "$tmp/mission.out" && break
  kill -0 "$mission_pid" 2>/dev/null || { cat "$tmp/mission.out" >&2; fatal "refloc-mission ended before driving"; }
  sleep 0.1
done
grep -q "^sent mission" "$tmp/mission.out" || fatal "the mission never started"
sleep 1   # under way: the peer's bases are real messages of a driving robot

"$build/bin/ops_hostile_peer" --record "$tmp/hostile.tsv" --rate 10 --burst 4 --phase-gap-s 1.5 \
  >"$tmp/peer.out" 2>&1 &
peer_pid=$!
t_peer=$(date +%s)
set +e
wait "$peer_pid"
peer_rc=$?
peer_pid=""
t_peer_end=$(date +%s)
kill -0 "$mission_pid" 2>/dev/null && mission_running_after_peer=yes || mission_running_after_peer=no
wait "$mission_pid"
mission_rc=$?
set -e
mission_pid=""
cat "$tmp/peer.out"
echo "hostile peer ran $((t_peer_end - t_peer)) s; mission still driving when it finished: $mission_running_after_peer"
[ "$peer_rc" = 0 ] || failures+=("peer: ops_hostile_peer exited $peer_rc")
[ "$mission_running_after_peer" = yes ] || failures+=("peer: the mission ended before the peer's last phase")
cat "$tmp/mission.out"

# Every pid as at the start, and its peak RSS, before anything is stopped.
end_pids="$(all_pids)"
echo "== processes: pid at start -> at end, peak RSS (VmHWM)"
for p in "${programs[@]}"; do
  old="$(pid_in "$p" "$start_pids")" new="$(pid_in "$p" "$end_pids")"
  hwm="-"
  [ -n "$new" ] && hwm="$(awk '/^VmHWM:/ {print $2}' "/proc/$new/status" 2>/dev/null || true)"
  [ -n "$hwm" ] || hwm="-"
  printf '%-20s %8s -> %-8s %8s kB\n' "$p" "$old" "${new:-dead}" "$hwm"
  [ "$old" = "$new" ] || failures+=("alive: $p pid $old -> ${new:-not RUNNING} (died or restarted)")
  [ "$p" = lcm-logger ] && continue
  if [ "$hwm" != "-" ] && [ "$hwm" -ge "$rss_limit_kb" ]; then
    failures+=("rss: $p peak RSS $hwm kB >= $rss_limit_kb kB")
  fi
done
"$build/bin/refloc-status" --once 2>/dev/null || true
"$refloc" stop >/dev/null 2>&1 || true   # lcm-logger flushes the log

[ "$mission_rc" = 0 ] || failures+=("mission: refloc-mission exited $mission_rc (not every waypoint within tolerance)")
if [ -f "$tmp/mission.json" ]; then
  python3 - "$tmp/mission.json" <<'PY' || failures+=("mission: report (above)")
import json, sys
r = json.load(open(sys.argv[1]))
print(f"mission: {r['waypoints_reached']}/{r['waypoints_total']} waypoints, max true error "
      f"{r['max_waypoint_error_mm']:.1f} mm, {r['duration_s']:.1f} s, goal resends {r['goal_resends']}, "
      f"POSE RMSE {r['pose_rmse_mm']} mm, POSE NEES {r['pose_nees']}, range bias {r['range_bias_mm']} mm")
assert r["waypoints_reached"] == r["waypoints_total"], r
assert not r["aborted"], r["abort_reason"]
assert r["max_waypoint_error_mm"] < 20.0, r["max_waypoint_error_mm"]
PY
  if [ "$offset_mm" != 0 ]; then
    jq -e '.pose_nees.nees_fixes > 100 and .pose_nees.position_nees_mean < 4' "$tmp/mission.json" >/dev/null ||
      failures+=("bias: POSE position NEES mean not < 4: $(jq -c .pose_nees "$tmp/mission.json")")
    jq -e --argjson mm "$offset_mm" '.range_bias_mm != null and ((.range_bias_mm - $mm) | fabs) < 10' \
      "$tmp/mission.json" >/dev/null ||
      failures+=("bias: range bias estimate not within 10 mm of $offset_mm: $(jq -c '{range_bias_mm, range_bias_sigma_mm}' "$tmp/mission.json")")
  fi
else
  failures+=("mission: no report $tmp/mission.json")
fi

echo "== log check"
"$build/bin/ops_hostile_log_check" --log "$tmp/logs/refloc.0" --record "$tmp/hostile.tsv" --max-ok-error-m 0.1 ||
  failures+=("log: ops_hostile_log_check (FAIL lines above)")

echo "== what the services said (last 3 warnings or errors each, from $REFLOC_RUN_DIR/<name>.log)"
for s in "${services[@]}"; do
  f="$REFLOC_RUN_DIR/$s.log"
  [ -f "$f" ] || continue
  grep -aiE 'warn|error|critical|terminate|bad_alloc' "$f" | tail -n 3 | sed "s/^/  $s: /" || true
done

if [ ${#failures[@]} -gt 0 ]; then
  printf 'FAIL %s\n' "${failures[@]}" >&2
  exit 1
fi
passed=true
echo "PASS"
