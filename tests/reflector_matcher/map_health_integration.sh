#!/usr/bin/env bash
# Map maintenance end to end, in a private netns (tests/tools/run_in_netns.sh): robot_sim renders
# a hall whose reflectors differ from the map (data/world_map_changes.json: 13 moved by 0.1 m,
# 3 removed, 102 added), the whole stack drives the south aisle from (3, 3) to (17.5, 2)
# (data/mission_south_aisle.json, ~17 s), the matcher publishes MAP_HEALTH into the run's LCM log.
# Asserted with refloc-map update on that log:
#   the evidence reports reflector 3 missing, 13 moved and one candidate, nothing else changed;
#   the updated map (version 2, source updated) has no reflector 3, reflector 13 within 20 mm of
#   where the world has it and one new reflector within 20 mm of 102;
#   an existing --out is refused (exit 2), and so is the new map with the old evidence (another
#   version).
#   map_health_integration.sh REPO_ROOT BUILD_DIR
set -euo pipefail
repo="$1"
build="$2"
data="$repo/tests/reflector_matcher/data"
tmp="$(mktemp -d /tmp/refloc_map_health.XXXXXX)"
passed=false
cleanup() { if [ "$passed" = true ]; then rm -rf "$tmp"; else echo "kept $tmp for inspection" >&2; fi; }
trap cleanup EXIT

map="$repo/deploy/config/map_demo_v2.json"
export REFLOC_ARGS_robot_sim="--world $data/world_map_changes.json"
export REFLOC_ARGS_reflector_matcher="--map $map"
set +e
"$repo/deploy/run_mission.sh" --build-dir "$build" --mission "$data/mission_south_aisle.json" \
  --log-dir "$tmp/run" >"$tmp/mission.out" 2>&1
rc=$?
set -e
[ "$rc" = 0 ] || { cat "$tmp/mission.out"; echo "FAIL: run_mission exit $rc" >&2; exit 1; }
grep -h "map health" "$tmp/run"/*reflector_matcher* 2>/dev/null || true

map_tool="$build/bin/refloc-map"
"$map_tool" update --map "$map" --evidence "$tmp/run/refloc.0" --dry-run | tee "$tmp/dry_run.txt"
failures=()
expect_line() { grep -q "$1" "$tmp/dry_run.txt" || failures+=("dry run lacks: $1"); }
expect_line "^remove reflector 3 "
expect_line "^move reflector 13 "
[ "$(grep -c '^add reflector' "$tmp/dry_run.txt")" = 1 ] || failures+=("not exactly 1 reflector added")
[ "$(grep -c '^\(move\|remove\) reflector' "$tmp/dry_run.txt")" = 2 ] ||
  failures+=("a reflector that stands where the map says was changed")

"$map_tool" update --map "$map" --evidence "$tmp/run/refloc.0" --out "$tmp/next.json"
python3 - "$tmp/next.json" <<'PY' || failures+=("the updated map does not match the world")
import json, math, sys
m = json.load(open(sys.argv[1]))
assert m["version"] == 2 and m["source"] == "updated", (m["version"], m["source"])
by_id = {r["id"]: (r["x"], r["y"]) for r in m["reflectors"]}
assert 3 not in by_id, "reflector 3 still mapped"
assert len(by_id) == 24, len(by_id)
for what, (x, y), (px, py) in [("moved reflector 13", (19.9, 2.7), by_id[13]), ("added reflector", (15.6, 0.1), by_id[25])]:
    d = math.hypot(px - x, py - y)
    print(f"{what}: {1000 * d:.1f} mm from the world's")
    assert d < 0.02, f"{what} {d:.3f} m off"
PY
set +e
"$map_tool" update --map "$map" --evidence "$tmp/run/refloc.0" --out "$tmp/next.json" 2>/dev/null
[ $? = 2 ] || failures+=("an existing --out was not refused with exit 2")
"$map_tool" update --map "$tmp/next.json" --evidence "$tmp/run/refloc.0" --dry-run 2>"$tmp/other.err"
[ $? = 2 ] && grep -q "version 1" "$tmp/other.err" || failures+=("evidence of version 1 applied to version 2")
set -e
if [ ${#failures[@]} -gt 0 ]; then
  printf 'FAIL: %s\n' "${failures[@]}" >&2
  exit 1
fi
echo "PASS: missing, moved and candidates reported; the updated map matches the world"
passed=true
