"""refloc-plot plan: refloc-plan's grid.json as heat maps, one panel per quantity, with axes in
metres, the reflectors, the occluders (walls, racks) and the drivable area drawn."""

import json

from refloc_plot_data import DataError

CLASS_ORDER = ["ok", "fragile", "blind", "lost", "ambiguous"]
CLASS_COLOURS = ["#c7e9c0", "#fdd49e", "#252525", "#9e9ac8", "#e31a1c"]
SUGGESTION_COLOUR = "#1f78b4"


def load_plan(path):
    """grid.json as refloc-plan writes it; DataError naming the file and key when it is not."""
    try:
        with open(path, encoding="utf-8") as f:
            plan = json.load(f)
    except OSError as e:
        raise DataError(f"{path}: cannot read ({e.strerror})") from e
    except json.JSONDecodeError as e:
        raise DataError(f"{path}: line {e.lineno}: not JSON ({e.msg})") from e
    for key in ("resolution_m", "cells", "reflectors", "occluders", "summary"):
        if not isinstance(plan, dict) or key not in plan:
            raise DataError(f"{path}: /{key} missing; expected refloc-plan's grid.json")
    if not plan["cells"]:
        raise DataError(f"{path}: /cells is empty: the grid has no cell (drivable area?)")
    return plan


def _raster(plan, cells, value):
    """A 2D array over the cells' bounding box (NaN where there is no cell) and its extent [m]."""
    import numpy as np
    res = plan["resolution_m"]
    xs = [c["x_m"] for c in plan["cells"]]
    ys = [c["y_m"] for c in plan["cells"]]
    x0, y0 = min(xs) - res / 2, min(ys) - res / 2
    nx = int(round((max(xs) - min(xs)) / res)) + 1
    ny = int(round((max(ys) - min(ys)) / res)) + 1
    grid = np.full((ny, nx), np.nan)
    for c in cells:
        v = value(c)
        if v is None:
            continue
        grid[int(round((c["y_m"] - y0) / res - 0.5)), int(round((c["x_m"] - x0) / res - 0.5))] = v
    return grid, (x0, x0 + nx * res, y0, y0 + ny * res)


def _draw_layout(ax, plan, suggestions=False):
    from matplotlib.patches import Polygon, Rectangle
    for a in plan.get("drivable_areas", []):
        ax.add_patch(Rectangle((a["x_min"], a["y_min"]), a["x_max"] - a["x_min"], a["y_max"] - a["y_min"],
                               fill=False, ls=":", lw=0.7, edgecolor="#555555", zorder=3))
    for o in plan["occluders"]:
        pts = o["points"]
        if o.get("closed") and len(pts) >= 3:
            ax.add_patch(Polygon(pts, closed=True, facecolor="#bdbdbd", edgecolor="#444444", lw=1.0, zorder=2,
                                 alpha=0.35 if _area(pts) < 0.5 * _box_area(plan) else 0.0))
            ax.add_patch(Polygon(pts, closed=True, fill=False, edgecolor="#444444", lw=1.2, zorder=3))
        else:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], color="#444444", lw=1.2, zorder=3)
    xs = [r["x_m"] for r in plan["reflectors"]]
    ys = [r["y_m"] for r in plan["reflectors"]]
    ax.scatter(xs, ys, s=22, marker="o", facecolor="white", edgecolor="#006d2c", lw=1.3, zorder=4,
               label=f"reflectors ({len(xs)})")
    if suggestions and plan.get("suggestions"):
        sx = [s["x_m"] for s in plan["suggestions"]]
        sy = [s["y_m"] for s in plan["suggestions"]]
        ax.scatter(sx, sy, s=160, marker="*", color=SUGGESTION_COLOUR, edgecolor="white", lw=0.6, zorder=5,
                   label=f"suggested ({len(sx)})")


def _area(pts):
    return 0.5 * abs(sum(pts[i][0] * pts[(i + 1) % len(pts)][1] - pts[(i + 1) % len(pts)][0] * pts[i][1]
                         for i in range(len(pts))))


def _box_area(plan):
    xs = [p[0] for o in plan["occluders"] for p in o["points"]] + [r["x_m"] for r in plan["reflectors"]]
    ys = [p[1] for o in plan["occluders"] for p in o["points"]] + [r["y_m"] for r in plan["reflectors"]]
    return (max(xs) - min(xs)) * (max(ys) - min(ys)) if xs else 1.0


