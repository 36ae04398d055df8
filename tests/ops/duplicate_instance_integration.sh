#!/usr/bin/env bash
# Two processes of one service on one LCM bus, on two "computers" (network namespaces
# on a bridge, ttl=1), where the per-host instance lock cannot see the other: both
# services' heartbeats turn ERROR "two instances: pid A, pid B" (ServiceRuntime hears
# its name from another pid), refloc-status shows one ERROR row per process and exits
# 1; after one is killed, the other is OK again and refloc-status exits 0.
# Must run in a private netns (tests/tools/run_in_netns.sh): the bridge lives there.
#   duplicate_instance_integration.sh REPO_ROOT BUILD_DIR
set -euo pipefail
build="$2"
[ "${REFLOC_IN_NETNS:-}" = 1 ] || { echo "run me through tests/tools/run_in_netns.sh" >&2; exit 64; }
for tool in ip nsenter unshare; do
  command -v "$tool" >/dev/null || { echo "SKIP: $tool not installed" >&2; exit 77; }
done
tmp="$(mktemp -d /tmp/refloc_duplicate_test.XXXXXX)"
url="udpm://239.255.76.67:7667?ttl=1"
declare -A holder=() peer=() addr=([a]=10.78.0.1 [b]=10.78.0.2)
cleanup() {
  local rc=$?
  set +e
  for h in a b; do
    [ -n "${peer[$h]:-}" ] && kill -9 "${peer[$h]}" 2>/dev/null
    [ -n "${holder[$h]:-}" ] && kill "${holder[$h]}" 2>/dev/null
  done
  wait 2>/dev/null
  [ $rc -ne 0 ] && tail -n 5 "$tmp"/*.log >&2
  rm -rf "$tmp"
  exit $rc
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

ip link add br0 type bridge
ip link set br0 type bridge mcast_snooping 0
ip link set br0 up
for h in a b; do
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
on_host() { local h="$1"; shift; nsenter -t "${holder[$h]}" -n -- "$@"; }

for h in a b; do
  # nsenter execs the program: $! is the service's own pid (a function would add a subshell).
  nsenter -t "${holder[$h]}" -n -- "$build/bin/lcm_echo_peer" --lcm-url "$url" >"$tmp/peer_$h.log" 2>&1 &
  peer[$h]=$!
done

rc=0
on_host a "$build/bin/refloc-status" --lcm-url "$url" --once --wait 4 --json --expect lcm_echo_peer \
  >"$tmp/status.json" || rc=$?
[ "$rc" = 1 ] || fail "refloc-status exit $rc with two instances, expected 1: $(cat "$tmp/status.json")"
python3 - "$tmp/status.json" "${peer[a]}" "${peer[b]}" <<'PY' || fail "refloc-status JSON: $(cat "$tmp/status.json")"
import json, sys
doc = json.load(open(sys.argv[1]))
pids = sorted(int(p) for p in sys.argv[2:])
rows = [s for s in doc["services"] if s["service"] == "lcm_echo_peer"]
assert not doc["ok"], doc["ok"]
assert sorted(r["pid"] for r in rows) == pids, rows
for r in rows:
    assert r["duplicate"] and r["state"] == "ERROR", r
    assert "two instances: pid" in r["state_detail"], r["state_detail"]
    assert all(str(p) in r["state_detail"] for p in pids), r["state_detail"]
    assert r["counters"].get("other_instance_heartbeats", 0) > 0, r["counters"]
print("refloc-status: two ERROR rows,", rows[0]["state_detail"])
PY
for h in a b; do
  grep -q "two instances: pid .* of lcm_echo_peer on this LCM bus" "$tmp/peer_$h.log" ||
    fail "lcm_echo_peer on $h logged no duplicate"
done
echo "both services logged: $(grep -m1 "two instances" "$tmp/peer_a.log" | sed 's/.*error: //')"

kill -9 "${peer[b]}"
wait "${peer[b]}" 2>/dev/null || true
peer[b]=""
for _ in $(seq 20); do
  grep -q "no other instance of lcm_echo_peer heard any more" "$tmp/peer_a.log" && break
  sleep 0.5
done
grep -q "no other instance of lcm_echo_peer heard any more" "$tmp/peer_a.log" || fail "survivor still sees a duplicate"
on_host a "$build/bin/refloc-status" --lcm-url "$url" --once --wait 2 --json --expect lcm_echo_peer \
  >"$tmp/status_after.json" || fail "refloc-status exit $? after the second was killed: $(cat "$tmp/status_after.json")"
grep -q '"state":"OK"' "$tmp/status_after.json" || fail "survivor not OK: $(cat "$tmp/status_after.json")"
echo "after kill -9 of one: the other is OK, refloc-status exits 0"
echo "PASS"
