#!/usr/bin/env bash
# deploy/refloc + deploy/supervisord.conf end to end, in a private netns
# (tests/tools/run_in_netns.sh): supervisord starts from the repo config with
# its own socket, lists every program, runs lcm-logger (which writes a log),
# runs a "robot_sim" (lcm_echo_peer standing in) that refloc-status sees,
# restarts it when killed, restarts it on request, shows its logs, and stops
# everything. A program that exits 2 (navigator with a broken config) stays EXITED,
# not retried, with its one-line error in `deploy/refloc status`; one that fails at
# once otherwise ("mecanum_odometry" = /bin/false) keeps being retried with a growing
# delay. lcm-logger runs under refloc-logger-watch, whose HEARTBEAT lcm_logger is OK.
#   supervisor_integration.sh REPO_ROOT BUILD_DIR
set -euo pipefail
repo="$1"
build="$2"
tmp="$(mktemp -d /tmp/refloc_supervisor_test.XXXXXX)"
export REFLOC_BUILD="$tmp/build" REFLOC_RUN_DIR="$tmp/run" REFLOC_LOG_DIR="$tmp/logs" REFLOC_CONFIG_DIR="$tmp/config"
export REFLOC_PROGRAMS="lcm-logger robot_sim"
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
mkdir -p "$REFLOC_BUILD/bin" "$REFLOC_CONFIG_DIR"
# The stand-in takes only --lcm-url: deploy/refloc exec also passes the shipped robot_sim.json
# and robot.json (files missing from REFLOC_CONFIG_DIR fall back to the shipped ones).
printf '#!/bin/sh\nexec "%s" "$1" "$2"\n' "$build/bin/lcm_echo_peer" >"$REFLOC_BUILD/bin/robot_sim"
chmod +x "$REFLOC_BUILD/bin/robot_sim"
ln -s "$build/bin/navigator" "$REFLOC_BUILD/bin/navigator"
ln -s "$build/bin/refloc-logger-watch" "$REFLOC_BUILD/bin/refloc-logger-watch"
ln -s "$(command -v false)" "$REFLOC_BUILD/bin/mecanum_odometry"
refloc="$repo/deploy/refloc"

cleanup() {
  if [ -f "$REFLOC_RUN_DIR/supervisord.pid" ]; then
    "$refloc" stop >/dev/null 2>&1 || true
  fi
  rm -rf "$tmp"
}
trap cleanup EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }
program_pid() { "$refloc" status "$1" | awk '/RUNNING/ {sub(",", "", $4); print $4}'; }
wait_running() {
  for _ in $(seq 50); do
    [ -n "$(program_pid "$1")" ] && return 0
    sleep 0.1
  done
  fail "$1 not RUNNING: $("$refloc" status "$1")"
}

help="$("$refloc" --help)"
grep -q "restart NAME" <<<"$help" || fail "--help"
"$refloc" start --sim || fail "start"
[ -S "$REFLOC_RUN_DIR/supervisor.sock" ] || fail "no socket in $REFLOC_RUN_DIR"

status="$("$refloc" status)" || true
mapfile -t listed < <("$refloc" list)
[ ${#listed[@]} -eq 10 ] || fail "deploy/services.list has ${#listed[@]} programs: ${listed[*]}"
for program in "${listed[@]}"; do
  grep -q "^$program " <<<"$status" || fail "status does not list $program: $status"
done
grep -q "^navigator .*STOPPED" <<<"$status" || fail "navigator is not in REFLOC_PROGRAMS, yet: $status"
grep -qxF "[program:navigator]" "$REFLOC_RUN_DIR/programs.conf" || fail "no programs.conf written from the list"
echo "status lists all ${#listed[@]} programs of deploy/services.list"

wait_running lcm-logger
wait_running robot_sim
"$build/bin/refloc-status" --once --wait 2.5 --expect lcm_echo_peer,lcm_logger ||
  fail "refloc-status does not see the supervised peer and the logger's heartbeat"

old_pid="$(program_pid robot_sim)"
kill -9 "$old_pid"
sleep 0.3
wait_running robot_sim
new_pid="$(program_pid robot_sim)"
[ "$new_pid" != "$old_pid" ] || fail "robot_sim was not restarted after kill -9"
echo "autorestart: robot_sim pid $old_pid -> $new_pid"

"$refloc" restart robot_sim >/dev/null || fail "restart robot_sim"
wait_running robot_sim
[ "$(program_pid robot_sim)" != "$new_pid" ] || fail "restart did not replace the process"
logs="$("$refloc" logs robot_sim)"
grep -q "started, pid" <<<"$logs" || fail "logs robot_sim"

[ -f "$REFLOC_LOG_DIR/refloc.0" ] || fail "lcm-logger wrote no $REFLOC_LOG_DIR/refloc.0"

# A configuration error is not retried: EXITED (terminal with autorestart=unexpected,
# exitcodes=2), the reason shown by status.
echo '{"not json' >"$REFLOC_CONFIG_DIR/navigator.json"
"$refloc" start --sim navigator >/dev/null || true
# (status exits 3 while a program is not RUNNING: read its output, not its code)
for _ in $(seq 50); do
  grep -q "EXITED" <<<"$("$refloc" status navigator || true)" && break
  sleep 0.1
done
status="$("$refloc" status navigator)" || true
grep -q "^navigator .*EXITED" <<<"$status" || fail "navigator with a bad config is not EXITED: $status"
grep -q "not restarted (exit 2): navigator: error: " <<<"$status" || fail "status shows no reason: $status"
sleep 3
status="$("$refloc" status navigator)" || true
grep -q "^navigator .*EXITED" <<<"$status" || fail "navigator left EXITED: $status"
starts="$(grep -c "navigator: error: " "$REFLOC_RUN_DIR/navigator.log")"
[ "$starts" = 1 ] || fail "navigator was started $starts times with a bad config"
echo "config error: EXITED after one start, status says: $(grep 'not restarted' <<<"$status")"

# Any other quick failure is retried, with a delay growing by 1 s a start.
"$refloc" start --sim mecanum_odometry >/dev/null || true
sleep 4
retries="$(grep -c "ended within 1 s of its start" "$REFLOC_RUN_DIR/mecanum_odometry.log" || true)"
[ "$retries" -ge 2 ] || fail "a quick exit 1 was retried $retries times in 4 s: $(cat "$REFLOC_RUN_DIR/mecanum_odometry.log")"
status="$("$refloc" status mecanum_odometry)" || true
grep -Eq "RUNNING|STARTING|EXITED" <<<"$status" || fail "mecanum_odometry gave up: $status"
"$refloc" stop mecanum_odometry >/dev/null || true
echo "quick exit 1: retried $retries times in 4 s, with back-off"
last_pid="$(program_pid robot_sim)"
"$refloc" stop || fail "stop"
[ ! -e "$REFLOC_RUN_DIR/supervisord.pid" ] || fail "supervisord pid file left behind"
! kill -0 "$last_pid" 2>/dev/null || fail "robot_sim still running after stop"
summary="$("$build/bin/refloc-log" "$REFLOC_LOG_DIR/refloc.0")"
grep -q "HEARTBEAT" <<<"$summary" || fail "the log has no HEARTBEAT"
echo "PASS"
