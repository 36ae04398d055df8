#!/bin/bash
# Every program refloc ships answers --version and --help with exit 0 and a bad option with 64
# (usage error, README "Exit codes"), without starting. Arguments: the programs' paths.
set -uo pipefail
[ $# -gt 0 ] || { echo "usage: $0 PROGRAM..." >&2; exit 64; }
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
for program in "$@"; do
  name=$(basename "$program")
  out=$(timeout 10 "$program" --version 2>&1); rc=$?
  [ $rc -eq 0 ] || fail "$name --version: exit $rc, expected 0: $out"
  [[ "$out" == "$name from refloc "* ]] || fail "$name --version printed '$out', expected '$name from refloc VERSION ...'"
  out=$(timeout 10 "$program" --help 2>&1); rc=$?
  [ $rc -eq 0 ] || fail "$name --help: exit $rc, expected 0"
  out=$(timeout 10 "$program" --no-such-option 2>&1); rc=$?
  [ $rc -eq 64 ] || fail "$name --no-such-option: exit $rc, expected 64: $out"
  echo "$name: --version, --help 0; bad option 64"
done
[ $failures -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
echo "PASS: $# programs"
