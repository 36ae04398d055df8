#!/usr/bin/env bash
# Stall test (issue 11), in a private netns (tests/tools/run_in_netns.sh): robot_sim
# (LMS100 emulator at 50 Hz), the driver, extractor, matcher, solver, odometry and
# fusion under supervisord (deploy/refloc), recorded by lcm-logger. Each of extractor,
# matcher, solver and fusion in turn is stopped with SIGSTOP for 0.6 s (a busy host
# does this), then SIGCONT, 2 s apart. udpm delivers the whole bus to every process, so
# the paused process's kernel socket buffer must hold all of it meanwhile.
#   stall_test.sh REPO_ROOT BUILD_DIR default|tiny
# default: the default LCM URL (recv_buf_size from common/lcm_url.hpp). Pass: 0 scans
#   lost at every stage (LMS100_SCAN scan_counter, REFLECTORS, REFLECTOR_MATCHES and
#   LASER_POSE by scan utime; every ODOMETRY answered by a POSE), no socket on the LCM
#   port dropped a datagram, RcvbufErrors unchanged (refloc-status --json "udp"). The
#   consumers' gap counters (HEARTBEAT) are printed: they also count the source's gaps
#   (scan_counter gaps of a driver reconnecting on an overloaded host), so not judged here.
# tiny: the stack's URL asks for recv_buf_size=65536 (lcm-logger keeps the default
#   buffer so the log is complete). Pass: scans ARE lost, and the loss is visible:
#   RcvbufErrors grew, refloc-status names every paused service among the sockets that
#   dropped, and gap counters the consumers report in HEARTBEAT are > 0.
# Prints the counts per pause and the kernel counters before/after.
set -euo pipefail
repo="$1"
build="$2"
mode="${3:-default}"
[[ "$mode" =~ ^(default|tiny)$ ]] || { echo "usage: $0 REPO BUILD default|tiny" >&2; exit 64; }
tmp="$(mktemp -d /tmp/refloc_stall_test.XXXXXX)"
export REFLOC_BUILD="$build" REFLOC_RUN_DIR="$tmp/run" REFLOC_LOG_DIR="$tmp/logs" REFLOC_LOG_SPLIT_MB=2000
export REFLOC_CONFIG_DIR="$repo/deploy/config" REFLOC_ARGS_lms100_driver="--host 127.0.0.1"
export REFLOC_PROGRAMS="lcm-logger robot_sim lms100_driver mecanum_odometry reflector_extractor reflector_matcher pose_solver pose_fusion"
big_url="udpm://239.255.76.67:7667?ttl=0"  # our programs add the default recv_buf_size
unset LCM_DEFAULT_URL                       # default: deploy/refloc's, the code default
if [ "$mode" = tiny ]; then
  export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=65536"
  # lcm-logger takes the last --lcm-url; deploy/refloc exec puts these arguments after its own.
  export REFLOC_ARGS_lcm_logger="--lcm-url=udpm://239.255.76.67:7667?ttl=0&recv_buf_size=2097152"
fi
refloc="$repo/deploy/refloc"
victims=(reflector_extractor reflector_matcher pose_solver pose_fusion)
pause_s=0.6
passed=false

