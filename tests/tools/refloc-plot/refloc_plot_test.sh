#!/usr/bin/env bash
# tools/refloc-plot on small recorded data: a mission trace (the first two waypoints of a demo
# run, thinned; also drawn as drive traces) and a refloc-eval paper-table CSV give non-empty PNG
# and SVG pictures with the expected panels (the SVG keeps its text); bad input ends with the
# documented exit codes; and refloc-eval itself draws its picture after its CSV.
#   refloc_plot_test.sh REPO REFLOC_EVAL_BINARY
set -euo pipefail
repo="$1"
refloc_eval="$2"
plot="$repo/tools/refloc-plot/refloc-plot.py"
data="$repo/tests/tools/refloc-plot/data"
world="$repo/deploy/config/world_demo.json"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
expect_text() {  # FILE TEXT...
  local file="$1"; shift
  for text in "$@"; do grep -qF -- "$text" "$file" || fail "$file lacks '$text'"; done
}
expect_exit() {  # CODE MESSAGE-PART COMMAND...
  local code="$1" part="$2" rc=0; shift 2
  "$@" >"$tmp/out" 2>"$tmp/err" || rc=$?
  [ "$rc" -eq "$code" ] || fail "exit $rc, want $code: $* ($(cat "$tmp/err"))"
  grep -qF -- "$part" "$tmp/err" || fail "stderr lacks '$part': $(cat "$tmp/err")"
}
expect_png() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "$1 is not a PNG"; }

"$plot" mission --trace "$data/mission_trace.csv" --world "$world" --out "$tmp/path.svg" --out "$tmp/path.png" \
  --title "fixture mission" >/dev/null
expect_png "$tmp/path.png"
[ "$(stat -c %s "$tmp/path.png")" -gt 20000 ] || fail "path.png is nearly empty"
# The map panel (metres, walls, reflectors, three traces, waypoints), the zoom in mm and the
# error panel in mm with arrivals.
expect_text "$tmp/path.svg" "fixture mission" "x [m] (map frame)" "y [m]" "reflectors (24)" "walls" \
  "ground truth" "POSE (fused)" "LASER_POSE fixes" "WP0" "WP6" "zoom ±40 mm around WP0" "true arrival error 7.5 mm" \
  "position error vs ground truth [mm]" "time since the mission started [s]" "waypoint arrival (true error)" "2 m"

"$plot" eval --csv "$data/eval_paper_table.csv" --reference "$data/paper_table1_errors.csv" \
  --world "$repo/deploy/config/paper_cell.json" --out "$tmp/eval.svg" >/dev/null
expect_text "$tmp/eval.svg" "x [m] (map frame)" "reflectors (9)" "x error (estimate − truth) [mm]" "y error [mm]" \
  "paper's Table 1 (real LMS100) (30)" "default mode (30)" "pose number" "Cramér-Rao bound"

# drive: any trace with GROUND_TRUTH and LASER_POSE rows, one per motion source.
"$plot" drive --trace odometry="$data/mission_trace.csv" --trace no_compensation="$data/mission_trace.csv" \
  --world "$world" --out "$tmp/drive.svg" >/dev/null
expect_text "$tmp/drive.svg" "x [m] (map frame)" "fixes, odometry (" "fixes, no_compensation (" \
  "no_compensation: RMSE" "fix position error vs truth [mm]"

# Bad input: exit 2 naming the file, usage errors 64.
expect_exit 2 "$tmp/none.csv: cannot read" "$plot" mission --trace "$tmp/none.csv" --world "$world"
printf 'kind,t_s,x_m,y_m,theta_rad,error_mm\nGROUND_TRUTH,zero,1,2,0,\n' >"$tmp/bad.csv"
expect_exit 2 "$tmp/bad.csv: line 2: t_s = 'zero' is not a number" "$plot" mission --trace "$tmp/bad.csv" --world "$world"
printf 'kind,t_s\n' >"$tmp/columns.csv"
expect_exit 2 "columns x_m, y_m, theta_rad, error_mm missing" "$plot" mission --trace "$tmp/columns.csv" --world "$world"
expect_exit 2 "world_none.json: cannot read" "$plot" mission --trace "$data/mission_trace.csv" --world "$tmp/world_none.json"
expect_exit 64 "the extension must be .png, .svg or .pdf" "$plot" mission --trace "$data/mission_trace.csv" \
  --world "$world" --out "$tmp/x.jpg"
expect_exit 64 "'odometry': expected SOURCE=FILE" "$plot" drive --trace odometry --world "$world"
expect_exit 64 "unrecognized arguments: --bogus" "$plot" eval --csv x.csv --world "$world" --bogus

# refloc-eval draws its own picture next to its CSV.
"$refloc_eval" paper-table --repeats 1 --out-prefix "$tmp/study" --no-progress >"$tmp/eval.out" 2>&1 ||
  fail "refloc-eval: $(tail -3 "$tmp/eval.out")"
expect_png "$tmp/study.png"
expect_text "$tmp/study.svg" "refloc-eval paper-table (10 poses x 1 scans" "paper's Table 1"
expect_text "$tmp/eval.out" "wrote $tmp/study.csv" "refloc-plot: wrote $tmp/study.png"
echo "refloc-plot: mission, eval and drive pictures, 7 bad inputs, refloc-eval's picture: all as expected"
