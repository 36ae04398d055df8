#!/usr/bin/env bash
# CI version of the load test: deploy/load_test.sh for a short run on this
# build (sanitizer builds included). Asserts that no scan was dropped and that
# the report lists every service with CPU, RSS and HEARTBEAT numbers; the
# latency is printed, not judged (ASan and a loaded CI machine say nothing
# about the 5 ms budget; the full 10-minute Release run does).
#   load_test_check.sh SOURCE_DIR BINARY_DIR [DURATION_S]
set -euo pipefail
source_dir="$1"
binary_dir="$2"
duration="${3:-20}"
run_dir="$binary_dir/tests/ops/load_test_run"
rm -rf "$run_dir"
json="$run_dir/report.json"
mkdir -p "$run_dir"

set +e
"$source_dir/deploy/load_test.sh" --duration "$duration" --build-dir "$binary_dir" --run-dir "$run_dir" \
  --json "$json" --max-p99-ms 0 --warmup-timeout 30
rc=$?
set -e
fail() { echo "load_test_check: FAIL: $*" >&2; exit 1; }
[ -f "$json" ] || fail "no report (load_test.sh exit $rc)"

jq -e '.scans.published > 0' "$json" >/dev/null || fail "no scan in the log"
jq -e '.scans.dropped == 0 and .scans.missing_counters == 0' "$json" >/dev/null ||
  fail "dropped scans: $(jq -c '{dropped: .scans.dropped, missing: .scans.missing_counters, gaps: .scans.gaps, stages: .scans.stages}' "$json")"
# 50 Hz over the run, give or take the logger's start and stop.
jq -e --argjson d "$duration" '.scans.published >= 50 * $d * 0.95' "$json" >/dev/null ||
  fail "only $(jq .scans.published "$json") scans in ${duration} s"
for s in $("$source_dir/deploy/refloc" list --services); do
  jq -e --arg s "$s" '[.services[] | select(.service == $s and .cpu_percent > 0 and .rss_peak_mb > 0
                        and .heartbeat_p99_us != null and .decode_errors == 0)] | length == 1' "$json" >/dev/null ||
    fail "service $s missing or incomplete in the report: $(jq -c --arg s "$s" '.services[] | select(.service == $s)' "$json")"
done
jq -e '[.services[] | select(.service == "lcm-logger" and .rss_peak_mb > 0)] | length == 1' "$json" >/dev/null ||
  fail "lcm-logger missing from the report"
echo "load_test_check: latency (not judged here): $(jq -c .latency_ms "$json")"
echo "load_test_check: load_test.sh exit $rc, checks $(jq -c .checks "$json")"
[ "$rc" -eq 0 ] || fail "load_test.sh exit $rc"
echo "load_test_check: PASS"
