#!/usr/bin/env bash
# One instance of a service per host and LCM bus (common/instance_lock), with real
# reflector_matcher processes in a private netns (tests/tools/run_in_netns.sh):
# a second one exits 2 at once with one line naming the running pid; a third with a
# different service name or another bus starts; after kill -9 of the first a new
# one starts (the kernel released the lock: no stale lock file).
#   instance_lock_integration.sh REPO_ROOT BUILD_DIR
set -euo pipefail
repo="$1"
build="$2"
[ "${REFLOC_IN_NETNS:-}" = 1 ] || { echo "run me through tests/tools/run_in_netns.sh" >&2; exit 64; }
tmp="$(mktemp -d /tmp/refloc_instance_lock_test.XXXXXX)"
url="udpm://239.255.76.67:7667?ttl=0"
pids=()
cleanup() {
  local rc=$?
  for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
  if [ $rc -ne 0 ]; then tail -n 5 "$tmp"/*.log >&2 || true; fi
  rm -rf "$tmp"
  exit $rc
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$repo"
matcher() {  # log file, extra args... (execs: run it with & or in ( ), so $! is the matcher's pid)
  local log="$1"; shift
  exec "$build/bin/reflector_matcher" --lcm-url "$url" --config deploy/config/reflector_matcher.json \
    --robot deploy/config/robot.json "$@" >"$log" 2>&1
}
wait_started() {  # log file
  for _ in $(seq 100); do
    grep -q "started, pid" "$1" && return 0
    sleep 0.1
  done
  fail "no 'started' in $1: $(cat "$1")"
}

matcher "$tmp/first.log" &
first=$!
pids+=("$first")
wait_started "$tmp/first.log"

rc=0
start_s=$(date +%s%N)
(matcher "$tmp/second.log") || rc=$?
elapsed_ms=$((($(date +%s%N) - start_s) / 1000000))
[ "$rc" = 2 ] || fail "second reflector_matcher exited $rc, expected 2"
# Info lines of what main did before the runtime (map loaded) may precede it; one error line.
[ "$(grep -c 'error' "$tmp/second.log")" = 1 ] || fail "expected one error line, got: $(cat "$tmp/second.log")"
# The last line, compared in the shell: `tail | grep -q PATTERN FILE` read the file, not the pipe,
# and under pipefail tail's SIGPIPE (grep -q exits early) failed the check on a loaded host.
last_line="$(tail -n 1 "$tmp/second.log")"
[[ "$last_line" == *"reflector_matcher: error: another reflector_matcher is already running on this host and LCM bus udpm://239.255.76.67:7667: pid $first;"* ]] ||
  fail "message does not name pid $first: $(cat "$tmp/second.log")"
echo "second instance refused in $elapsed_ms ms: $(cat "$tmp/second.log")"

# ttl does not make another bus; another group does.
rc=0
"$build/bin/reflector_matcher" --lcm-url "udpm://239.255.76.67:7667?ttl=1" --config deploy/config/reflector_matcher.json \
  --robot deploy/config/robot.json >"$tmp/ttl1.log" 2>&1 || rc=$?
[ "$rc" = 2 ] || fail "ttl=1 on the same group exited $rc, expected 2"
url_other="udpm://239.255.76.68:7668?ttl=0"
"$build/bin/reflector_matcher" --lcm-url "$url_other" --config deploy/config/reflector_matcher.json \
  --robot deploy/config/robot.json >"$tmp/other_bus.log" 2>&1 &
pids+=("$!")
wait_started "$tmp/other_bus.log"
echo "same service on another LCM group starts"

kill -9 "$first"
wait "$first" 2>/dev/null || true
matcher "$tmp/third.log" &
third=$!
pids+=("$third")
wait_started "$tmp/third.log"
kill -0 "$third" || fail "the new reflector_matcher died"
echo "after kill -9 of pid $first, pid $third started"
kill -TERM "$third"
rc=0
wait "$third" || rc=$?
[ "$rc" = 0 ] || fail "SIGTERM stop exited $rc"
echo "PASS"
