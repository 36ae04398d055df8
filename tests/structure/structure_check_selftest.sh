#!/usr/bin/env bash
# structure_check.py catches what it promises: in a scratch git repo, each check
# passes on a clean tree and fails, naming the file, once the rule is broken
# (a forbidden include, a 101-line main.cpp, a 41-line function, a 301-line file
# without a reason, an unformatted file); allowed includes and a stated reason pass.
#   structure_check_selftest.sh REPO_ROOT
set -euo pipefail
repo="$1"
check="$repo/tests/structure/structure_check.py"
tmp="$(mktemp -d /tmp/refloc_structure_selftest.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$tmp"
git init -q .
cp "$repo/.clang-format" .
mkdir -p services/pose_solver services/reflector_matcher services/robot_sim services/lms100_emulator \
  services/world_renderer common
echo '#pragma once' >common/angles.hpp
echo '#pragma once' >services/world_renderer/world.hpp
echo '#pragma once' >services/lms100_emulator/lms100_device.hpp
echo '#pragma once' >services/reflector_matcher/matcher.hpp
printf '#include "common/angles.hpp"\n#include "world_renderer/world.hpp"\n#include "lms100_emulator/lms100_device.hpp"\n' \
  >services/robot_sim/sim.cpp
printf '#include "common/angles.hpp"\n\nint main() { return 0; }\n' >services/pose_solver/main.cpp
clang-format -i services/robot_sim/sim.cpp services/pose_solver/main.cpp
git add -A

expect() {  # expect RC CHECK PATTERN: run the check, want exit RC and PATTERN in the output
  local rc=0 out
  out="$("$check" "$tmp" "$2" 2>&1)" || rc=$?
  [ "$rc" = "$1" ] || fail "$2: exit $rc, expected $1: $out"
  [ -z "$3" ] || grep -qF -- "$3" <<<"$out" || fail "$2: output lacks '$3': $out"
}
for c in includes mains length format; do expect 0 "$c" ""; done
expect 0 includes "robot_sim -> lms100_emulator (1), world_renderer (1)"
expect 0 includes "pose_solver -> (none)"

echo '#include "reflector_matcher/matcher.hpp"' >>services/pose_solver/main.cpp
expect 1 includes 'FORBIDDEN: services/pose_solver/main.cpp includes "reflector_matcher/matcher.hpp"'
printf '#include "common/angles.hpp"\n\nint main() { return 0; }\n' >services/pose_solver/main.cpp

{ echo 'int run() {'; for i in $(seq 39); do echo "  int v$i = $i;"; done; echo '}'; } >services/pose_solver/main.cpp
expect 1 mains "services/pose_solver/main.cpp: run() has 41 lines (at most 40)"
{ echo 'int run() {'; for i in $(seq 38); do echo "  int v$i = $i;"; done; echo '}'; } >services/pose_solver/main.cpp
expect 0 mains "longest function run() 40 lines"
for i in $(seq 70); do echo "int f$i() { return $i; }"; done >>services/pose_solver/main.cpp
expect 1 mains "TOO LONG: services/pose_solver/main.cpp has 110 lines (at most 100)"
git rm -q -f services/pose_solver/main.cpp

for i in $(seq 301); do echo "int g$i = $i;"; done >common/big.cpp
git add common/big.cpp
expect 1 length "NO REASON: common/big.cpp has 301 lines"
{ echo "// A table, longer than 300 lines because every entry is one line."; cat common/big.cpp; } >common/big2.cpp
mv common/big2.cpp common/big.cpp
expect 0 length "common/big.cpp: 302 lines"

printf 'int  h( ) {return 1;}\n' >common/ugly.cpp
git add common/ugly.cpp
expect 1 format "NOT FORMATTED: common/ugly.cpp"
echo "PASS: includes, mains, length and format catch their offences"
