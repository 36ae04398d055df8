#!/usr/bin/env bash
# The stack split over three "computers" (network namespaces on one bridge,
# 10.77.0.0/24), each running its part under supervisord via deploy/refloc with
# its own REFLOC_PROGRAMS and REFLOC_RUN_DIR, LCM multicast with ttl=1:
#   A 10.77.0.1  sensor side: lms100_driver (TCP to the emulator on C)
#   B 10.77.0.2  reflector_extractor reflector_matcher pose_solver web_console
#   C 10.77.0.3  robot_sim (LMS100 emulator on 10.77.0.3) mecanum_odometry
#                pose_fusion navigator lcm-logger, and refloc-mission
# Checks: ttl=0 stays on its computer and ttl=1 crosses the bridge; the emulator
# listens on C's bridge address only and A's driver is connected to it; the
# mission completes (every waypoint); refloc-status on C hears all 9 services;
# C's LCM log holds the channels published on A and on B; no sanitizer reports.
# Must run in a private netns (tests/tools/run_in_netns.sh): the bridge lives there.
#   multihost_mission.sh REPO_ROOT BUILD_DIR [MISSION_JSON]
set -euo pipefail
repo="$1"
build="$2"
mission="${3:-$repo/tests/ops/data/multihost_mission.json}"
[ "${REFLOC_IN_NETNS:-}" = 1 ] || { echo "run me through tests/tools/run_in_netns.sh" >&2; exit 64; }
for tool in ip nsenter unshare ss supervisord; do
  command -v "$tool" >/dev/null || { echo "SKIP: $tool not installed" >&2; exit 77; }
done
started_s=$(date +%s.%N)
tmp="$(mktemp -d /tmp/refloc_multihost_test.XXXXXX)"
refloc="$repo/deploy/refloc"
url1="udpm://239.255.76.67:7667?ttl=1"
url0="udpm://239.255.76.67:7667?ttl=0"
hosts=(a b c)
declare -A addr=([a]=10.77.0.1 [b]=10.77.0.2 [c]=10.77.0.3)
declare -A programs=(
  [a]="lms100_driver"
  [b]="reflector_extractor reflector_matcher pose_solver web_console"
  [c]="lcm-logger robot_sim mecanum_odometry pose_fusion navigator")
declare -A holder=()
peer_pid=""

fail() { echo "FAIL: $*" >&2; exit 1; }
seconds_since() { awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }'; }

say() { echo "== [$(seconds_since "$started_s") s] $*"; }

# host_prefix H sets prefix: run a command on host H with that computer's deploy/refloc
# environment (env and nsenter exec, so "${prefix[@]}" cmd & gives cmd's own pid).
host_prefix() {
  prefix=(env REFLOC_BUILD="$build" REFLOC_RUN_DIR="$tmp/$1/run" REFLOC_LOG_DIR="$tmp/$1/logs"
    REFLOC_PROGRAMS="${programs[$1]}" LCM_DEFAULT_URL="$url1"
    REFLOC_ARGS_lms100_driver="--host ${addr[c]}"
    REFLOC_ARGS_robot_sim="--sensor-bind-address ${addr[c]}"
    nsenter -t "${holder[$1]}" -n --)
}
on_host() {
  local prefix
  host_prefix "$1"
  shift
  "${prefix[@]}" "$@"
}
# Every process still in host H's namespace (by pid; only our private namespaces).
kill_host_processes() {
  local ns pid dir
  ns="$(readlink "/proc/${holder[$1]}/ns/net")" || return 0
  for dir in /proc/[0-9]*; do
    pid="${dir#/proc/}"
    [ "$pid" = "${holder[$1]}" ] && continue
    [ "$(readlink "/proc/$pid/ns/net" 2>/dev/null)" = "$ns" ] && kill -9 "$pid" 2>/dev/null
  done
  return 0
}

