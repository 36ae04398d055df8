#!/usr/bin/python3
"""Draws laser_mount.png / laser_mount.svg for docs/real-robot.md: the robot frame, the
wheel order, the laser reference point, its field of view and beam order, and
robot_T_laser (robot.json /laser_mount) with the paper's eq. 8 quantities OO' and beta.

The dimensions are the deployed robot.json's (wheel radius 0.076 m, lx 0.25 m, ly 0.22 m);
the mount is an example with y and theta not zero so that their signs show.

    /usr/bin/python3 docs/images/laser_mount.py   # Debian python3-matplotlib
"""
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Arc, FancyArrowPatch, Polygon, Rectangle, Wedge  # noqa: E402

LX, LY, WHEEL_R, WHEEL_W = 0.25, 0.22, 0.076, 0.06
MOUNT = (0.30, 0.10, math.radians(15.0))  # example x_m, y_m, theta_rad
FOV_DRAWN_M = 0.45  # radius of the drawn field of view (the real one reaches 20 m)
HERE = os.path.dirname(os.path.abspath(__file__))


def arrow(ax, start, end, color, text=None, text_at=None, lw=2.0, style="-|>", ms=14):
    ax.add_patch(FancyArrowPatch(start, end, arrowstyle=style, mutation_scale=ms, lw=lw, color=color))
    if text:
        ax.annotate(text, text_at or end, color=color, fontsize=11, ha="center", va="center")


def laser_to_robot(p):
    x, y, th = MOUNT
    return (x + math.cos(th) * p[0] - math.sin(th) * p[1], y + math.sin(th) * p[0] + math.cos(th) * p[1])


def draw_robot(ax):
    ax.add_patch(Rectangle((-0.33, -0.27), 0.66, 0.54, fc="#eeeeee", ec="#555555", lw=1.5, zorder=0))
    names = {(1, 1): "0 front-left", (1, -1): "1 front-right", (-1, -1): "2 rear-right", (-1, 1): "3 rear-left"}
    for (sx, sy), name in names.items():
        cx, cy = sx * LX, sy * LY
        ax.add_patch(Rectangle((cx - WHEEL_R, cy - WHEEL_W / 2), 2 * WHEEL_R, WHEEL_W, fc="#777777", ec="k", zorder=1))
        ax.annotate(name, (cx - (0.04 if sx > 0 else 0.0), cy + sy * 0.075), ha="center", va="center", fontsize=9)
        arrow(ax, (cx - 0.05, cy), (cx + 0.05, cy), "w", lw=1.2, ms=9)
    ax.annotate("wheel arrows: a positive wheel speed\ndrives that wheel's contact point forward",
                (-0.33, -0.36), fontsize=8, color="#555555", ha="left", va="top")


def draw_robot_frame(ax):
    ax.plot(0, 0, "o", color="tab:blue", ms=7, zorder=5)
    arrow(ax, (0, 0), (0.2, 0), "tab:blue", "+x forward", (0.12, -0.035))
    arrow(ax, (0, 0), (0, 0.2), "tab:blue", "+y left", (-0.065, 0.18))
    ax.add_patch(Arc((0, 0), 0.16, 0.16, theta1=100, theta2=200, color="tab:blue", lw=1.5))
    end = (0.08 * math.cos(math.radians(200)), 0.08 * math.sin(math.radians(200)))
    start = (0.08 * math.cos(math.radians(190)), 0.08 * math.sin(math.radians(190)))
    arrow(ax, start, end, "tab:blue", lw=1.5, ms=10)
    ax.annotate("+θ, +wz: counter-\nclockwise", (-0.1, 0.07), color="tab:blue", fontsize=8, ha="right")
    ax.annotate("robot reference point:\ncentre of the four wheels", (-0.03, -0.06), color="tab:blue",
                fontsize=9, ha="right", va="top")


