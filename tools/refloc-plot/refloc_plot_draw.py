"""The pieces both pictures share: the map (walls, obstacles, reflectors) under a path, a scale
bar, the colours of the three traces and the waypoint marks."""

import math

from matplotlib.patches import Circle, Polygon
from mpl_toolkits.axes_grid1.anchored_artists import AnchoredSizeBar

# One colour per source in every picture (matplotlib's default cycle, colour-blind safe pair).
TRUTH_COLOUR = "black"
POSE_COLOUR = "#1f77b4"
LASER_COLOUR = "#ff7f0e"
WAYPOINT_COLOUR = "#d62728"
WALL_COLOUR = "#444444"
REFLECTOR_COLOUR = "#2ca02c"


def draw_map(ax, world, label_reflectors=True):
    """Walls as lines, obstacles filled light grey, reflectors as circles of their true size
    with a marker that stays visible when the map is small, in the map frame [m]."""
    for i, wall in enumerate(world["walls"]):
        xs, ys = zip(*wall) if wall else ((), ())
        ax.plot(xs, ys, color=WALL_COLOUR, lw=1.8, zorder=1, label="walls" if i == 0 else None)
    for i, obstacle in enumerate(world["obstacles"]):
        ax.add_patch(Polygon(obstacle, closed=True, facecolor="#dddddd", edgecolor="#999999", lw=0.8, zorder=0,
                             label="racks, pillars" if i == 0 else None))
    if not world["reflectors"]:
        return
    ids, xs, ys, radii = zip(*world["reflectors"])
    for x, y, r in zip(xs, ys, radii):
        ax.add_patch(Circle((x, y), r, facecolor=REFLECTOR_COLOUR, edgecolor="none", zorder=1, alpha=0.8))
    ax.scatter(xs, ys, s=18, marker="o", facecolor="none", edgecolor=REFLECTOR_COLOUR, lw=1.0, zorder=1,
               label=f"reflectors ({len(xs)})")
    if label_reflectors:
        for rid, x, y in zip(ids, xs, ys):
            ax.annotate(str(rid), (x, y), xytext=(3, 3), textcoords="offset points", fontsize=6,
                        color=REFLECTOR_COLOUR, zorder=1)


def nice_length(span):
    """A 1, 2 or 5 times a power of ten near a fifth of span, for a scale bar."""
    target = max(span / 5.0, 1e-9)
    power = 10.0 ** math.floor(math.log10(target))
    return max((m * power for m in (1, 2, 5) if m * power <= target), default=power)


def length_label(metres):
    if metres >= 1.0:
        return f"{metres:g} m"
    if metres >= 0.01:
        return f"{metres * 100:g} cm"
    return f"{metres * 1000:g} mm"


def add_scale_bar(ax, span, metres_per_unit=1.0, loc="lower right"):
    """A bar of a round length about a fifth of span (in the axes' data units)."""
    length = nice_length(span * metres_per_unit) / metres_per_unit
    ax.add_artist(AnchoredSizeBar(ax.transData, length, length_label(length * metres_per_unit), loc, pad=0.4, sep=3,
                                  frameon=True, size_vertical=span / 400.0, color="black",
                                  fontproperties={"size": 8}))


def set_map_axes(ax, xs, ys, margin_m):
    """Equal scale, axes in metres with a grid, limits around the points."""
    ax.set_xlim(min(xs) - margin_m, max(xs) + margin_m)
    ax.set_ylim(min(ys) - margin_m, max(ys) + margin_m)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel("x [m] (map frame)")
    ax.set_ylabel("y [m]")
    ax.grid(True, lw=0.4, color="#cccccc", zorder=-1)


def draw_waypoints(ax, waypoints, arrow_m, label=True):
    """Targets as red crosses with their heading as a short arrow and their index (0-based, as
    refloc-mission's "waypoint 0 reached" lines count)."""
    for i, (x, y, theta) in enumerate(zip(waypoints["x_m"], waypoints["y_m"], waypoints["theta_rad"])):
        ax.plot([x], [y], marker="x", color=WAYPOINT_COLOUR, ms=7, mew=1.6, zorder=6,
                label="waypoints (target, heading)" if i == 0 else None)
        ax.annotate("", xy=(x + arrow_m * math.cos(theta), y + arrow_m * math.sin(theta)), xytext=(x, y),
                    arrowprops={"arrowstyle": "->", "color": WAYPOINT_COLOUR, "lw": 1.0}, zorder=6)
        if label:
            ax.annotate(f"WP{i}", (x, y), xytext=(5, -11), textcoords="offset points", fontsize=8,
                        color=WAYPOINT_COLOUR, weight="bold", zorder=6)


def rmse(values):
    finite = [v for v in values if not math.isnan(v)]
    return math.sqrt(sum(v * v for v in finite) / len(finite)) if finite else math.nan


def percentile(values, share):
    finite = sorted(v for v in values if not math.isnan(v))
    if not finite:
        return math.nan
    return finite[min(len(finite) - 1, int(share * (len(finite) - 1) + 0.5))]


def running_mean(times, values, window):
    """Mean of the finite values within the last `window` (same unit as times) at each time."""
    out, start, total, count = [], 0, 0.0, 0
    for i, (t, v) in enumerate(zip(times, values)):
        if not math.isnan(v):
            total, count = total + v, count + 1
        while times[start] < t - window:
            if not math.isnan(values[start]):
                total, count = total - values[start], count - 1
            start += 1
        out.append(total / count if count else math.nan)
    return out


def error_panel_limit(series_mm, marks_mm):
    """Top of the error axis: the 99.5th percentile with headroom, so that a few start-up
    outliers do not squash the millimetres; clipped points are counted in the title."""
    top = max([percentile(s, 0.995) for s in series_mm] + marks_mm + [1.0])
    return 1.25 * top if not math.isnan(top) else 10.0


def legible_fix_markers(legend):
    """Scatter entries drawn at one readable size in the legend (the plot's fixes are tiny)."""
    handles = getattr(legend, "legend_handles", None) or getattr(legend, "legendHandles", [])
    for handle in handles:
        if hasattr(handle, "set_sizes"):
            handle.set_sizes([25.0])
            handle.set_alpha(0.9)
