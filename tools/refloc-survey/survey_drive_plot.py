#!/usr/bin/python3
"""survey_drive_plot: the picture of a driving survey (refloc-survey drive --report DIR draws it).

  survey_drive_plot.py --report DIR [--truth MAP.json] [--out F.png] [--out F.svg] [--title T]

Left: the optimised trajectory, the traced occluders, each surveyed reflector with its id and
its 3-sigma ellipse (magnified, the factor in the legend), the bright things not mapped (with
the reason in the report), and with --truth the true reflectors. Right: per reflector its
sigma (major, minor) and, when DIR/comparison.csv exists (--truth given to refloc-survey), the
error against the truth after the rigid alignment. Reads DIR/reflectors.csv, trajectory.csv,
occluders.csv, rejected.csv; draws with matplotlib (Debian's python3-matplotlib) and the shared
helpers of tools/refloc-plot. Exit codes: 0 written, 64 usage, 2 missing or bad input, 1 other."""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "refloc-plot"))
from refloc_plot_data import DataError, _number, _rows, load_json  # noqa: E402

EXIT_USAGE, EXIT_DATA, EXIT_FAILURE = 64, 2, 1


class Parser(argparse.ArgumentParser):
    def error(self, message):
        self.print_usage(sys.stderr)
        print(f"{self.prog}: {message}", file=sys.stderr)
        sys.exit(EXIT_USAGE)


def table(path, columns):
    rows = _rows(path, columns)
    return [{c: (_number(path, i, r, c) if c not in ("name", "reason") else r[c]) for c in columns}
            for i, r in enumerate(rows, start=2)]


def load_inputs(args):
    d = args.report
    inputs = {
        "reflectors": table(f"{d}/reflectors.csv", ("id", "x_m", "y_m", "cov_xx_m2", "cov_xy_m2", "cov_yy_m2",
                                                    "sigma_major_mm", "sigma_minor_mm", "anchor")),
        "trajectory": table(f"{d}/trajectory.csv", ("t_s", "x_m", "y_m")),
        "occluders": table(f"{d}/occluders.csv", ("name", "x0_m", "y0_m", "x1_m", "y1_m")),
        "rejected": table(f"{d}/rejected.csv", ("x_m", "y_m", "times_seen", "reason")),
        "comparison": [],
        "truth": [],
    }
    if os.path.exists(f"{d}/comparison.csv"):
        inputs["comparison"] = table(f"{d}/comparison.csv", ("map_id", "error_x_mm", "error_y_mm", "error_mm"))
    if args.truth:
        truth = load_json(args.truth)
        try:
            inputs["truth"] = [(float(r["x"]), float(r["y"])) for r in truth["reflectors"]]
        except (KeyError, TypeError, ValueError) as e:
            raise DataError(f"{args.truth}: /reflectors: expected x and y in metres") from e
    return inputs


def ellipse_scale(reflectors):
    """A round magnification that draws the largest 3-sigma ellipse ~0.4 m across."""
    largest = max((3e-3 * r["sigma_major_mm"] for r in reflectors), default=0.0)
    if largest <= 0.0:
        return 1.0
    raw = 0.4 / largest
    power = 10.0 ** math.floor(math.log10(raw))
    return max(m * power for m in (1, 2, 5, 10) if m * power <= raw)