def draw_laser(ax):
    x, y, th = MOUNT
    deg = math.degrees(th)
    ax.add_patch(Wedge((x, y), FOV_DRAWN_M, deg - 135, deg + 135, fc="tab:orange", alpha=0.10, ec="none"))
    for a, label, dy in ((-135, "beam 0 at −135°\n(LMS100: −45°)", -0.02), (135, "last beam +135°\n(LMS100: 225°)", 0.02)):
        end = laser_to_robot((FOV_DRAWN_M * math.cos(math.radians(a)), FOV_DRAWN_M * math.sin(math.radians(a))))
        ax.plot([x, end[0]], [y, end[1]], color="tab:orange", lw=1, ls="--")
        ax.annotate(label, (end[0], end[1] + dy), fontsize=8, color="tab:orange", ha="center",
                    va="top" if a < 0 else "bottom")
    r_arc = 0.40
    ax.add_patch(Arc((x, y), 2 * r_arc, 2 * r_arc, theta1=deg - 40, theta2=deg + 40, color="tab:orange", lw=1.2))
    tip = laser_to_robot((r_arc * math.cos(math.radians(40)), r_arc * math.sin(math.radians(40))))
    before = laser_to_robot((r_arc * math.cos(math.radians(34)), r_arc * math.sin(math.radians(34))))
    arrow(ax, before, tip, "tab:orange", lw=1.2, ms=10)
    ax.annotate("beams in time order:\ncounter-clockwise", laser_to_robot((0.47, -0.12)), fontsize=8,
                color="tab:orange", ha="left", va="center")
    body = [laser_to_robot(p) for p in ((-0.05, -0.05), (0.05, -0.05), (0.05, 0.05), (-0.05, 0.05))]
    ax.add_patch(Polygon(body, closed=True, fc="#f3c08a", ec="k", zorder=3))
    ax.plot(x, y, "o", color="tab:red", ms=7, zorder=6)
    arrow(ax, (x, y), laser_to_robot((0.2, 0)), "tab:red", "laser +x\n(LMS100 90°)", laser_to_robot((0.27, 0.04)))
    arrow(ax, (x, y), laser_to_robot((0, 0.16)), "tab:red", "laser +y", laser_to_robot((0.06, 0.2)))


def draw_mount(ax):
    x, y, th = MOUNT
    # Dimension lines outside the body, so they do not hide the axes.
    ax.plot([0, 0], [-0.27, -0.47], color="k", lw=0.6, ls=":")
    ax.plot([x, x], [y, -0.47], color="k", lw=0.6, ls=":")
    arrow(ax, (0, -0.45), (x, -0.45), "k", lw=1, style="<|-|>", ms=8)
    ax.annotate("x_m", (x / 2, -0.47), fontsize=10, ha="center", va="top")
    ax.plot([0.33, 0.72], [0, 0], color="k", lw=0.6, ls=":")
    ax.plot([x, 0.72], [y, y], color="k", lw=0.6, ls=":")
    arrow(ax, (0.70, 0), (0.70, y), "k", lw=1, style="<|-|>", ms=8)
    ax.annotate("y_m", (0.715, y / 2), fontsize=10, ha="left", va="center")
    ax.plot([x, x + 0.25], [y, y], color="k", lw=0.8, ls="--")
    ax.add_patch(Arc((x, y), 0.44, 0.44, theta1=0, theta2=math.degrees(th), color="k", lw=1.2))
    ax.annotate("theta_rad", (x + 0.23, y + 0.035), fontsize=10, ha="left")
    ax.plot([x, 0], [y, 0], color="tab:purple", lw=1.5)
    ax.annotate("OO'", (x * 0.45, y * 0.45 + 0.015), color="tab:purple", fontsize=10, ha="center", va="bottom")
    ax.annotate("laser reference point:\nthe mirror's axis of rotation,\nwhere ranges are measured from",
                laser_to_robot((0.05, -0.22)), color="tab:red", fontsize=9, ha="left", va="top")


def main():
    fig, ax = plt.subplots(figsize=(10.5, 8.5))
    draw_robot(ax)
    draw_robot_frame(ax)
    draw_laser(ax)
    draw_mount(ax)
    x, y, th = MOUNT
    beta = -math.atan2(-y, -x)
    ax.set_title(
        "Top view. robot.json /laser_mount = robot_T_laser, the laser frame in the robot frame\n"
        f"example: x_m = {x:.2f}, y_m = {y:.2f}, theta_rad = {th:.3f} ({math.degrees(th):.0f}°); deployed: 0.30, 0, 0",
        fontsize=11)
    ax.text(-0.66, 0.72,
            "a point seen by the laser at range r, angle φ (laser frame):\n"
            "  robot_p = (x_m, y_m) + R(theta_rad) · (r cos φ, r sin φ)\n"
            "paper eq. 8 (mount angle 0): robot = laser + OO'·(cos(α−β), sin(α−β)),\n"
            "  OO' = hypot(x_m, y_m),"
            f"  α the robot heading, β = −atan2(−y_m, −x_m) = {math.degrees(beta):.1f}° here",
            fontsize=9, family="monospace", va="top")
    ax.set_aspect("equal")
    ax.set_xlim(-0.68, 1.0)
    ax.set_ylim(-0.58, 0.75)
    ax.set_xlabel("robot x [m]")
    ax.set_ylabel("robot y [m]")
    ax.grid(True, lw=0.3, alpha=0.5)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(HERE, f"laser_mount.{ext}"), dpi=110)


if __name__ == "__main__":
    main()
