#!/usr/bin/env bash
# docs/parameters.md must be what the readers say (regenerated, compared line by line), every key
# must have a meaning, and every service's --print-config of its shipped file must be a config
# file the service accepts again with the same effective values.
set -euo pipefail
root="$1" bin="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail=0

"$root/docs/generate-parameters.sh" "$bin" >"$work/parameters.md"
if ! diff -u "$root/docs/parameters.md" "$work/parameters.md" >"$work/diff"; then
  echo "FAIL: docs/parameters.md disagrees with the readers; regenerate it:"
  echo "  docs/generate-parameters.sh build/bin >docs/parameters.md"
  head -40 "$work/diff"
  fail=1
fi
undocumented="$(grep -E '^\| `[^`]+` \|.*\|  \|$' "$work/parameters.md" | cut -d'|' -f2 || true)"
if [ -n "$undocumented" ]; then
  echo "FAIL: keys without a meaning (give the reader call a ConfigKey {pointer, unit, meaning}):"
  echo "$undocumented" | head -40
  fail=1
fi

for s in lms100_driver reflector_extractor reflector_matcher pose_solver mecanum_odometry pose_fusion navigator \
         robot_sim lms100_emulator web_console; do
  shipped="$root/deploy/config/$s.json"
  args=(--config "$shipped")
  [ -f "$shipped" ] || args=(--config "")
  if ! (cd "$work" && "$bin/$s" "${args[@]}" --print-config >"$work/$s.jsonc" 2>"$work/$s.err"); then
    echo "FAIL: $s --print-config: $(cat "$work/$s.err")"; fail=1; continue
  fi
  # The printed file is valid input; beside a copy of the shipped files, as relative paths in it
  # (map_file, world_file) are relative to the config file.
  mkdir -p "$work/config" && cp -r "$root/deploy/config/." "$work/config/"
  cp "$work/$s.jsonc" "$work/config/$s.printed.json"
  if ! (cd "$work" && "$bin/$s" --config "$work/config/$s.printed.json" --print-config \
          >"$work/$s.again" 2>"$work/$s.err"); then
    echo "FAIL: $s does not accept its own --print-config output: $(cat "$work/$s.err")"; fail=1
  elif ! diff <(grep -v '^// ' "$work/$s.jsonc") <(grep -v '^// ' "$work/$s.again") >/dev/null; then
    echo "FAIL: $s reads different values back from its --print-config output"; fail=1
  fi
done
[ $fail -eq 0 ] && echo "docs/parameters.md matches the readers; every key documented; --print-config round-trips"
exit $fail
