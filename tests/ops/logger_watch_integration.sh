#!/usr/bin/env bash
# lcm-logger's alarm (tools/refloc-logger-watch through `deploy/refloc exec lcm-logger`),
# in a private netns (tests/tools/run_in_netns.sh), read back with refloc-status:
#   1. a working logger on a busy bus: HEARTBEAT lcm_logger OK, the log grows;
#   2. a full disk (a 512 KiB tmpfs, filled, in a private mount namespace):
#      ERROR "disk full: 0 MB free in <dir>/";
#   3. a read-only log directory (a tmpfs remounted ro): ERROR "lcm-logger exits:
#      exit N: <lcm-logger's last line>".
#   logger_watch_integration.sh REPO_ROOT BUILD_DIR
set -euo pipefail
repo="$1"
build="$2"
[ "${REFLOC_IN_NETNS:-}" = 1 ] || { echo "run me through tests/tools/run_in_netns.sh" >&2; exit 64; }
tmp="$(mktemp -d /tmp/refloc_logger_watch_test.XXXXXX)"
export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0" REFLOC_BUILD="$build" REFLOC_RUN_DIR="$tmp/run"
pids=()
cleanup() {
  local rc=$?
  set +e
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  sleep 0.3
  for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null; done
  wait 2>/dev/null
  [ $rc -ne 0 ] && tail -n 8 "$tmp"/*.log >&2
  rm -rf "$tmp"
  exit $rc
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
mkdir -p "$tmp/run"

# Traffic for the logger: the echo peer's heartbeats, five a second.
"$build/bin/lcm_echo_peer" >"$tmp/peer.log" 2>&1 &
pids+=("$!")

logger_detail() {  # expected state -> prints lcm_logger's state_detail; fails unless state matches
  "$build/bin/refloc-status" --once --wait 2.5 --json --expect lcm_logger >"$tmp/status.json" || true
  python3 - "$tmp/status.json" "$1" <<'PY'
import json, sys
rows = [s for s in json.load(open(sys.argv[1]))["services"] if s["service"] == "lcm_logger"]
assert rows and rows[0].get("state") == sys.argv[2], rows
print(rows[0]["state_detail"])
PY
}
stop_logger() {
  kill "$1"
  for _ in $(seq 50); do kill -0 "$1" 2>/dev/null || break; sleep 0.1; done
}

# 1. working
REFLOC_LOG_DIR="$tmp/logs" "$repo/deploy/refloc" exec lcm-logger >"$tmp/ok.log" 2>&1 &
watcher=$!
pids+=("$watcher")
sleep 1.5
logger_detail OK >/dev/null || fail "working logger not OK: $(cat "$tmp/status.json")"
size1=$(stat -c %s "$tmp/logs/refloc.0")
sleep 1.5
size2=$(stat -c %s "$tmp/logs/refloc.0")
[ "$size2" -gt "$size1" ] || fail "log does not grow: $size1 -> $size2"
stop_logger "$watcher"
echo "working logger: lcm_logger OK, refloc.0 $size1 -> $size2 bytes"

# 2. full disk: a tiny tmpfs seen only by this mount namespace.
if unshare -m --propagation private true 2>/dev/null; then
  mkdir -p "$tmp/full"
  unshare -m --propagation private bash -c '
    set -e
    mount -t tmpfs -o size=512k tmpfs "$1/full"
    dd if=/dev/zero of="$1/full/filler" bs=4k 2>/dev/null || true
    REFLOC_LOG_DIR="$1/full" exec "$2/deploy/refloc" exec lcm-logger' full "$tmp" "$repo" >"$tmp/full.log" 2>&1 &
  watcher=$!
  pids+=("$watcher")
  sleep 2
  detail="$(logger_detail ERROR)" || fail "full disk: not ERROR: $(cat "$tmp/status.json")"
  [ "$detail" = "disk full: 0 MB free in $tmp/full/" ] || fail "full disk: detail '$detail'"
  stop_logger "$watcher"
  echo "full disk (512 KiB tmpfs, filled): ERROR '$detail'"
else
  echo "no mount namespace here: full-disk case skipped"
fi

# 3. a read-only log directory (EROFS stops root too): lcm-logger cannot open its log and exits.
# The 4 MB tmpfs is below the default free-space minimum: REFLOC_LOGGER_MIN_FREE_MB=1 here.
if unshare -m --propagation private true 2>/dev/null; then
  mkdir -p "$tmp/ro"
  unshare -m --propagation private bash -c '
    set -e
    mount -t tmpfs -o size=4m tmpfs "$1/ro"
    mount -o remount,ro "$1/ro"
    REFLOC_LOG_DIR="$1/ro" REFLOC_LOGGER_MIN_FREE_MB=1 exec "$2/deploy/refloc" exec lcm-logger' ro "$tmp" "$repo" >"$tmp/exits.log" 2>&1 &
  watcher=$!
  pids+=("$watcher")
  sleep 2
  detail="$(logger_detail ERROR)" || fail "logger exits: not ERROR: $(cat "$tmp/status.json")"
  [[ "$detail" == "lcm-logger exits: exit "* ]] || fail "logger exits: detail '$detail'"
  stop_logger "$watcher"
  echo "read-only log directory: ERROR '$detail'"
else
  echo "no mount namespace here: read-only case skipped"
fi
echo "PASS"
