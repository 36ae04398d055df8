#!/usr/bin/env bash
# robot_sim --sensor-bind-address: the emulated LMS100 listens where it is told
# (another computer's driver needs the LAN address), on loopback by default,
# and an address this computer does not have is a startup error naming it.
# Private netns (tests/tools/run_in_netns.sh): 127.0.0.2 is a local address there too.
#   multihost_sensor_bind_check.sh REPO_ROOT BUILD_DIR
set -euo pipefail
repo="$1"
build="$2"
[ "${REFLOC_IN_NETNS:-}" = 1 ] || { echo "run me through tests/tools/run_in_netns.sh" >&2; exit 64; }
cd "$repo"
tmp="$(mktemp -d /tmp/refloc_sensor_bind.XXXXXX)"
sim_pid=""
cleanup() {
  [ -n "$sim_pid" ] && kill "$sim_pid" 2>/dev/null && wait "$sim_pid" 2>/dev/null
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
sim=("$build/bin/robot_sim" --config deploy/config/robot_sim.json --port 0)

# start_sim LOG ARGS...: robot_sim in the background (sim_pid); endpoint = the emulator's address:port.
start_sim() {
  local log="$1"; shift
  "${sim[@]}" "$@" >"$log" 2>&1 &
  sim_pid=$!
  for _ in $(seq 200); do
    endpoint="$(sed -n 's/.*LMS100 emulator on \([0-9.]*:[0-9]*\) .*/\1/p' "$log")"
    [ -n "$endpoint" ] && return 0
    kill -0 "$sim_pid" 2>/dev/null || { cat "$log" >&2; return 1; }
    sleep 0.05
  done
  cat "$log" >&2
  return 1
}
stop_sim() { kill "$sim_pid"; wait "$sim_pid" || true; sim_pid=""; }

start_sim "$tmp/bound.log" --sensor-bind-address 127.0.0.2 || fail "robot_sim did not start"
[[ "$endpoint" == 127.0.0.2:* ]] || fail "emulator on $endpoint, expected 127.0.0.2"
listen="$(ss -ltnH "sport = :${endpoint#*:}")"
grep -q "127.0.0.2:${endpoint#*:}" <<<"$listen" || fail "ss does not show 127.0.0.2: $listen"
! grep -q "127.0.0.1:" <<<"$listen" || fail "also listening on 127.0.0.1: $listen"
stop_sim
echo "--sensor-bind-address 127.0.0.2: listening on $endpoint only"

start_sim "$tmp/default.log" || fail "robot_sim did not start without the option"
[[ "$endpoint" == 127.0.0.1:* ]] || fail "default emulator address $endpoint, expected 127.0.0.1"
stop_sim
echo "default: $endpoint"

for bad in 10.99.0.1 eth0; do
  rc=0
  timeout 20 "${sim[@]}" --sensor-bind-address "$bad" >"$tmp/bad.log" 2>&1 || rc=$?
  if [ $rc -eq 0 ] || [ $rc -eq 124 ]; then fail "robot_sim --sensor-bind-address $bad: exit $rc, expected a startup error"; fi
  grep -q "$bad" "$tmp/bad.log" || fail "the error does not name $bad: $(cat "$tmp/bad.log")"
  echo "--sensor-bind-address $bad: exit $rc, $(grep -m1 "$bad" "$tmp/bad.log")"
done
echo "PASS"
