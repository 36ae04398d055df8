#!/usr/bin/env bash
# Restart under load (issue 6), in a private netns (tests/tools/run_in_netns.sh):
# the whole stack under supervisord (deploy/refloc) drives a mission
# (tests/ops/data/restart_kill_mission.json: out and back, so that the seven kills fit in it
# even when supervisorctl is slow on a loaded host) while every service in turn is killed
# with SIGKILL. Checks: supervisord restarts it; no other program's pid changes;
# the mission still reaches every waypoint within tolerance; from the LCM log
# (restart_log_check): POSE gap <= 1 s per kill (1.5 s sanitized), the new process back to useful
# output, and the restarted matcher's first OK is a global relocalization.
#   restart_under_load.sh REPO_ROOT BUILD_DIR
# Not killed: robot_sim is the simulated physical world (killing it resets the
# plant, which no real robot does), and lcm-logger records the log we measure.
# supervisord restarts a dead program only when its main loop wakes up: poll()
# with a 1 s timeout, and SIGCHLD does not interrupt it (Python retries EINTR).
# On a quiet stack that added 1-2 s to every restart (measured: spawn 1.0-2.0 s
# after the kill); deploy/supervisord.conf now runs supervisor-tick, whose output
# wakes the loop every 50 ms, and this test measures exactly what a field
# installation gets. Under systemd (deploy/systemd) it is RestartSec=0.5 instead.
# REFLOC_RESTART_POKE=1 also wakes supervisord through its control socket with
# curl during each restart (the test's earlier work-around, kept for comparison).
set -euo pipefail
repo="$1"
build="$2"
tmp="$(mktemp -d /tmp/refloc_restart_test.XXXXXX)"
export REFLOC_BUILD="$build" REFLOC_RUN_DIR="$tmp/run" REFLOC_LOG_DIR="$tmp/logs"
# REFLOC_RESTART_CONFIG_DIR: other service configs, e.g. to see a check fail.
export REFLOC_CONFIG_DIR="${REFLOC_RESTART_CONFIG_DIR:-$repo/deploy/config}" REFLOC_LOG_SPLIT_MB=2000
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
export REFLOC_ARGS_lms100_driver="--host 127.0.0.1"
unset REFLOC_PROGRAMS
refloc="$repo/deploy/refloc"
kills="$tmp/kills.txt"
# Every service of a real robot (deploy/services.list): not the simulated world.
mapfile -t victims < <("$refloc" list --services --real)
mapfile -t programs < <("$refloc" list)
spacing_us=3500000   # kill to kill; each restart's recovery is seen before the next kill
mission_pid=""
passed=false

cleanup() {
  [ -n "$mission_pid" ] && kill "$mission_pid" 2>/dev/null || true
  if [ -f "$REFLOC_RUN_DIR/supervisord.pid" ]; then "$refloc" stop >/dev/null 2>&1 || true; fi
  if [ "$passed" = true ]; then rm -rf "$tmp"; else echo "kept $tmp for inspection" >&2; fi
}
trap cleanup EXIT

fail() {
  echo "FAIL: $*" >&2
  [ -f "$tmp/mission.out" ] && { echo "--- refloc-mission output:" >&2; cat "$tmp/mission.out" >&2; }
  exit 1
}
now_us() { date +%s%6N; }
# "name pid" of every program, pid empty unless RUNNING; one supervisorctl call
# (each costs a Python start-up). deploy/refloc status prints "name RUNNING pid N, uptime ...".
# Wake supervisord's main loop every 20 ms for 2 s (see above); no curl: no waking.
poke_supervisord() {
  command -v curl >/dev/null || return 0
  [ "${REFLOC_RESTART_POKE:-0}" = 1 ] || return 0
  local i
  for i in $(seq 100); do
    curl -s -o /dev/null --max-time 1 --unix-socket "$REFLOC_RUN_DIR/supervisor.sock" -H 'Content-Type: text/xml' \
      -d '<?xml version="1.0"?><methodCall><methodName>supervisor.getState</methodName></methodCall>' \
      http://localhost/RPC2 || true
    sleep 0.02
  done
}
all_pids() {
  "$refloc" status 2>/dev/null | awk '{pid = ""} $2 == "RUNNING" {pid = $4; sub(",", "", pid)} {print $1, pid}' || true
}
pid_in() { awk -v n="$1" '$1 == n {print $2}' <<<"$2"; }
program_pid() { pid_in "$1" "$(all_pids)"; }

for b in "${victims[@]}" robot_sim refloc-mission; do
  [ -x "$build/bin/$b" ] || { echo "SKIP: $build/bin/$b not built"; exit 77; }
