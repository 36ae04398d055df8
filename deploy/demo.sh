#!/usr/bin/env bash
# Set up and run the main job: install dependencies if missing, build what the demo runs,
# and run the full refloc stack against the built-in simulator in a private network
# namespace (deploy/run_mission.sh, which starts it with deploy/refloc start --sim).
#   deploy/demo.sh [run_mission options]      (BUILD_DIR defaults to build-demo)
# Builds Release without tests and benchmarks (deploy/test.sh builds those), and of the
# rest only the services in deploy/services.list and the tools the run calls.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
for arg in "$@"; do
  case "$arg" in
    -h|--help)
      sed -n '2,7p' "$0"
      echo
      echo "run_mission options:"
      deploy/run_mission.sh --help
      exit 0 ;;
  esac
done
deploy/install-deps.sh
build_dir="${BUILD_DIR:-build-demo}"
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DREFLOC_BUILD_TESTS=OFF \
  -DREFLOC_BUILD_BENCHMARKS=OFF >/dev/null
mapfile -t targets < <(deploy/refloc list --services)
# run_mission.sh calls refloc-mission and refloc-status; lcm-logger runs under refloc-logger-watch.
targets+=(refloc-mission refloc-status refloc-logger-watch)
cmake --build "$build_dir" -j "$(nproc)" --target "${targets[@]}"
exec tests/tools/run_in_netns.sh deploy/run_mission.sh --build-dir "$build_dir" "$@"
