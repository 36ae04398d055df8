#!/usr/bin/env bash
# deploy/refloc + deploy/supervisord.conf end to end, in a private netns
# (tests/tools/run_in_netns.sh): supervisord starts from the repo config with
# its own socket, lists every program, runs lcm-logger (which writes a log),
# runs a "robot_sim" (lcm_echo_peer standing in) that refloc-status sees,
# restarts it when killed, restarts it on request, shows its logs, and stops
# everything.
#   supervisor_integration.sh REPO_ROOT BUILD_DIR
set -euo pipefail
repo="$1"
build="$2"
tmp="$(mktemp -d /tmp/refloc_supervisor_test.XXXXXX)"
export REFLOC_BUILD="$tmp/build" REFLOC_RUN_DIR="$tmp/run" REFLOC_LOG_DIR="$tmp/logs" REFLOC_CONFIG_DIR="$tmp/config"
export REFLOC_PROGRAMS="lcm-logger robot_sim"
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
mkdir -p "$REFLOC_BUILD/bin" "$REFLOC_CONFIG_DIR"
ln -s "$build/bin/lcm_echo_peer" "$REFLOC_BUILD/bin/robot_sim"
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
"$refloc" start || fail "start"
[ -S "$REFLOC_RUN_DIR/supervisor.sock" ] || fail "no socket in $REFLOC_RUN_DIR"

status="$("$refloc" status)" || true
mapfile -t listed < <("$refloc" list)
[ ${#listed[@]} -eq 9 ] || fail "deploy/services.list has ${#listed[@]} programs: ${listed[*]}"
for program in "${listed[@]}"; do
  grep -q "^$program " <<<"$status" || fail "status does not list $program: $status"
done
grep -q "^navigator .*STOPPED" <<<"$status" || fail "navigator is not in REFLOC_PROGRAMS, yet: $status"
grep -qxF "[program:navigator]" "$REFLOC_RUN_DIR/programs.conf" || fail "no programs.conf written from the list"
echo "status lists all ${#listed[@]} programs of deploy/services.list"

wait_running lcm-logger
wait_running robot_sim
"$build/bin/refloc-status" --once --wait 1.5 --expect lcm_echo_peer || fail "refloc-status does not see the supervised peer"

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
last_pid="$(program_pid robot_sim)"
"$refloc" stop || fail "stop"
[ ! -e "$REFLOC_RUN_DIR/supervisord.pid" ] || fail "supervisord pid file left behind"
! kill -0 "$last_pid" 2>/dev/null || fail "robot_sim still running after stop"
summary="$("$build/bin/refloc-log" "$REFLOC_LOG_DIR/refloc.0")"
grep -q "HEARTBEAT" <<<"$summary" || fail "the log has no HEARTBEAT"
echo "PASS"