done
command -v supervisord >/dev/null && command -v lcm-logger >/dev/null || { echo "SKIP: no supervisord/lcm-logger"; exit 77; }

"$refloc" start --sim >/dev/null || fail "deploy/refloc start"
for _ in $(seq 300); do
  missing=0
  pids="$(all_pids)"
  for p in "${programs[@]}"; do [ -n "$(pid_in "$p" "$pids")" ] || missing=1; done
  [ $missing = 0 ] && break
  sleep 0.1
done
[ $missing = 0 ] || fail "not everything RUNNING: $("$refloc" status || true)"

"$build/bin/refloc-mission" --mission "$repo/tests/ops/data/restart_kill_mission.json" --json "$tmp/mission.json" \
  --log-file "$tmp/logs/refloc.0" --trace "$tmp/path_trace.csv" >"$tmp/mission.out" 2>&1 &
mission_pid=$!
for _ in $(seq 600); do
  grep -q "^sent mission" "$tmp/mission.out" && break
  kill -0 "$mission_pid" 2>/dev/null || fail "refloc-mission ended before driving"
  sleep 0.1
done
grep -q "^sent mission" "$tmp/mission.out" || fail "the mission never started"
sleep 2   # under way

: >"$kills"
for victim in "${victims[@]}"; do
  kill -0 "$mission_pid" 2>/dev/null || fail "the mission ended before $victim was killed: kill spacing too long for it"
  before="$(all_pids)"
  old="$(pid_in "$victim" "$before")"
  [ -n "$old" ] || fail "$victim not RUNNING before its kill"
  kill -9 "$old"
  t_kill="$(now_us)"
  poke_supervisord &
  poker=$!
  new=""
  for _ in $(seq 200); do  # RUNNING again (supervisord: startsecs=1)
    new="$(program_pid "$victim")"
    [ -n "$new" ] && [ "$new" != "$old" ] && break
    new=""
    sleep 0.05
  done
  kill "$poker" 2>/dev/null || true
  wait "$poker" 2>/dev/null || true
  [ -n "$new" ] || fail "$victim was not restarted: $("$refloc" status "$victim" || true)"
  echo "$victim $old $t_kill $new" >>"$kills"
  # Recovery window, then nobody else may have died meanwhile.
  remaining_us=$(( t_kill + spacing_us - $(now_us) ))
  [ "$remaining_us" -gt 0 ] && sleep "$(printf '%d.%06d' $((remaining_us / 1000000)) $((remaining_us % 1000000)))"
  after="$(all_pids)"
  while read -r name pid; do
    [ "$name" = "$victim" ] && continue
    now_pid="$(pid_in "$name" "$after")"
    [ "$pid" = "$now_pid" ] || fail "$name changed pid ($pid -> ${now_pid:-none}) while $victim restarted"
  done <<<"$before"
  echo "killed $victim (pid $old) -> restarted as pid $new; others unchanged"
done

set +e
wait "$mission_pid"
mission_rc=$?
set -e
mission_pid=""
cat "$tmp/mission.out"
"$refloc" stop >/dev/null 2>&1 || true   # lcm-logger flushes the log
[ "$mission_rc" = 0 ] || fail "refloc-mission exited $mission_rc: not every waypoint reached within tolerance"
python3 - "$tmp/mission.json" <<'PY' || fail "mission report"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["waypoints_reached"] == r["waypoints_total"], r
assert not r["aborted"], r["abort_reason"]
assert r["max_waypoint_error_mm"] < 20.0, r["max_waypoint_error_mm"]
print(f"mission: {r['waypoints_reached']}/{r['waypoints_total']} waypoints, max true error "
      f"{r['max_waypoint_error_mm']:.1f} mm, {r['duration_s']:.1f} s, goal resends {r['goal_resends']}")
PY
# The POSE gap bound is the field's 1 s in a Release build (measured there: gaps 14-51 ms,
# respawn 32-93 ms). A sanitized build (CI's) spends 0.4-1.1 s between the kill and the new
# process's main() on a loaded 2-core host (ASan's start-up; measured in CI: respawn 417-1140 ms
# for every service alike), which is the whole gap when pose_fusion itself is killed: it crossed
# 1 s once (1024 ms, respawn 971 ms). There the bound is 1.5 s: still a restart, not a wait.
max_pose_gap=1.0
if [[ "$(ldd "$build/bin/pose_fusion" 2>/dev/null)" == *libasan* ]]; then
  max_pose_gap=1.5
  echo "sanitized build: POSE gap bound 1.5 s instead of 1 s"
fi
"$build/bin/ops_restart_log_check" --log "$tmp/logs/refloc.0" --kills "$kills" --max-pose-gap "$max_pose_gap" ||
  fail "restart checks (table above)"
passed=true
echo "PASS"
