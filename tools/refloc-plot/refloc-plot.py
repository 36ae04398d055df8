#!/usr/bin/python3
"""refloc-plot: pictures of refloc runs with matplotlib (Debian's python3-matplotlib).

  refloc-plot.py mission --trace RUN.trace.csv --world WORLD.json [--out F.png] [--out F.svg]
      the path of a mission over the map (walls, racks, reflectors) with the true path, the fused
      POSE and the LASER_POSE fixes, a zoom around one waypoint in mm, and the position error of
      POSE and LASER_POSE against the truth over time in mm with the waypoint arrivals marked
  refloc-plot.py eval --csv STUDY.csv --world WORLD.json [--reference R.csv] [--out F.png]
      refloc-eval's paper-table / random study: where the poses were, the error scatter (x, y)
      per mode in mm, and the error per pose against the Cramér-Rao bound
  refloc-plot.py drive --trace SOURCE=F.trace.csv [--trace ...] --world WORLD.json [--out F.png]
      refloc-eval drive: the true loop and each motion source's fixes over the map, and each
      source's fix error over time in mm (dots, and a 1 s running mean)
  refloc-plot.py plan --grid OUT/grid.json [--out F.png] [--out F.svg]
      refloc-plan's grid: reflectors seen, class (blind / fragile / ambiguous, with arrows to the
      confusable pose), CRLB position and heading sigma, and before / after the suggestions

The format follows each --out's extension (.png, .svg, .pdf). Exit codes: 0 written,
64 usage error, 2 missing or bad input file, 1 anything else."""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from refloc_plot_data import DataError, load_eval_csv, load_reference_csv, load_trace, load_world  # noqa: E402

EXIT_USAGE, EXIT_DATA, EXIT_FAILURE = 64, 2, 1


class Parser(argparse.ArgumentParser):
    def error(self, message):
        self.print_usage(sys.stderr)
        print(f"{self.prog}: {message}", file=sys.stderr)
        sys.exit(EXIT_USAGE)


def load_inputs(args):
    """Every input file, read before matplotlib loads: a bad file fails fast."""
    if args.command == "plan":
        from refloc_plot_plan import load_plan
        return {"plan": load_plan(args.grid)}
    world = load_world(args.world, args.map)
    if args.command == "mission":
        return {"trace": load_trace(args.trace), "world": world}
    if args.command == "drive":
        return {"traces": [(name, load_trace(path)) for name, path in args.trace], "world": world}
    return {"rows": load_eval_csv(args.csv), "world": world,
            "reference": load_reference_csv(args.reference) if args.reference else []}


