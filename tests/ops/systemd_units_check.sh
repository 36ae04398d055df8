#!/usr/bin/env bash
# deploy/systemd units: systemd-analyze verify accepts every unit (with
# /opt/refloc mapped onto a temporary tree of stand-in executables), and each
# service unit has the supervision settings the deploy docs promise.
#   systemd_units_check.sh REPO_ROOT      (exit 77 = skipped: no systemd-analyze)
set -euo pipefail
repo="$1"
command -v systemd-analyze >/dev/null || { echo "SKIP: no systemd-analyze"; exit 77; }
tmp="$(mktemp -d /tmp/refloc_systemd_test.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

services=(lms100_driver reflector_extractor reflector_matcher pose_solver mecanum_odometry pose_fusion navigator robot_sim)
mkdir -p "$tmp/opt/build/bin" "$tmp/units"
for s in "${services[@]}"; do
  unit="$repo/deploy/systemd/refloc-$s.service"
  [ -f "$unit" ] || fail "missing $unit"
  for setting in "Type=notify" "Restart=always" "RestartSec=0.5" "WatchdogSec=3" \
                 "ExecStart=/opt/refloc/build/bin/$s --config /opt/refloc/deploy/config/$s.json" \
                 "Environment=LCM_DEFAULT_URL=udpm://239.255.76.67:7667?ttl=0"; do
    grep -qxF "$setting" "$unit" || fail "$unit lacks '$setting'"
  done
  printf '#!/bin/sh\n' >"$tmp/opt/build/bin/$s"
  chmod +x "$tmp/opt/build/bin/$s"
done
for unit in "$repo"/deploy/systemd/*.service "$repo"/deploy/systemd/*.target; do
  sed "s|/opt/refloc|$tmp/opt|g" "$unit" >"$tmp/units/$(basename "$unit")"
done
count="$(find "$tmp/units" -name '*.service' | wc -l)"
[ "$count" -eq 9 ] || fail "expected 9 service units, found $count"
output="$(cd "$tmp/units" && systemd-analyze verify --man=no ./*.service ./*.target 2>&1)" || fail "verify: $output"
[ -z "$output" ] || fail "systemd-analyze verify complained: $output"
echo "PASS: $count service units and refloc.target verify"
