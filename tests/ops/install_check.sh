#!/usr/bin/env bash
# Install and package (issue 13), one install for every check:
#   cmake --install BUILD_DIR --prefix <tmp>/opt/refloc; every installed binary answers
#   --version; from another working directory, <prefix>/deploy/refloc start (robot profile)
#   runs no robot_sim and refuses it by name; <prefix>/deploy/run_mission.sh (start --sim)
#   drives a 2-waypoint mission from the install, localizing; cpack -G DEB builds a .deb
#   whose file list holds the binaries, configs and units, and whose Depends names liblcm1.
# Must run in a private netns (tests/tools/run_in_netns.sh).
#   install_check.sh REPO_ROOT BUILD_DIR
set -euo pipefail
repo="$1"
build="$2"
[ "${REFLOC_IN_NETNS:-}" = 1 ] || { echo "run me through tests/tools/run_in_netns.sh" >&2; exit 64; }
tmp="$(mktemp -d /tmp/refloc_install_test.XXXXXX)"
prefix="$tmp/opt/refloc"
fail() { echo "FAIL: $*" >&2; exit 1; }
cleanup() {
  [ -S "$tmp/run/supervisor.sock" ] && REFLOC_RUN_DIR="$tmp/run" "$prefix/deploy/refloc" stop >/dev/null 2>&1
  rm -rf "$tmp"
}
trap cleanup EXIT

cmake --install "$build" --prefix "$prefix" >"$tmp/install.log" || fail "cmake --install: $(tail -5 "$tmp/install.log")"
for f in deploy/refloc deploy/services.list deploy/supervisord.conf deploy/config/robot.json \
         deploy/config/map_demo.json deploy/systemd/refloc@.service bin/pose_solver bin/refloc-status \
         bin/web_console services/web_console/www/index.html; do
  [ -e "$prefix/$f" ] || fail "the install has no $f"
done
! ls "$prefix/bin" | grep -Eq '_test|_tests$|_integration|_bench|^bench_' ||
  fail "tests or benchmarks installed: $(ls "$prefix/bin" | grep -E '_test|_integration|_bench|^bench_' | tr '\n' ' ')"

# --version of every installed binary.
elsewhere="$tmp/elsewhere"
mkdir -p "$elsewhere"
cd "$elsewhere"
count=0
for binary in "$prefix"/bin/*; do
  out="$("$binary" --version 2>&1)" || fail "$(basename "$binary") --version exited $?: $out"
  grep -q "refloc [0-9]" <<<"$out" || fail "$(basename "$binary") --version says '$out'"
  count=$((count + 1))
done
echo "--version: $count installed binaries, e.g. $("$prefix/bin/pose_solver" --version)"

# The robot profile from the install: no robot_sim, ever; the driver needs no sensor to run.
export REFLOC_RUN_DIR="$tmp/run" REFLOC_LOG_DIR="$tmp/logs" LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
"$prefix/deploy/refloc" start >"$tmp/start.out" 2>&1 || fail "start (robot profile): $(cat "$tmp/start.out")"
sleep 1
status="$("$prefix/deploy/refloc" status)" || true
! grep -q "^robot_sim" <<<"$status" || fail "robot_sim is in the robot profile: $status"
! pgrep -f "$prefix/bin/robot_sim" >/dev/null || fail "a robot_sim process runs in the robot profile"
grep -q "^lms100_driver .*RUNNING" <<<"$status" || fail "lms100_driver not RUNNING: $status"
grep -q "^pose_solver .*RUNNING" <<<"$status" || fail "pose_solver not RUNNING: $status"
rc=0
"$prefix/deploy/refloc" start robot_sim 2>"$tmp/refused" || rc=$?
[ "$rc" = 64 ] || fail "start robot_sim in the robot profile exited $rc, not 64"
rc=0
"$prefix/deploy/refloc" start --sim 2>>"$tmp/refused" || rc=$?
[ "$rc" = 64 ] || fail "start --sim beside a running robot profile exited $rc, not 64"
echo "robot profile: $(grep -c RUNNING <<<"$status") programs RUNNING, no robot_sim; refused: $(head -1 "$tmp/refused")"
"$prefix/deploy/refloc" stop >/dev/null || fail "stop"

# --sim from the install, another working directory: a 2-waypoint mission.
unset REFLOC_RUN_DIR REFLOC_LOG_DIR
"$prefix/deploy/run_mission.sh" --mission "$repo/tests/ops/data/multihost_mission.json" \
  --log-dir "$tmp/mission" --json mission.json >"$tmp/mission.out" 2>&1 ||
  fail "run_mission.sh from the install: $(tail -20 "$tmp/mission.out")"
[ -f "$elsewhere/mission.json" ] || fail "no mission.json in the caller's working directory"
grep -q "waypoints reached: 2/2" "$tmp/mission.out" || fail "the mission did not reach 2/2: $(tail -20 "$tmp/mission.out")"
if [ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  [ -s "$tmp/mission/path.png" ] || fail "no path.png from the install's refloc-plot: $(grep -i plot "$tmp/mission.out")"
fi
echo "mission from the install: $(grep -m1 "waypoints reached" "$tmp/mission.out"), picture $(ls "$tmp/mission/path.png" 2>/dev/null || echo none)"

# The Debian package.
command -v dpkg-deb >/dev/null || { echo "SKIP: no dpkg-deb" >&2; exit 77; }
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$tmp/pkg" >"$tmp/cpack.log" 2>&1 ||
  fail "cpack: $(tail -5 "$tmp/cpack.log")"
deb="$(ls "$tmp"/pkg/*.deb)"
contents="$(dpkg-deb -c "$deb")"
for f in bin/lms100_driver bin/pose_solver bin/robot_sim bin/refloc-status deploy/refloc \
         deploy/config/lms100_driver.json deploy/config/robot.json deploy/systemd/refloc@.service \
         deploy/systemd/refloc-lcm-logger.service deploy/systemd/refloc.target; do
  grep -q "\./opt/refloc/$f\$" <<<"$contents" || fail "$(basename "$deb") lacks /opt/refloc/$f"
done
depends="$(dpkg-deb -f "$deb" Depends)"
grep -q "liblcm1" <<<"$depends" && grep -q supervisor <<<"$depends" || fail "Depends: $depends"
echo "deb: $(basename "$deb"), $(wc -l <<<"$contents") entries, Depends: $depends"
echo PASS