def plot_mission(args, inputs, plt):
    from refloc_plot_draw import (LASER_COLOUR, POSE_COLOUR, TRUTH_COLOUR, WAYPOINT_COLOUR, add_scale_bar, draw_map,
                                  draw_waypoints, error_panel_limit, legible_fix_markers, rmse, set_map_axes)
    trace, world = inputs["trace"], inputs["world"]
    truth, pose, laser, wps = (trace[k] for k in ("GROUND_TRUTH", "POSE", "LASER_POSE", "WAYPOINT"))
    fig = plt.figure(figsize=(14, 11), layout="constrained")
    grid = fig.add_gridspec(2, 2, width_ratios=[2.7, 1], height_ratios=[1.75, 1])
    ax_map, ax_zoom, ax_err = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1]), fig.add_subplot(grid[1, :])
    fig.suptitle(args.title or f"refloc mission: {os.path.basename(args.trace)}", fontsize=13)

    def traces(ax, to_x, to_y, fix_size):
        # Fixes first and faint, the truth thick and half transparent over them, POSE thin on top.
        ax.scatter(to_x(laser["x_m"]), to_y(laser["y_m"]), s=fix_size, color=LASER_COLOUR, alpha=0.45, lw=0,
                   zorder=3, label=f"LASER_POSE fixes ({len(laser['t_s'])})")
        ax.plot(to_x(truth["x_m"]), to_y(truth["y_m"]), color=TRUTH_COLOUR, lw=2.6, alpha=0.35, zorder=4,
                label="ground truth")
        ax.plot(to_x(pose["x_m"]), to_y(pose["y_m"]), color=POSE_COLOUR, lw=0.9, zorder=5, label="POSE (fused)")

    draw_map(ax_map, world)
    same = lambda values: values  # noqa: E731
    traces(ax_map, same, same, 2.0)
    draw_waypoints(ax_map, wps, arrow_m=0.6)
    ax_map.plot(truth["x_m"][:1], truth["y_m"][:1], marker="o", ms=7, color=TRUTH_COLOUR, zorder=6, ls="none",
                label="start")
    xs = [p[0] for w in world["walls"] for p in w] + truth["x_m"]
    ys = [p[1] for w in world["walls"] for p in w] + truth["y_m"]
    set_map_axes(ax_map, xs, ys, margin_m=0.4)
    add_scale_bar(ax_map, max(xs) - min(xs))
    legible_fix_markers(ax_map.legend(loc="upper left", bbox_to_anchor=(0.0, -0.09), ncol=4, fontsize=8,
                                      frameon=False))
    ax_map.set_title("path over the map; the zoom (right) shows the millimetres", fontsize=10)

    k = min(max(args.zoom_waypoint, 0), len(wps["x_m"]) - 1) if wps["x_m"] else -1
    if k >= 0:
        cx, cy, half_mm = wps["x_m"][k], wps["y_m"][k], args.zoom_mm
        traces(ax_zoom, lambda v: [(x - cx) * 1000 for x in v], lambda v: [(y - cy) * 1000 for y in v], 14.0)
        ax_zoom.plot([0], [0], marker="x", color=WAYPOINT_COLOUR, ms=12, mew=2, zorder=6, ls="none", label="target")
        if not math.isnan(wps["t_s"][k]):
            # The truth when the navigator called it reached: what the arrival error measures.
            i = min(range(len(truth["t_s"])), key=lambda j: abs(truth["t_s"][j] - wps["t_s"][k]))
            ax_zoom.plot([(truth["x_m"][i] - cx) * 1000], [(truth["y_m"][i] - cy) * 1000], marker="D", ms=7,
                         color=WAYPOINT_COLOUR, mfc="none", mew=1.6, zorder=6, ls="none",
                         label="truth when reported reached")
        legible_fix_markers(ax_zoom.legend(loc="upper right", fontsize=7, framealpha=0.9))
        ax_zoom.set_xlim(-half_mm, half_mm)
        ax_zoom.set_ylim(-half_mm, half_mm)
        ax_zoom.set_aspect("equal", adjustable="box")
        ax_zoom.grid(True, lw=0.4, color="#cccccc")
        ax_zoom.set_xlabel(f"x − {cx:g} m [mm]")
        ax_zoom.set_ylabel(f"y − {cy:g} m [mm]")
        arrival = "" if math.isnan(wps["error_mm"][k]) else f", true arrival error {wps['error_mm'][k]:.1f} mm"
        ax_zoom.set_title(f"zoom ±{half_mm:g} mm around WP{k}\n{arrival.lstrip(', ')}", fontsize=10)
        add_scale_bar(ax_zoom, 2 * half_mm, metres_per_unit=0.001)
    else:
        ax_zoom.axis("off")

    pose_rmse, laser_rmse = rmse(pose["error_mm"]), rmse(laser["error_mm"])
    ax_err.scatter(laser["t_s"], laser["error_mm"], s=5, color=LASER_COLOUR, alpha=0.5, lw=0, zorder=3,
                   label=f"LASER_POSE fixes, RMSE {laser_rmse:.1f} mm")
    ax_err.plot(pose["t_s"], pose["error_mm"], color=POSE_COLOUR, lw=0.9, zorder=4,
                label=f"POSE (fused), RMSE {pose_rmse:.1f} mm")
    arrivals = [(i, t, e) for i, (t, e) in enumerate(zip(wps["t_s"], wps["error_mm"])) if not math.isnan(t)]
    top = error_panel_limit([pose["error_mm"], laser["error_mm"]], [e for _, _, e in arrivals if not math.isnan(e)])
    for n, (i, t, e) in enumerate(arrivals):
        ax_err.axvline(t, color=WAYPOINT_COLOUR, lw=0.9, ls="--", zorder=2,
                       label="waypoint arrival (true error)" if n == 0 else None)
        ax_err.plot([t], [e], marker="D", color=WAYPOINT_COLOUR, ms=5, zorder=5)
        ax_err.annotate(f"WP{i}\n{e:.1f} mm", (t, top), xytext=(3, -3), textcoords="offset points", va="top",
                        fontsize=8, color=WAYPOINT_COLOUR)
    clipped = sum(1 for s in (pose["error_mm"], laser["error_mm"]) for v in s if v > top)
    ax_err.set_ylim(0, top)
    ax_err.set_xlim(0, 1.04 * max(truth["t_s"]))
    ax_err.set_xlabel("time since the mission started [s]")
    ax_err.set_ylabel("position error vs ground truth [mm]")
    ax_err.grid(True, lw=0.4, color="#cccccc")
    legible_fix_markers(ax_err.legend(loc="upper left", bbox_to_anchor=(0.0, 0.86), fontsize=8, framealpha=0.9))
    hidden = f" ({clipped} point{'s' if clipped > 1 else ''} above {top:.0f} mm not shown)" if clipped else ""
    ax_err.set_title("position error over time" + hidden, fontsize=10)
    return fig


