#!/usr/bin/env bash
# The console page in headless Chromium against the whole simulated stack (deploy/refloc start
# --sim under supervisord, in a private netns: tests/tools/run_in_netns.sh), web_console with
# control on and a token. browser_check.py does the page's part; this script starts and stops the
# stack and hands the stack's own LCM log (lcm-logger under supervisord) to the verification.
#   web_console_browser.sh REPO_ROOT BUILD_DIR ARTIFACT_DIR
# Leaves ARTIFACT_DIR/web_console_browser.png (the screenshot) and .txt (what the page showed).
# Exit 77 (skip) without chromium, chromium-driver or python3-selenium.
set -euo pipefail
repo="$1"
build="$2"
artifacts="$3"
mkdir -p "$artifacts"
tmp="$(mktemp -d /tmp/refloc_browser_test.XXXXXX)"
export REFLOC_BUILD="$build" REFLOC_RUN_DIR="$tmp/run" REFLOC_LOG_DIR="$tmp/logs"
# Only web_console.json differs from the shipped config (deploy/refloc falls back per file).
export REFLOC_CONFIG_DIR="$tmp/config"
mkdir -p "$REFLOC_CONFIG_DIR"
token="browser-test-token"
jq --arg map "$repo/deploy/config/map_demo.json" --arg token "$token" \
  '.map_file = $map | .control.enabled = true | .control.token = $token' \
  <(grep -v '^ *//' "$repo/deploy/config/web_console.json") >"$REFLOC_CONFIG_DIR/web_console.json"
export REFLOC_ARGS_lms100_driver="--host 127.0.0.1"
unset REFLOC_PROGRAMS
refloc="$repo/deploy/refloc"
passed=false
cleanup() {
  if [ -f "$REFLOC_RUN_DIR/supervisord.pid" ]; then "$refloc" stop >/dev/null 2>&1 || true; fi
  if [ "$passed" = true ]; then rm -rf "$tmp"; else echo "kept $tmp for inspection" >&2; fi
}
trap cleanup EXIT

set +e
/usr/bin/python3 -c "import selenium" 2>/dev/null && command -v chromium >/dev/null && command -v chromedriver >/dev/null
have_browser=$?
set -e
if [ $have_browser -ne 0 ]; then
  echo "SKIP: needs chromium, chromium-driver and python3-selenium (deploy/install-deps.sh)" >&2
  exit 77
fi

"$refloc" start --sim >/dev/null
# The page's 2 s are counted from its load: the stack is localized first (an OK POSE).
for _ in $(seq 300); do
  "$refloc" status 2>/dev/null | grep -q "web_console .*RUNNING" && break
  sleep 0.1
done
for _ in $(seq 30); do
  "$build/bin/refloc-status" --once --wait 1 2>/dev/null | grep -q "^POSE OK" && break
done

set +e
/usr/bin/python3 "$repo/tests/web_console/browser_check.py" page --url http://127.0.0.1:8080/ \
  --map "$repo/deploy/config/map_demo.json" --token "$token" \
  --screenshot "$artifacts/web_console_browser.png" --out "$tmp/clicks.json" | tee "$artifacts/web_console_browser.txt"
page_rc=${PIPESTATUS[0]}
set -e
[ "$page_rc" -eq 77 ] && exit 77
sleep 1.5  # the HEARTBEAT after the refusal (every 0.5 s) and the NAV_GOAL reach the logger
"$refloc" stop >/dev/null
"$build/bin/refloc-log" "$tmp/logs/refloc.0" -c NAV_GOAL -c INITIAL_POSE -c HEARTBEAT --jsonl "$tmp/log.jsonl" >/dev/null
/usr/bin/python3 "$repo/tests/web_console/browser_check.py" verify --clicks "$tmp/clicks.json" \
  --log-jsonl "$tmp/log.jsonl" | tee -a "$artifacts/web_console_browser.txt"
verify_rc=${PIPESTATUS[0]}
[ "$page_rc" -eq 0 ] && [ "$verify_rc" -eq 0 ] || exit 1
passed=true
echo "PASS"
