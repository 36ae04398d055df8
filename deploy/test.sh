#!/usr/bin/env bash
# Set up and run every test: install Debian dependencies if missing, check that
# every C++ file is clang-formatted (the repo's .clang-format), build with warnings
# as errors and AddressSanitizer/UBSan, run ctest.
#   deploy/test.sh [extra ctest args]      (BUILD_DIR defaults to build-test)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
deploy/install-deps.sh
# Formatting first: a minute's build is not spent on a tree CI rejects anyway
# (the same check runs as ctest structure_format).
tests/structure/structure_check.py . format
build_dir="${BUILD_DIR:-build-test}"
jobs="${JOBS:-$(nproc)}"
# Benchmarks are not run by ctest and their numbers mean nothing under sanitizers:
# deploy/demo.sh builds them (Release) instead, which keeps CI within its time.
# -g1 (line tables, no variable info): sanitizer reports still name file:line, and the
# compile is a third faster than with -g on CI's 2 cores.
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DREFLOC_WERROR=ON \
  -DREFLOC_SANITIZE=ON -DREFLOC_BUILD_BENCHMARKS=OFF
cmake --build "$build_dir" -j "$jobs"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
cd "$build_dir"
# A CI log shown cut keeps its tail: after a failure the failed tests' FAIL lines come last.
rc=0
ctest --output-on-failure -j "$jobs" --timeout 600 "$@" || rc=$?
[ "$rc" = 0 ] || /usr/bin/python3 "$root/tests/tools/failed_test_summary.py" . || true
exit "$rc"
