#!/usr/bin/env bash
# Set up and run the main job: install dependencies if missing, build, and run
# the full refloc stack against the built-in simulator in a private network
# namespace. See README.md.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
deploy/install-deps.sh
build_dir="${BUILD_DIR:-build}"
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
exec tests/tools/run_in_netns.sh deploy/run_mission.sh --build-dir "$build_dir" "$@"
