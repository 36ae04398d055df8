#!/usr/bin/env bash
# deploy/lcm-spy.sh starts lcm-spy with the refloc types jar on its class path:
# lcm-spy reports all 17 types before it opens its window (which fails
# headless, as expected here).
#   lcm_spy_launcher_check.sh REPO_ROOT BUILD_DIR
set -euo pipefail
repo="$1"
export REFLOC_BUILD="$2"
output="$(DISPLAY='' timeout 60 "$repo/deploy/lcm-spy.sh" --lcm-url memq:// 2>&1 || true)"
if ! grep -q "Found 17 LCM types" <<<"$output"; then
  echo "FAIL: lcm-spy did not find the 15 refloc types:" >&2
  echo "$output" >&2
  exit 1
fi
help="$("$repo/deploy/lcm-spy.sh" --help)"
grep -q "refloc_lcmtypes.jar" <<<"$help" || { echo "FAIL: --help" >&2; exit 1; }
echo "PASS: lcm-spy found 17 LCM types"