def _limits(ax, plan):
    xs = [c["x_m"] for c in plan["cells"]] + [p[0] for o in plan["occluders"] for p in o["points"]]
    ys = [c["y_m"] for c in plan["cells"]] + [p[1] for o in plan["occluders"] for p in o["points"]]
    xs += [r["x_m"] for r in plan["reflectors"]]
    ys += [r["y_m"] for r in plan["reflectors"]]
    m = 0.3
    ax.set_xlim(min(xs) - m, max(xs) + m)
    ax.set_ylim(min(ys) - m, max(ys) + m)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")


def _class_panel(ax, plan, cells, summary, title, suggestions, rivals):
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch
    grid, extent = _raster(plan, cells, lambda c: CLASS_ORDER.index(c["class"]))
    ax.imshow(grid, origin="lower", extent=extent, cmap=ListedColormap(CLASS_COLOURS), vmin=-0.5,
              vmax=len(CLASS_ORDER) - 0.5, interpolation="nearest", zorder=1)
    _draw_layout(ax, plan, suggestions)
    if rivals:
        confused = [c for c in cells if c.get("rival")]
        step = max(1, len(confused) // 12)
        for c in confused[::step]:
            r = c["rival"]
            ax.annotate("", xy=(r["x_m"], r["y_m"]), xytext=(c["x_m"], c["y_m"]), zorder=6,
                        arrowprops=dict(arrowstyle="->", color="#67000d", lw=0.8, alpha=0.8),
                        annotation_clip=False)
    handles = [Patch(facecolor=col, edgecolor="#777777", label=name) for name, col in zip(CLASS_ORDER, CLASS_COLOURS)]
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(0.0, -0.12), ncol=5, fontsize=7, frameon=False)
    ax.set_title(f"{title}\nblind {100 * summary['blind']:.1f} %, fragile {100 * summary['fragile']:.1f} %, "
                 f"ambiguous {100 * summary['ambiguous']:.1f} %, bad {100 * summary['bad']:.1f} %", fontsize=9)
    _limits(ax, plan)


def _value_panel(fig, ax, plan, key, title, label, cmap, vmax=None):
    grid, extent = _raster(plan, plan["cells"], lambda c: c[key])
    import numpy as np
    finite = grid[np.isfinite(grid)]
    top = vmax if vmax is not None else (float(np.percentile(finite, 98)) if finite.size else 1.0)
    im = ax.imshow(grid, origin="lower", extent=extent, cmap=cmap, vmin=0, vmax=max(top, 1e-9),
                   interpolation="nearest", zorder=1)
    _draw_layout(ax, plan)
    fig.colorbar(im, ax=ax, shrink=0.8, label=label)
    ax.set_title(title, fontsize=9)
    _limits(ax, plan)


def plot_plan(args, inputs, plt):
    plan = inputs["plan"]
    after = bool(plan.get("cells_after"))
    fig, axes = plt.subplots(2 if not after else 3, 2, figsize=(13, 9.5 if not after else 14), layout="constrained")
    axes = axes.flatten()
    title = args.title or (f"refloc-plan: {plan['map']} ({plan['resolution_m']} m grid, "
                           f"{plan['headings']} headings, worst heading per cell)")
    fig.suptitle(title, fontsize=12)
    _value_panel(fig, axes[0], plan, "visible_min", "reflectors seen (fewest over headings)", "reflectors [-]",
                 "viridis", vmax=max([c["visible_min"] for c in plan["cells"]] + [3]))
    _class_panel(axes[1], plan, plan["cells"], plan["summary"],
                 "class (arrows: a cell -> the pose it can be taken for)", suggestions=False, rivals=True)
    _value_panel(fig, axes[2], plan, "sigma_xy_mm",
                 f"CRLB position sigma, single scan (median {plan['summary']['median_sigma_xy_mm']:.1f} mm, "
                 f"limit {plan['crlb_limit_mm']:g} mm)", "sigma xy [mm]", "magma_r")
    _value_panel(fig, axes[3], plan, "sigma_theta_mrad", "CRLB heading sigma, single scan", "sigma theta [mrad]",
                 "magma_r")
    if after:
        _class_panel(axes[4], plan, plan["cells"], plan["summary"], "before (suggestions marked)", True, False)
        _class_panel(axes[5], plan, plan["cells_after"], plan["summary_after"],
                     f"after adding the {len(plan['suggestions'])} suggested reflectors", True, True)
    axes[0].legend(loc="upper left", bbox_to_anchor=(0.0, -0.12), fontsize=7, frameon=False)
    return fig
