#!/usr/bin/python3
"""refloc-plot: pictures of refloc runs with matplotlib (Debian's python3-matplotlib).

  refloc-plot.py mission --trace RUN.trace.csv --world WORLD.json [--out F.png] [--out F.svg]
      the path of a mission over the map (walls, racks, reflectors) with the true path, the fused
      POSE and the LASER_POSE fixes, a zoom around one waypoint in mm, and the position error of
      POSE and LASER_POSE against the truth over time in mm with the waypoint arrivals marked
  refloc-plot.py eval --csv STUDY.csv --world WORLD.json [--reference R.csv] [--out F.png]
      refloc-eval's paper-table / random study: where the poses were, the error scatter (x, y)
      per mode in mm, and the error per pose against the Cramér-Rao bound

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


def error_panel_limit(series_mm, marks_mm):
    """Top of the error axis: the 99.5th percentile with headroom, so that a few start-up
    outliers do not squash the millimetres; clipped points are counted in the title."""
    from refloc_plot_draw import percentile
    top = max([percentile(s, 0.995) for s in series_mm] + marks_mm + [1.0])
    return 1.25 * top if not math.isnan(top) else 10.0


def legible_fix_markers(legend):
    """Scatter entries drawn at one readable size in the legend (the plot's fixes are tiny)."""
    handles = getattr(legend, "legend_handles", None) or getattr(legend, "legendHandles", [])
    for handle in handles:
        if hasattr(handle, "set_sizes"):
            handle.set_sizes([25.0])
            handle.set_alpha(0.9)


def load_inputs(args):
    """Every input file, read before matplotlib loads: a bad file fails fast."""
    world = load_world(args.world, args.map)
    if args.command == "mission":
        return {"trace": load_trace(args.trace), "world": world}
    return {"rows": load_eval_csv(args.csv), "world": world,
            "reference": load_reference_csv(args.reference) if args.reference else []}


def plot_mission(args, inputs, plt):
    from refloc_plot_draw import (LASER_COLOUR, POSE_COLOUR, TRUTH_COLOUR, WAYPOINT_COLOUR, add_scale_bar, draw_map,
                                  draw_waypoints, rmse, set_map_axes)
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


def plot_eval(args, inputs, plt):
    from matplotlib.ticker import MaxNLocator
    from refloc_plot_draw import POSE_COLOUR, LASER_COLOUR, add_scale_bar, draw_map, percentile, rmse, set_map_axes
    rows, world, reference = inputs["rows"], inputs["world"], inputs["reference"]
    colours = {"default": POSE_COLOUR, "paper": LASER_COLOUR}
    good = {m: [r for r in rows if r["mode"] == m and r["published_ok"] == 1 and r["wrong"] == 0] for m in colours}
    fig = plt.figure(figsize=(13, 10), layout="constrained")
    grid = fig.add_gridspec(2, 2, width_ratios=[1.2, 1], height_ratios=[1.5, 1])
    ax_map, ax_xy, ax_pose = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1]), fig.add_subplot(grid[1, :])
    fig.suptitle(args.title or f"refloc-eval: {os.path.basename(args.csv)}", fontsize=13)

    draw_map(ax_map, world)
    per_pose = {}
    for r in good["default"]:
        per_pose.setdefault(int(r["pose_index"]), (r["true_x_m"], r["true_y_m"], []))[2].append(
            math.hypot(r["err_x_mm"], r["err_y_mm"]))
    if per_pose:
        px, py, pe = zip(*[(x, y, rmse(e)) for x, y, e in per_pose.values()])
        points = ax_map.scatter(px, py, c=pe, s=22, cmap="viridis", zorder=4, label="poses (colour: default-mode RMSE)")
        # Beside the drawn map, not the space an equal-aspect map leaves free.
        colour_axis = ax_map.inset_axes([1.02, 0.05, 0.025, 0.9])
        fig.colorbar(points, cax=colour_axis, label="default mode position RMSE at the pose [mm]")
    for mode, marker in (("paper", "x"), ("default", "+")):
        wrong = [r for r in rows if r["mode"] == mode and r["wrong"] == 1]
        if wrong:
            ax_map.scatter([r["true_x_m"] for r in wrong], [r["true_y_m"] for r in wrong], marker=marker, color="red",
                           s=34, lw=1.4, zorder=5, label=f"wrong pose published by {mode} mode ({len(wrong)})")
    xs = [p[0] for w in world["walls"] for p in w] + [r["true_x_m"] for r in rows]
    ys = [p[1] for w in world["walls"] for p in w] + [r["true_y_m"] for r in rows]
    set_map_axes(ax_map, xs, ys, margin_m=0.3)
    add_scale_bar(ax_map, max(xs) - min(xs))
    ax_map.legend(loc="upper left", bbox_to_anchor=(0.0, -0.1), ncol=2, fontsize=8, frameon=False)
    ax_map.set_title("true poses of the study over the map", fontsize=10)

    if reference:
        ax_xy.scatter(*zip(*reference), marker="s", s=22, color="#999999", alpha=0.8, zorder=3,
                      label=f"{args.reference_label} ({len(reference)})")
    spans = [abs(v) for r in reference for v in r]
    for mode in ("paper", "default"):
        ex, ey = [r["err_x_mm"] for r in good[mode]], [r["err_y_mm"] for r in good[mode]]
        if not ex:
            continue
        radial = [math.hypot(x, y) for x, y in zip(ex, ey)]
        ax_xy.scatter(ex, ey, s=12, color=colours[mode], alpha=0.5, lw=0, zorder=4,
                      label=f"{mode} mode ({len(ex)}), RMSE {rmse(radial):.1f} mm")
        ax_xy.add_patch(plt.Circle((0, 0), rmse(radial), fill=False, ls="--", color=colours[mode], lw=1.2, zorder=5))
        spans.append(percentile(radial, 0.99))
    lim = 1.15 * max(spans + [1.0])
    ax_xy.set_xlim(-lim, lim)
    ax_xy.set_ylim(-lim, lim)
    ax_xy.set_aspect("equal", adjustable="box")
    ax_xy.axhline(0, color="#888888", lw=0.6)
    ax_xy.axvline(0, color="#888888", lw=0.6)
    ax_xy.grid(True, lw=0.4, color="#cccccc")
    ax_xy.set_xlabel("x error (estimate − truth) [mm]")
    ax_xy.set_ylabel("y error [mm]")
    ax_xy.legend(loc="upper left", fontsize=8, framealpha=0.9)
    ax_xy.set_title("position error per scan (dashed: RMSE); 99 % of points inside", fontsize=10)

    # The modes side by side at each pose, the bound behind them.
    bound = sorted({(int(r["pose_index"]) + 1, r["crlb_rmse_mm"]) for r in good["default"] if r["crlb_rmse_mm"] > 0})
    if bound:
        ax_pose.plot(*zip(*bound), color="#555555", lw=0, marker="_", ms=14 if len(bound) <= 50 else 4, mew=2.0, zorder=2,
                     label="Cramér-Rao bound of the LMS100 beam (RMSE at the pose)")
    per_scan = []
    for mode, shift in (("paper", -0.15), ("default", 0.15)):
        errors = [math.hypot(r["err_x_mm"], r["err_y_mm"]) for r in good[mode]]
        per_scan += errors
        ax_pose.scatter([r["pose_index"] + 1 + shift for r in good[mode]], errors, s=12, alpha=0.7, lw=0,
                        color=colours[mode], label=f"{mode} mode", zorder=3)
    ax_pose.set_ylim(0, 1.2 * max([percentile(per_scan, 0.995)] + [b for _, b in bound] + [1.0]))
    ax_pose.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax_pose.set_xlabel("pose number")
    ax_pose.set_ylabel("position error [mm]")
    ax_pose.grid(True, lw=0.4, color="#cccccc")
    ax_pose.legend(loc="upper center", ncol=3, fontsize=8, framealpha=0.9)
    ax_pose.set_title("position error per scan by pose (published, not wrong)", fontsize=10)
    return fig


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
    for p in (mission, evaluation):
        p.add_argument("--world", required=True, help="the world file the run used (walls; its map_file)")
        p.add_argument("--map", help="reflector map (default: the world's map_file)")
        p.add_argument("--out", action="append", help="picture file, format by extension (repeatable; "
                       "default: the input with .png)")
        p.add_argument("--title", help="title above the picture")
    args = parser.parse_args(argv)
    if args.command == "mission" and args.zoom_mm <= 0:
        parser.error(f"--zoom-mm must be above 0, got {args.zoom_mm}")
    outputs = args.out or [os.path.splitext(args.trace if args.command == "mission" else args.csv)[0] + ".png"]
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
    fig = plot_mission(args, inputs, plt) if args.command == "mission" else plot_eval(args, inputs, plt)
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
