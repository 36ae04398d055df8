#!/usr/bin/env bash
# deploy/systemd: one template refloc@.service for every service in deploy/services.list,
# refloc-lcm-logger.service and refloc.target. systemd-analyze verify accepts the
# template instantiated for every listed service and the other units (with /opt/refloc
# mapped onto a temporary tree holding the real deploy/refloc and list and stand-in
# binaries); the units carry the supervision settings the deploy docs promise; and the
# command line deploy/refloc exec gives an instance comes from the list (--config,
# --robot for the programs marked robot_json).
#   systemd_units_check.sh REPO_ROOT      (exit 77 = skipped: no systemd-analyze)
set -euo pipefail
repo="$1"
command -v systemd-analyze >/dev/null || { echo "SKIP: no systemd-analyze"; exit 77; }
tmp="$(mktemp -d /tmp/refloc_systemd_test.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

units="$repo/deploy/systemd"
count="$(find "$units" -name '*.service' | wc -l)"
[ "$count" -eq 2 ] || fail "expected refloc@.service and refloc-lcm-logger.service, found $count service units: $(ls "$units")"
template="$units/refloc@.service"
for setting in "Type=notify" "NotifyAccess=main" "Restart=always" "RestartSec=0.5" "WatchdogSec=3" \
               "RestartPreventExitStatus=2" "ExecStart=/opt/refloc/deploy/refloc exec %i" \
               "Environment=REFLOC_BUILD=/opt/refloc/build" "Environment=REFLOC_CONFIG_DIR=/opt/refloc/deploy/config" \
               "Environment=LCM_DEFAULT_URL=udpm://239.255.76.67:7667?ttl=0" "WantedBy=refloc.target"; do
  grep -qxF "$setting" "$template" || fail "$template lacks '$setting'"
done
for setting in "ExecStart=/opt/refloc/deploy/refloc exec lcm-logger" "Restart=always" "WantedBy=refloc.target"; do
  grep -qxF "$setting" "$units/refloc-lcm-logger.service" || fail "refloc-lcm-logger.service lacks '$setting'"
done

# /opt/refloc stand-in: the real deploy/refloc and services.list, configs, stand-in binaries
# that print their arguments.
opt="$tmp/opt"
mkdir -p "$opt/deploy/config" "$opt/build/bin" "$tmp/units"
cp "$repo/deploy/refloc" "$repo/deploy/services.list" "$opt/deploy/"
mapfile -t services < <("$repo/deploy/refloc" list --services)
[ ${#services[@]} -ge 8 ] || fail "deploy/refloc list --services gave ${services[*]}"
for s in "${services[@]}"; do
  printf '#!/bin/sh\necho "$@"\n' >"$opt/build/bin/$s"
  chmod +x "$opt/build/bin/$s"
  echo '{}' >"$opt/deploy/config/$s.json"
done
echo '{}' >"$opt/deploy/config/robot.json"
for unit in "$units"/*.service "$units"/*.target; do
  sed "s|/opt/refloc|$opt|g" "$unit" >"$tmp/units/$(basename "$unit")"
done
instances=()
for s in "${services[@]}"; do instances+=("./refloc@$s.service"); done
output="$(cd "$tmp/units" && systemd-analyze verify --man=no "${instances[@]}" ./refloc-lcm-logger.service \
  ./refloc.target 2>&1)" || fail "verify: $output"
[ -z "$output" ] || fail "systemd-analyze verify complained: $output"

# What ExecStart runs for each instance, with the unit's environment.
robot_services=()
for s in "${services[@]}"; do
  args="$(env -i PATH="$PATH" REFLOC_BUILD="$opt/build" REFLOC_CONFIG_DIR="$opt/deploy/config" \
    LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0" "$opt/deploy/refloc" exec "$s")"
  expected="--lcm-url udpm://239.255.76.67:7667?ttl=0 --config $opt/deploy/config/$s.json"
  if awk -v n="$s" '$1 == n && $4 == "yes" {found = 1} END {exit !found}' "$repo/deploy/services.list"; then
    expected+=" --robot $opt/deploy/config/robot.json"
    robot_services+=("$s")
  fi
  [[ "$args" == "$expected"* ]] || fail "refloc@$s runs '$s $args', expected '$s $expected ...'"
done
echo "PASS: refloc@.service verifies for ${#services[@]} services (${services[*]}), with refloc-lcm-logger.service" \
  "and refloc.target; --robot passed to ${robot_services[*]}"