def source_and_file(text):
    name, sep, path = text.partition("=")
    if not sep or not name or not path:
        raise argparse.ArgumentTypeError(f"'{text}': expected SOURCE=FILE")
    return name, path


def main(argv):
    parser = Parser(prog="refloc-plot", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True, parser_class=Parser)
    mission = sub.add_parser("mission", help="a mission's path and errors (refloc-mission --trace CSV)")
    mission.add_argument("--trace", required=True, help="refloc-mission's trace CSV")
    mission.add_argument("--zoom-waypoint", type=int, default=0,
                         help="waypoint the zoom is centred on (0-based, as refloc-mission counts them)")
    mission.add_argument("--zoom-mm", type=float, default=40.0, help="half width of the zoom [mm]")
    evaluation = sub.add_parser("eval", help="refloc-eval paper-table / random (its CSV)")
    evaluation.add_argument("--csv", required=True, help="refloc-eval's measurement CSV")
    evaluation.add_argument("--reference", help="CSV of published errors (err_x_mm, err_y_mm) to show")
    evaluation.add_argument("--reference-label", default="paper's Table 1 (real LMS100)")
    drive = sub.add_parser("drive", help="refloc-eval drive: fixes per motion source (its trace CSVs)")
    drive.add_argument("--trace", type=source_and_file, action="append", required=True,
                       help="SOURCE=FILE: a motion source's trace (repeatable)")
    plan = sub.add_parser("plan", help="refloc-plan's grid.json: heat maps per quantity")
    plan.add_argument("--grid", required=True, help="refloc-plan's grid.json (it holds the map and walls)")
    for p in (mission, evaluation, drive):
        p.add_argument("--world", required=True, help="the world file the run used (walls; its map_file)")
        p.add_argument("--map", help="reflector map (default: the world's map_file)")
    for p in (mission, evaluation, drive, plan):
        p.add_argument("--out", action="append", help="picture file, format by extension (repeatable; "
                       "default: the input with .png)")
        p.add_argument("--title", help="title above the picture")
    args = parser.parse_args(argv)
    if args.command == "mission" and args.zoom_mm <= 0:
        parser.error(f"--zoom-mm must be above 0, got {args.zoom_mm}")
    first_input = {"mission": lambda: args.trace, "eval": lambda: args.csv, "drive": lambda: args.trace[0][1],
                   "plan": lambda: args.grid}
    outputs = args.out or [os.path.splitext(first_input[args.command]())[0] + ".png"]
    for out in outputs:
        if os.path.splitext(out)[1].lower() not in (".png", ".svg", ".pdf"):
            parser.error(f"--out {out}: the extension must be .png, .svg or .pdf")
    try:
        inputs = load_inputs(args)
    except DataError as e:
        print(f"refloc-plot: {e}", file=sys.stderr)
        return EXIT_DATA
    try:
        import matplotlib
    except ImportError:
        print("refloc-plot: matplotlib missing: apt-get install python3-matplotlib (deploy/install-deps.sh)",
              file=sys.stderr)
        return EXIT_FAILURE
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.fonttype"] = "none"  # SVG text stays text (searchable, smaller)
    import matplotlib.pyplot as plt
    from refloc_plot_studies import plot_drive, plot_eval
    plots = {"mission": plot_mission, "eval": plot_eval, "drive": plot_drive}
    if args.command == "plan":
        from refloc_plot_plan import plot_plan  # only refloc-plan's pictures need it
        plots["plan"] = plot_plan
    fig = plots[args.command](args, inputs, plt)
    for out in outputs:
        try:
            fig.savefig(out, dpi=110)
        except OSError as e:
            print(f"refloc-plot: {out}: cannot write ({e.strerror})", file=sys.stderr)
            return EXIT_FAILURE
        print(f"refloc-plot: wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
