"""refloc-eval's pictures: a paper-table / random study (poses over the map, error scatter,
error per pose against the Cramér-Rao bound) and a drive (fixes per motion source over the map,
error over time)."""

import math
import os

from refloc_plot_draw import (LASER_COLOUR, POSE_COLOUR, TRUTH_COLOUR, add_scale_bar, draw_map, error_panel_limit,
                              legible_fix_markers, percentile, rmse, running_mean, set_map_axes)


def plot_eval(args, inputs, plt):
    from matplotlib.ticker import MaxNLocator
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


def plot_drive(args, inputs, plt):
    traces, world = inputs["traces"], inputs["world"]
    colours = ["#1f77b4", "#9467bd", "#d62728", "#8c564b", "#e377c2"]  # not the reflectors' green
    fig = plt.figure(figsize=(13, 11), layout="constrained")
    grid = fig.add_gridspec(2, 1, height_ratios=[1.6, 1])
    ax_map, ax_err = fig.add_subplot(grid[0]), fig.add_subplot(grid[1])
    fig.suptitle(args.title or "refloc-eval drive", fontsize=13)
    draw_map(ax_map, world)
    truth = traces[0][1]["GROUND_TRUTH"]
    ax_map.plot(truth["x_m"], truth["y_m"], color=TRUTH_COLOUR, lw=2.6, alpha=0.35, zorder=4, label="true path")
    for n, (name, trace) in enumerate(traces):
        fixes, colour = trace["LASER_POSE"], colours[n % len(colours)]
        ax_map.scatter(fixes["x_m"], fixes["y_m"], s=2, color=colour, alpha=0.4, lw=0, zorder=3,
                       label=f"fixes, {name} ({len(fixes['t_s'])})")
        ax_err.scatter(fixes["t_s"], fixes["error_mm"], s=3, color=colour, alpha=0.25, lw=0, zorder=3)
        ax_err.plot(fixes["t_s"], running_mean(fixes["t_s"], fixes["error_mm"], 1.0), color=colour, lw=1.6, zorder=4,
                    label=f"{name}: RMSE {rmse(fixes['error_mm']):.1f} mm (line: 1 s running mean)")
    xs = [p[0] for w in world["walls"] for p in w] + truth["x_m"]
    ys = [p[1] for w in world["walls"] for p in w] + truth["y_m"]
    set_map_axes(ax_map, xs, ys, margin_m=0.4)
    add_scale_bar(ax_map, max(xs) - min(xs))
    legible_fix_markers(ax_map.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False))
    ax_map.set_title("true path and the fixes of each motion source over the map", fontsize=10)
    top = error_panel_limit([t["LASER_POSE"]["error_mm"] for _, t in traces], [])
    ax_err.set_ylim(0, top)
    ax_err.set_xlim(0, max(truth["t_s"]))
    ax_err.set_xlabel("time [s] (fixes scored after the warm-up)")
    ax_err.set_ylabel("fix position error vs truth [mm]")
    ax_err.grid(True, lw=0.4, color="#cccccc")
    ax_err.legend(loc="upper right", fontsize=8, framealpha=0.9)
    ax_err.set_title("LASER_POSE error over time per motion source", fontsize=10)
    return fig