def draw_map(ax, inputs, scale):
    from matplotlib.patches import Ellipse
    for i, o in enumerate(inputs["occluders"]):
        ax.plot([o["x0_m"], o["x1_m"]], [o["y0_m"], o["y1_m"]], color="#444444", lw=1.6, zorder=1,
                label=f"occluders traced ({len(inputs['occluders'])} segments)" if i == 0 else None)
    t = inputs["trajectory"]
    ax.plot([p["x_m"] for p in t], [p["y_m"] for p in t], color="#1f77b4", lw=0.8, zorder=2,
            label=f"trajectory, optimised ({len(t)} scans)")
    if inputs["truth"]:
        xs, ys = zip(*inputs["truth"])
        ax.scatter(xs, ys, s=60, marker="o", facecolor="none", edgecolor="black", lw=0.8, zorder=3,
                   label=f"true reflectors ({len(xs)})")
    for i, r in enumerate(inputs["reflectors"]):
        cov = [[r["cov_xx_m2"], r["cov_xy_m2"]], [r["cov_xy_m2"], r["cov_yy_m2"]]]
        a, b, c = cov[0][0], cov[0][1], cov[1][1]
        root = math.sqrt(max(0.0, (a - c) ** 2 / 4 + b * b))
        major, minor = math.sqrt(max(0.0, (a + c) / 2 + root)), math.sqrt(max(0.0, (a + c) / 2 - root))
        angle = 0.5 * math.degrees(math.atan2(2 * b, a - c))
        ax.add_patch(Ellipse((r["x_m"], r["y_m"]), 6 * major * scale, 6 * minor * scale, angle=angle,
                             facecolor="#2ca02c", alpha=0.35, edgecolor="#2ca02c", zorder=4,
                             label=f"surveyed reflectors, 3σ ellipse ×{scale:g}" if i == 0 else None))
        ax.plot([r["x_m"]], [r["y_m"]], marker="+", color="#2ca02c", ms=6, zorder=5)
        ax.annotate(f"{int(r['id'])}{'A' if r['anchor'] else ''}", (r["x_m"], r["y_m"]), xytext=(4, 4),
                    textcoords="offset points", fontsize=7, color="#2ca02c", zorder=5)
    shown = [j for j in inputs["rejected"] if j["times_seen"] >= 5]
    if shown:
        ax.scatter([j["x_m"] for j in shown], [j["y_m"] for j in shown], marker="x", color="#d62728", s=40, zorder=5,
                   label=f"seen, not mapped ({len(shown)}; reasons in report.txt)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [m] (map frame)")
    ax.set_ylabel("y [m]")
    ax.grid(True, lw=0.4, color="#cccccc", zorder=-1)
    ax.legend(loc="upper left", fontsize=8, bbox_to_anchor=(0.0, -0.08), ncol=2, frameon=False)


def draw_numbers(ax, inputs):
    refl = inputs["reflectors"]
    ids = [int(r["id"]) for r in refl]
    x = range(len(ids))
    ax.bar([i - 0.2 for i in x], [r["sigma_major_mm"] for r in refl], width=0.4, color="#2ca02c", alpha=0.6,
           label="σ major [mm]")
    ax.bar([i + 0.2 for i in x], [r["sigma_minor_mm"] for r in refl], width=0.4, color="#98df8a",
           label="σ minor [mm]")
    errors = {int(c["map_id"]): c["error_mm"] for c in inputs["comparison"]}
    if errors:
        ax.plot(list(x), [errors.get(i, math.nan) for i in ids], "o", color="black",
                label="error vs truth after rigid alignment [mm]")
    ax.set_xticks(list(x))
    ax.set_xticklabels([str(i) for i in ids], fontsize=7)
    ax.set_xlabel("reflector id")
    ax.set_ylabel("mm")
    ax.grid(True, axis="y", lw=0.4, color="#cccccc")
    ax.legend(fontsize=8)


def main():
    parser = Parser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--report", required=True, help="refloc-survey drive's --report folder")
    parser.add_argument("--truth", help="the true map, drawn beside (simulation)")
    parser.add_argument("--out", action="append", help="picture file (.png, .svg, .pdf); repeatable")
    parser.add_argument("--title", help="title of the picture")
    args = parser.parse_args()
    outs = args.out or [os.path.join(args.report, "survey.png")]
    for out in outs:
        if os.path.splitext(out)[1].lower() not in (".png", ".svg", ".pdf"):
            parser.error(f"--out {out}: the extension must be .png, .svg or .pdf")
    try:
        inputs = load_inputs(args)
    except DataError as e:
        print(f"survey_drive_plot: {e}", file=sys.stderr)
        return EXIT_DATA
    try:
        import matplotlib
        matplotlib.use("Agg")
        matplotlib.rcParams["svg.fonttype"] = "none"
        import matplotlib.pyplot as plt
    except ImportError:
        print("survey_drive_plot: matplotlib missing (Debian: python3-matplotlib)", file=sys.stderr)
        return EXIT_FAILURE
    fig = plt.figure(figsize=(16, 8.5), layout="constrained")
    grid = fig.add_gridspec(1, 2, width_ratios=[2.3, 1])
    ax_map, ax_num = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1])
    fig.suptitle(args.title or f"refloc-survey drive: {os.path.abspath(args.report)}", fontsize=12)
    draw_map(ax_map, inputs, ellipse_scale(inputs["reflectors"]))
    draw_numbers(ax_num, inputs)
    try:
        for out in outs:
            fig.savefig(out, dpi=110)
    except OSError as e:
        print(f"survey_drive_plot: cannot write the picture: {e}", file=sys.stderr)
        return EXIT_FAILURE
    return 0


if __name__ == "__main__":
    sys.exit(main())