cleanup() {
  if [ -f "$REFLOC_RUN_DIR/supervisord.pid" ]; then "$refloc" stop >/dev/null 2>&1 || true; fi
  if [ "$passed" = true ]; then rm -rf "$tmp"; else echo "kept $tmp for inspection" >&2; fi
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

for b in robot_sim lms100_driver mecanum_odometry "${victims[@]}" refloc-status refloc-log; do
  [ -x "$build/bin/$b" ] || { echo "SKIP: $build/bin/$b not built"; exit 77; }
done
command -v supervisord >/dev/null && command -v lcm-logger >/dev/null || { echo "SKIP: no supervisord/lcm-logger"; exit 77; }

status_json() {  # refloc-status's view, udp counters included, over the big-buffer URL
  "$build/bin/refloc-status" --lcm-url "$big_url" --once --wait 2 --json \
    --expect "lms100_driver,mecanum_odometry,$(IFS=,; echo "${victims[*]}"),robot_sim" 2>/dev/null || true
}
# Unread bytes (skb truesize) in the LCM-port (7667 = 0x1DF3) sockets a pid holds: /proc/net/udp rx_queue.
socket_queue_bytes() {
  local inodes="" fd target sum=0 sl local_address rem st queues inode rest
  for fd in /proc/"$1"/fd/*; do
    target="$(readlink "$fd" 2>/dev/null)" || continue
    [[ "$target" =~ ^socket:\[([0-9]+)\]$ ]] && inodes+=" ${BASH_REMATCH[1]} "
  done
  while read -r sl local_address rem st queues _ _ _ _ inode rest; do
    [[ "$local_address" == *:1DF3 && "$inodes" == *" $inode "* ]] || continue
    sum=$((sum + 16#${queues#*:}))
  done < <(tail -n +2 /proc/net/udp)
  echo "$sum"
}
# deploy/refloc status prints "name RUNNING pid N, uptime ..."
program_pid() { "$refloc" status "$1" 2>/dev/null | awk '$2 == "RUNNING" {p = $4; sub(",", "", p); print p}'; }

"$refloc" start --sim >/dev/null || fail "deploy/refloc start"
# Warm: every service beats, the solver has published LASER_POSE and fusion POSE.
warm=false
for _ in $(seq 30); do
  s="$(status_json)"
  if jq -e '[.services[] | select((.service == "pose_solver" or .service == "pose_fusion")
            and .present and .messages_out > 0)] | length == 2' >/dev/null 2>&1 <<<"$s"; then
    warm=true
    break
  fi
done
[ "$warm" = true ] || fail "the stack did not come up: $("$refloc" status || true)"
sleep 2  # past the matcher's cold start
before="$(status_json)"
jq -c '.udp | {rcvbuf_errors, in_errors, lcm_sockets: (.sockets | length)}' <<<"$before" |
  sed 's/^/kernel UDP before: /'

: >"$tmp/pauses.txt"
for v in "${victims[@]}"; do
  pid="$(program_pid "$v")"
  [ -n "$pid" ] || fail "$v not RUNNING"
  t0="$(date +%s%6N)"
  kill -STOP "$pid"
  sleep "$pause_s"
  queued="$(socket_queue_bytes "$pid")"
  kill -CONT "$pid"
  t1="$(date +%s%6N)"
  echo "$v $pid $t0 $t1" >>"$tmp/pauses.txt"
  echo "paused $v (pid $pid) for $(( (t1 - t0) / 1000 )) ms: its LCM socket held $queued bytes of kernel memory" \
    "at the end ($(awk -v q="$queued" -v t=$(( t1 - t0 )) 'BEGIN { printf "%.2f", q / t }') MB/s of bus)"
  sleep 2
done
after="$(status_json)"
jq -c '.udp | {rcvbuf_errors, in_errors, dropping}' <<<"$after" | sed 's/^/kernel UDP after:  /'
"$refloc" stop >/dev/null 2>&1 || true  # lcm-logger flushes the log
log="$REFLOC_LOG_DIR/refloc.0"
[ -s "$log" ] || fail "no LCM log"
"$build/bin/refloc-log" "$log" --scans --json >"$tmp/scans.json" 2>/dev/null || true
"$build/bin/refloc-log" "$log" -c LMS100_SCAN -c REFLECTORS -c REFLECTOR_MATCHES -c LASER_POSE -c ODOMETRY -c POSE \
  -c HEARTBEAT --jsonl "$tmp/chain.jsonl" >/dev/null 2>&1 || fail "refloc-log --jsonl"
printf '%s\n' "$before" >"$tmp/before.json"
printf '%s\n' "$after" >"$tmp/after.json"

python3 "$repo/tests/ops/stall_check.py" "$mode" "$tmp" "${victims[@]}" || fail "stall checks (above)"
passed=true
echo "PASS ($mode)"
