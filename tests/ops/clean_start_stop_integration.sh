#!/usr/bin/env bash
# Honest start and stop (common/service_runtime), real processes in a private netns
# (tests/tools/run_in_netns.sh):
#   - robot_sim whose world file does not load, or whose emulator port is taken (after
#     the runtime is up), exits non-zero and never logs "started" (it used to);
#   - a runtime-based service stopped by SIGINT and by SIGTERM exits 0, its last
#     HEARTBEAT is STOPPING, and it counts no lcm_handle_errors (the interrupted wait
#     is not an LCM error).
#   clean_start_stop_integration.sh REPO_ROOT BUILD_DIR
set -euo pipefail
repo="$1"
build="$2"
[ "${REFLOC_IN_NETNS:-}" = 1 ] || { echo "run me through tests/tools/run_in_netns.sh" >&2; exit 64; }
tmp="$(mktemp -d /tmp/refloc_start_stop_test.XXXXXX)"
url="udpm://239.255.76.67:7667?ttl=0"
cleanup() {
  local rc=$?
  [ $rc -ne 0 ] && tail -n 5 "$tmp"/*.log >&2
  rm -rf "$tmp"
  exit $rc
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$repo"

rc=0
"$build/bin/robot_sim" --lcm-url "$url" --robot deploy/config/robot.json --world "$tmp/no_such_world.json" \
  >"$tmp/robot_sim.log" 2>&1 || rc=$?
[ "$rc" = 2 ] || fail "robot_sim with a missing world exited $rc, expected 2"
! grep -q "started" "$tmp/robot_sim.log" || fail "robot_sim logged 'started' before its world failed"
echo "robot_sim, missing world: exit 2, no 'started': $(tail -n 1 "$tmp/robot_sim.log")"

# The runtime (LCM) is up before robot_sim opens its emulator's port: a taken port must not
# leave a "started" behind either.
# The holder says when it listens: a fixed sleep lost the race on a loaded host (robot_sim took
# the port first, ran, and the test timed out).
python3 -c "import socket, sys, time; s = socket.socket(); s.bind(('127.0.0.1', 2112)); s.listen(); open(sys.argv[1], 'w').close(); time.sleep(30)" "$tmp/holder_ready" &
holder=$!
for _ in $(seq 100); do [ -e "$tmp/holder_ready" ] && break; sleep 0.1; done
[ -e "$tmp/holder_ready" ] || fail "the port holder did not listen on 127.0.0.1:2112 within 10 s"
rc=0
"$build/bin/robot_sim" --lcm-url "$url" --robot deploy/config/robot.json --config deploy/config/robot_sim.json \
  --port 2112 >"$tmp/robot_sim_port.log" 2>&1 || rc=$?
kill "$holder"
[ "$rc" != 0 ] || fail "robot_sim on a taken port exited 0"
! grep -q "started" "$tmp/robot_sim_port.log" || fail "robot_sim logged 'started' before its emulator failed"
echo "robot_sim, emulator port taken: exit $rc, no 'started': $(tail -n 1 "$tmp/robot_sim_port.log")"

for signal in INT TERM; do
  "$build/bin/lcm_echo_peer" --lcm-url "$url" >"$tmp/peer_$signal.log" 2>&1 &
  peer=$!
  "$build/bin/refloc-status" --lcm-url "$url" --once --wait 4 --json --max-age 10 --expect lcm_echo_peer \
    >"$tmp/status_$signal.json" &
  status_pid=$!
  sleep 2
  grep -q "started, pid $peer" "$tmp/peer_$signal.log" || fail "no 'started, pid $peer' once running"
  kill "-$signal" "$peer"
  rc=0
  wait "$peer" || rc=$?
  [ "$rc" = 0 ] || fail "SIG$signal stop exited $rc"
  wait "$status_pid" || true
  python3 - "$tmp/status_$signal.json" <<'PY' || fail "SIG$signal: last heartbeat: $(cat "$tmp/status_$signal.json")"
import json, sys
row = [s for s in json.load(open(sys.argv[1]))["services"] if s["service"] == "lcm_echo_peer"][0]
assert row["state"] == "STOPPING", row["state"]
assert "lcm_handle_errors" not in row["counters"], row["counters"]
PY
  echo "SIG$signal: exit 0, last heartbeat STOPPING, no lcm_handle_errors"
done
echo "PASS"
