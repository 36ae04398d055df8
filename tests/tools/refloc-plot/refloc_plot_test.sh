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
# residual_correlation.py on a synthetic run: a robot driving along x at 1 m/s past 3 reflectors,
# 50 scans/s; each detection's error = the reflector's persistent offset (3 mm radial) + white
# noise (6 mm). The persistent part must come out as correlation at every lag (9/45 = 0.2), the
# white part as none: rho at one scan near 0.2 radial, near 0 tangential.
/usr/bin/python3 - "$tmp/corr.jsonl" <<'PY'
import json, math, random, sys
random.seed(3)
refl = {1: (5.0, 3.0, 0.003), 2: (10.0, -3.0, -0.003), 3: (15.0, 3.0, 0.003)}
with open(sys.argv[1], "w") as f:
    for k in range(1000):
        t = 1_000_000 + 20_000 * k
        x = 0.02 * k
        f.write(json.dumps({"channel": "GROUND_TRUTH", "msg": {"utime": t, "x": x, "y": 0.0, "theta": 0.0}}) + "\n")
        matches = []
        lx = x + 0.3
        for i, (mx, my, bias) in refl.items():
            px, py = mx - lx, my
            r = math.hypot(px, py)
            er, et = bias + random.gauss(0, 0.006), random.gauss(0, 0.006)
            dx = px + (er * px - et * py) / r
            dy = py + (er * py + et * px) / r
            matches.append({"map_id": i, "map_x": mx, "map_y": my, "detection": {"x": dx, "y": dy, "utime": t}})
        f.write(json.dumps({"channel": "REFLECTOR_MATCHES", "msg": {"utime": t, "status": 0, "matches": matches}}) + "\n")
        f.write(json.dumps({"channel": "MAP_HEALTH", "type": None}) + "\n")
PY
/usr/bin/python3 "$repo/tools/refloc-plot/residual_correlation.py" --jsonl "$tmp/corr.jsonl" \
  --robot "$repo/deploy/config/robot.json" --out "$tmp/corr.png" >"$tmp/corr.out"
expect_png "$tmp/corr.png"
/usr/bin/python3 - "$tmp/corr.out" <<'PY' || fail "residual_correlation: $(cat "$tmp/corr.out")"
import re, sys
text = open(sys.argv[1]).read()
radial, tangential = map(float, re.search(r"one scan \(0-30 ms\): radial (\S+), tangential (\S+)", text).groups())
assert 0.12 < radial < 0.28 and abs(tangential) < 0.08, (radial, tangential)
PY
expect_exit 2 "needs GROUND_TRUTH" /usr/bin/python3 "$repo/tools/refloc-plot/residual_correlation.py" \
  --jsonl /dev/null --robot "$repo/deploy/config/robot.json" --out "$tmp/x.png"

echo "refloc-plot: mission, eval and drive pictures, 7 bad inputs, refloc-eval's picture: all as expected"
