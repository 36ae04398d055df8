#!/usr/bin/env bash
# deploy/systemd: one template refloc@.service for every service in deploy/services.list,
# refloc-lcm-logger.service and refloc.target. systemd-analyze verify accepts the
# template instantiated for every listed service and the other units (with /opt/refloc
# mapped onto a temporary tree holding the real deploy/refloc and list and stand-in
# binaries); the units carry the supervision settings the deploy docs promise; and the
# command line deploy/refloc exec gives an instance comes from the list (--config,
# --robot for the programs marked robot_json), each file from the per-computer
# REFLOC_CONFIG_DIR (/etc/refloc) when there, else the shipped one; the tree has the
# install layout (<prefix>/bin). The unit's robot profile refuses robot_sim with exit 2
# (not restarted); REFLOC_PROFILE=sim runs it and points the driver at 127.0.0.1.
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
               "Environment=REFLOC_CONFIG_DIR=/etc/refloc" "Environment=REFLOC_PROFILE=robot" \
               "Environment=LCM_DEFAULT_URL=udpm://239.255.76.67:7667?ttl=0" "WantedBy=refloc.target"; do
  grep -qxF "$setting" "$template" || fail "$template lacks '$setting'"
done
for setting in "ExecStart=/opt/refloc/deploy/refloc exec lcm-logger" "Restart=always" "WantedBy=refloc.target"; do
  grep -qxF "$setting" "$units/refloc-lcm-logger.service" || fail "refloc-lcm-logger.service lacks '$setting'"
done

# /opt/refloc stand-in: the real deploy/refloc and services.list, configs, stand-in binaries
# that print their arguments.
opt="$tmp/opt"
etc="$tmp/etc-refloc"
mkdir -p "$opt/deploy/config" "$opt/bin" "$tmp/units" "$etc"
cp "$repo/deploy/refloc" "$repo/deploy/services.list" "$opt/deploy/"
mapfile -t services < <("$repo/deploy/refloc" list --services)
[ ${#services[@]} -ge 8 ] || fail "deploy/refloc list --services gave ${services[*]}"
for s in "${services[@]}"; do
  printf '#!/bin/sh\necho "$@"\n' >"$opt/bin/$s"
  chmod +x "$opt/bin/$s"
  echo '{}' >"$opt/deploy/config/$s.json"
done
echo '{}' >"$opt/deploy/config/robot.json"
# This computer overrides the driver's config and robot.json, nothing else.
echo '{}' >"$etc/lms100_driver.json"
echo '{}' >"$etc/robot.json"
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
unit_env() {
  env -i PATH="$PATH" HOME="$tmp" REFLOC_CONFIG_DIR="$etc" REFLOC_PROFILE="$1" \
    LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0" "$opt/deploy/refloc" exec "$2"
}
for s in "${services[@]}"; do
  profile=robot
  if awk -v n="$s" '$1 == n && $3 == "yes" {found = 1} END {exit !found}' "$repo/deploy/services.list"; then
    rc=0
    out="$(unit_env robot "$s" 2>&1)" || rc=$?
    [ "$rc" = 2 ] || fail "refloc@$s (simulation-only) in the robot profile exited $rc, not 2: $out"
    grep -q "simulation-only" <<<"$out" || fail "refloc@$s in the robot profile says: $out"
    profile=sim
  fi
  args="$(unit_env "$profile" "$s")"
  config_dir="$opt/deploy/config"
  [ -f "$etc/$s.json" ] && config_dir="$etc"
  expected="--lcm-url udpm://239.255.76.67:7667?ttl=0 --config $config_dir/$s.json"
  if awk -v n="$s" '$1 == n && $4 == "yes" {found = 1} END {exit !found}' "$repo/deploy/services.list"; then
    expected+=" --robot $etc/robot.json"
    robot_services+=("$s")
  fi
  [[ "$args" == "$expected"* ]] || fail "refloc@$s runs '$s $args', expected '$s $expected ...'"
done
[[ "$(unit_env robot lms100_driver)" != *--host* ]] || fail "the robot profile passes the driver a --host"
[[ "$(unit_env sim lms100_driver)" == *"--host 127.0.0.1" ]] || fail "the sim profile's driver does not dial 127.0.0.1"
echo "PASS: refloc@.service verifies for ${#services[@]} services (${services[*]}), with refloc-lcm-logger.service" \
  "and refloc.target; --robot passed to ${robot_services[*]}"