cleanup() {
  local rc=$?
  set +e
  [ -n "$peer_pid" ] && kill "$peer_pid" 2>/dev/null
  for h in "${hosts[@]}"; do
    [ -n "${holder[$h]:-}" ] || continue
    if [ -f "$tmp/$h/run/supervisord.pid" ]; then
      on_host "$h" "$refloc" stop >/dev/null 2>&1
    fi
    # Whatever did not stop (supervisord, programs): end it by pid.
    kill_host_processes "$h"
    kill "${holder[$h]}" 2>/dev/null
  done
  wait 2>/dev/null
  if [ $rc -ne 0 ]; then
    for f in "$tmp"/*/run/*.log; do
      [ -f "$f" ] || continue
      echo "---- last lines of ${f#"$tmp"/}"
      tail -n 15 "$f"
    done
  fi
  if [ -n "${REFLOC_KEEP_TMP:-}" ]; then echo "kept $tmp"; else rm -rf "$tmp"; fi
  exit $rc
}
trap cleanup EXIT

say "network: bridge br0 in the test netns, hosts a b c on 10.77.0.0/24"
ip link add br0 type bridge
# Flood multicast to every port instead of relying on IGMP snooping without a querier.
ip link set br0 type bridge mcast_snooping 0
ip link set br0 up
for h in "${hosts[@]}"; do
  mkdir -p "$tmp/$h/run" "$tmp/$h/logs"
  unshare -n sleep infinity &
  holder[$h]=$!
  for _ in $(seq 50); do
    [ "$(readlink "/proc/${holder[$h]}/ns/net")" != "$(readlink /proc/self/ns/net)" ] && break
    sleep 0.02
  done
  ip link add "veth-$h" type veth peer name "eth0-$h"
  ip link set "eth0-$h" netns "${holder[$h]}"
  ip link set "veth-$h" master br0 up
  nsenter -t "${holder[$h]}" -n -- bash -c "
    set -e
    ip link set lo up
    ip link set eth0-$h name eth0
    ip link set eth0 multicast on
    ip addr add ${addr[$h]}/24 dev eth0
    ip link set eth0 up
    ip route add 224.0.0.0/4 dev eth0"
done

say "LCM ttl: 0 stays on its computer, 1 reaches the others"
status_of() {  # host, expected service -> exit code of refloc-status
  local rc=0
  on_host "$1" "$build/bin/refloc-status" --lcm-url "$url1" --once --wait 3 --expect "$2" >/dev/null 2>&1 || rc=$?
  echo $rc
}
peer_with_ttl() {
  [ -n "$peer_pid" ] && { kill "$peer_pid"; wait "$peer_pid" 2>/dev/null || true; }
  local prefix
  host_prefix a
  "${prefix[@]}" "$build/bin/lcm_echo_peer" --lcm-url "$1" >"$tmp/a/peer.log" 2>&1 &
  peer_pid=$!
  sleep 0.5
}
peer_with_ttl "$url0"
rc_a_file="$tmp/a/status_rc"
(status_of a lcm_echo_peer >"$rc_a_file") &
rc_c0="$(status_of c lcm_echo_peer)"
wait $!
[ "$(cat "$rc_a_file")" = 0 ] || fail "ttl=0: host a does not hear its own lcm_echo_peer"
[ "$rc_c0" = 1 ] || fail "ttl=0: host c heard host a (refloc-status rc $rc_c0), expected it to stay local"
peer_with_ttl "$url1"
rc_c1="$(status_of c lcm_echo_peer)"
[ "$rc_c1" = 0 ] || fail "ttl=1: host c does not hear host a (refloc-status rc $rc_c1)"
kill "$peer_pid"; wait "$peer_pid" 2>/dev/null || true; peer_pid=""
echo "ttl=0: heard on a, not on c; ttl=1: heard on c"

say "starting the stack: a (${programs[a]}), b (${programs[b]}), c (${programs[c]})"
# Like three computers booting: all at once, in no particular order.
start_pids=()
for h in "${hosts[@]}"; do
  on_host "$h" "$refloc" start --sim >"$tmp/$h/start.out" 2>&1 &
  start_pids+=($!)
done
for i in "${!hosts[@]}"; do
  wait "${start_pids[$i]}" || fail "deploy/refloc start on host ${hosts[$i]}: $(cat "$tmp/${hosts[$i]}/start.out")"
done
for h in "${hosts[@]}"; do
  status="$(on_host "$h" "$refloc" status 2>&1)" || true
  for p in ${programs[$h]}; do
    grep -qE "^$p +(RUNNING|STARTING)" <<<"$status" || fail "host $h: $p not started: $status"
  done
  # supervisor-tick is supervisord's own wake-up helper (deploy/supervisord.conf), not a service.
  others="$(grep -E "RUNNING|STARTING" <<<"$status" | awk '$1 != "supervisor-tick" {print $1}' | sort | tr '\n' ' ')"
  [ "$others" = "$(tr ' ' '\n' <<<"${programs[$h]}" | sort | tr '\n' ' ')" ] ||
    fail "host $h runs more than REFLOC_PROGRAMS: $others"
done

say "mission $mission on host c"
mission_started_s=$(date +%s.%N)
set +e
on_host c timeout 300 "$build/bin/refloc-mission" --mission "$mission" --json "$tmp/mission.json" \
  --log-file "$tmp/c/logs/refloc.0" 2>&1 | tee "$tmp/mission.out"
mission_rc=${PIPESTATUS[0]}
set -e
mission_s="$(seconds_since "$mission_started_s")"

say "refloc-status --once on host c"
set +e
on_host c "$build/bin/refloc-status" --lcm-url "$url1" --once --wait 3 --max-age 5 | tee "$tmp/status.out"
status_rc=${PIPESTATUS[0]}
set -e

say "TCP: emulator on c listens on ${addr[c]} only, the driver on a is connected to it"
listen="$(on_host c ss -ltnH 'sport = :2111')"
grep -q "${addr[c]}:2111" <<<"$listen" || fail "robot_sim does not listen on ${addr[c]}:2111: $listen"
! grep -q "127.0.0.1:2111" <<<"$listen" || fail "robot_sim also listens on loopback: $listen"
established="$(on_host a ss -tnH state established "dst ${addr[c]}:2111")"
[ -n "$established" ] || fail "lms100_driver on host a has no TCP connection to ${addr[c]}:2111"

[ "$mission_rc" = 0 ] || fail "refloc-mission exit $mission_rc"
python3 - "$tmp/mission.json" <<'PY' || fail "mission report"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["waypoints_reached"] == r["waypoints_total"] >= 2, r
assert not r["aborted"], r["abort_reason"]
assert r["laser_pose_samples"] > 0, "no LASER_POSE from host b reached host c while driving"
print("mission: {}/{} waypoints, max true error {:.1f} mm {:.2f} deg, POSE RMSE {:.1f} mm, "
      "LASER_POSE RMSE {:.1f} mm over {} fixes, {:.1f} s".format(
          r["waypoints_reached"], r["waypoints_total"], r["max_waypoint_error_mm"],
          r["max_waypoint_heading_error_deg"], r["pose_rmse_mm"], r["laser_pose_rmse_mm"],
          r["laser_pose_samples"], r["duration_s"]))
PY
[ "$status_rc" = 0 ] || fail "refloc-status on host c misses a service (rc $status_rc)"

say "stopping"
stop_pids=()
for h in "${hosts[@]}"; do
  on_host "$h" "$refloc" stop >"$tmp/$h/stop.out" 2>&1 &
  stop_pids+=($!)
done
for i in "${!hosts[@]}"; do
  wait "${stop_pids[$i]}" || fail "deploy/refloc stop on host ${hosts[$i]}: $(cat "$tmp/${hosts[$i]}/stop.out")"
done

say "host c's LCM log"
"$build/bin/refloc-log" --json "$tmp/c/logs/refloc.0" >"$tmp/log.json" || fail "refloc-log"
python3 - "$tmp/log.json" <<'PY' || fail "channels missing from host c's log"
import json, sys
summary = json.load(open(sys.argv[1]))
c = {ch["channel"]: ch["count"] for ch in summary["channels"]}
origin = {"LMS100_SCAN": "a", "REFLECTORS": "b", "REFLECTOR_MATCHES": "b", "LASER_POSE": "b",
          "WHEEL_ENCODERS": "c", "GROUND_TRUTH": "c", "ODOMETRY": "c", "POSE": "c",
          "NAV_STATUS": "c", "CMD_VEL": "c", "NAV_GOAL": "c", "HEARTBEAT": "abc"}
missing = [ch for ch in origin if not c.get(ch)]
assert not missing, f"missing {missing}; log has {c}"
print("host c's log: " + ", ".join(f"{ch} {c[ch]} (from {origin[ch]})" for ch in origin))
PY

reports="$(grep -lE "ERROR: (Address|Leak)Sanitizer|runtime error:" "$tmp"/*/run/*.log 2>/dev/null || true)"
if [ -n "$reports" ]; then
  for f in $reports; do echo "---- ${f#"$tmp"/}"; grep -A20 -E "ERROR: (Address|Leak)Sanitizer|runtime error:" "$f" | head -40; done
  fail "sanitizer reports in program logs"
fi
echo "mission wall time ${mission_s} s, test wall time $(seconds_since "$started_s") s"
echo "PASS"
