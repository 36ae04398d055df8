#!/usr/bin/python3
"""Correlation of per-reflector detection errors over time and travelled distance (issue 15).

Input: a JSON-lines export of a simulated run (refloc-log LOG -c REFLECTOR_MATCHES -c GROUND_TRUTH
--jsonl F) and the robot file (laser mount). Every matched detection is compared with where its
map reflector lies, seen from the true laser pose at the scan's time (the extractor's motion
compensation expresses detections there; ground truth interpolated); the error is split along the line of sight (radial) and across it (tangential).
For pairs of sightings of the same reflector, the products of their errors (the run's mean
removed, not each reflector's: a reflector's persistent offset is correlation too) are
averaged in bins of the time between them and of the distance the laser travelled between them,
and normalised by the variance: rho = 1 is the same error again, 0 a fresh one.

    residual_correlation.py --jsonl run.jsonl --robot deploy/config/robot.json --out corr.png

Prints rho at one scan, the travelled distance where rho falls below 0.5 and 0.2, and rho
beyond 2 m (what stays: each reflector's own bias); writes corr.png/.svg and corr.csv.
"""

import argparse
import bisect
import csv
import json
import math
import re
import sys

import numpy as np


def load_mount(path):
    text = open(path).read()
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = "\n".join(line for line in text.splitlines() if not line.lstrip().startswith("//"))
    mount = json.loads(text)["laser_mount"]
    return mount["x_m"], mount["y_m"], mount["theta_rad"]


def read_run(path):
    truth, matches = [], []
    with open(path) as f:
        for line in f:
            d = json.loads(line)
            m = d.get("msg")
            if m is None:
                continue
            if d["channel"] == "GROUND_TRUTH":
                truth.append((m["utime"], m["x"], m["y"], m["theta"]))
            elif d["channel"] == "REFLECTOR_MATCHES" and m["status"] == 0:
                matches.append(m)
    truth.sort()
    return truth, matches


class Truth:
    def __init__(self, samples):
        self.t = [s[0] for s in samples]
        self.s = samples
        # travelled distance of the robot along the true path [m]
        self.dist = [0.0]
        for a, b in zip(samples, samples[1:]):
            self.dist.append(self.dist[-1] + math.hypot(b[1] - a[1], b[2] - a[2]))

    def at(self, utime):
        i = bisect.bisect_left(self.t, utime)
        if i <= 0 or i >= len(self.t):
            return None
        a, b = self.s[i - 1], self.s[i]
        w = (utime - a[0]) / max(b[0] - a[0], 1)
        dth = math.atan2(math.sin(b[3] - a[3]), math.cos(b[3] - a[3]))
        d = self.dist[i - 1] + w * (self.dist[i] - self.dist[i - 1])
        return a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2]), a[3] + w * dth, d


def residuals(truth, matches, mount, nees_by_range=None):
    """Per map id: arrays (utime [s], travelled [m], radial error [m], tangential error [m]).
    nees_by_range: if a dict, gets range bin [m] -> list of each detection's NEES against its
    own covariance (2 is honest)."""
    mx, my, mth = mount
    per = {}
    for m in matches:
        # The extractor re-expresses every detection in the laser frame at the scan's utime
        # (motion compensation), so that is the pose to compare with.
        pose = truth.at(m["utime"])
        if pose is None:
            continue
        for p in m["matches"]:
            det = p["detection"]
            x, y, th, travelled = pose
            lx = x + mx * math.cos(th) - my * math.sin(th)
            ly = y + mx * math.sin(th) + my * math.cos(th)
            lth = th + mth
            dx, dy = p["map_x"] - lx, p["map_y"] - ly
            px = dx * math.cos(lth) + dy * math.sin(lth)  # predicted centre, laser frame
            py = -dx * math.sin(lth) + dy * math.cos(lth)
            r = math.hypot(px, py)
            ex, ey = det["x"] - px, det["y"] - py
            if nees_by_range is not None and "covariance" in det:
                c = det["covariance"]
                det_c = c[0] * c[3] - c[1] * c[2]
                if det_c > 0:
                    nees = (c[3] * ex * ex - (c[1] + c[2]) * ex * ey + c[0] * ey * ey) / det_c
                    nees_by_range.setdefault(min(int(r // 2) * 2, 16), []).append(nees)
            radial = (ex * px + ey * py) / r
            tangential = (-ex * py + ey * px) / r
            per.setdefault(p["map_id"], []).append((m["utime"] * 1e-6, travelled, radial, tangential))
    return {k: np.array(sorted(v)) for k, v in per.items() if len(v) > 10}


def correlation(per, max_lag_s, time_edges, dist_edges):
    all_r = np.concatenate([v[:, 2] for v in per.values()])
    all_t = np.concatenate([v[:, 3] for v in per.values()])
    mean = np.array([all_r.mean(), all_t.mean()])
    var = np.array([all_r.var(), all_t.var()])
    n_t = len(time_edges) - 1
    n_d = len(dist_edges) - 1
    sums_t = np.zeros((n_t, 2)); cnt_t = np.zeros(n_t)
    sums_d = np.zeros((n_d, 2)); cnt_d = np.zeros(n_d)
    for v in per.values():
        e = v[:, 2:4] - mean
        for lag in range(1, len(v)):
            dt = v[lag:, 0] - v[:-lag, 0]
            keep = dt <= max_lag_s
            if not keep.any():
                break
            prod = e[lag:][keep] * e[:-lag][keep]
            dd = np.abs(v[lag:, 1] - v[:-lag, 1])[keep]
            it = np.digitize(dt[keep], time_edges) - 1
            idd = np.digitize(dd, dist_edges) - 1
            for idx, sums, cnt, nb in ((it, sums_t, cnt_t, n_t), (idd, sums_d, cnt_d, n_d)):
                ok = (idx >= 0) & (idx < nb)
                np.add.at(sums, idx[ok], prod[ok])
                np.add.at(cnt, idx[ok], 1)
    rho_t = sums_t / np.maximum(cnt_t, 1)[:, None] / var
    rho_d = sums_d / np.maximum(cnt_d, 1)[:, None] / var
    return rho_t, cnt_t, rho_d, cnt_d, var


def first_below(centres, rho, level):
    for c, r in zip(centres, rho):
        if r < level:
            return c
    return float("nan")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--jsonl", required=True, help="refloc-log --jsonl export with REFLECTOR_MATCHES and GROUND_TRUTH")
    parser.add_argument("--robot", required=True, help="robot file (laser mount)")
    parser.add_argument("--out", required=True, help="figure path (.png; .svg and .csv beside it)")
    parser.add_argument("--max-lag-s", type=float, default=20.0, help="longest time between paired sightings [s]")
    parser.add_argument("--title", default="per-reflector detection error correlation")
    a = parser.parse_args(argv)
    try:
        truth_samples, matches = read_run(a.jsonl)
        mount = load_mount(a.robot)
    except (OSError, ValueError, KeyError) as err:
        print(f"residual_correlation: {err}", file=sys.stderr)
        return 2
    if len(truth_samples) < 2 or not matches:
        print("residual_correlation: the export needs GROUND_TRUTH and OK REFLECTOR_MATCHES", file=sys.stderr)
        return 2
    nees_by_range = {}
    per = residuals(Truth(truth_samples), matches, mount, nees_by_range)
    time_edges = np.array([0.0, 0.03, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, a.max_lag_s + 1e-9])
    dist_edges = np.array([0.0, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 100.0])
    rho_t, cnt_t, rho_d, cnt_d, var = correlation(per, a.max_lag_s, time_edges, dist_edges)
    t_centres = 0.5 * (time_edges[:-1] + time_edges[1:])
    d_centres = np.sqrt(np.maximum(dist_edges[:-1], 1e-4) * dist_edges[1:])
    n = sum(len(v) for v in per.values())
    print(f"{n} matched detections of {len(per)} reflectors; error sigma radial {1e3 * math.sqrt(var[0]):.1f} mm, "
          f"tangential {1e3 * math.sqrt(var[1]):.1f} mm")
    print(f"rho at one scan (0-30 ms): radial {rho_t[0, 0]:.2f}, tangential {rho_t[0, 1]:.2f}")
    for k, name in enumerate(("radial", "tangential")):
        print(f"{name}: rho < 0.5 after {first_below(d_centres, rho_d[:, k], 0.5):.3f} m travelled, "
              f"< 0.2 after {first_below(d_centres, rho_d[:, k], 0.2):.3f} m; beyond 2 m {rho_d[-2, k]:.2f}")
    if nees_by_range:
        print("per-detection NEES against the extractor's covariance (2 is honest), by range: " +
              ", ".join(f"{lo}-{lo + 2} m {np.mean(v):.2f} (n {len(v)})" for lo, v in sorted(nees_by_range.items())))
    stem = a.out[:-4] if a.out.endswith(".png") else a.out
    with open(stem + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["axis", "bin_low", "bin_high", "pairs", "rho_radial", "rho_tangential"])
        for i in range(len(t_centres)):
            w.writerow(["time_s", time_edges[i], time_edges[i + 1], int(cnt_t[i]), rho_t[i, 0], rho_t[i, 1]])
        for i in range(len(d_centres)):
            w.writerow(["travelled_m", dist_edges[i], dist_edges[i + 1], int(cnt_d[i]), rho_d[i, 0], rho_d[i, 1]])
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, centres, rho, cnt, label in ((axes[0], t_centres, rho_t, cnt_t, "time between the sightings [s]"),
                                         (axes[1], d_centres, rho_d, cnt_d, "distance the laser travelled between them [m]")):
        ok = cnt > 20
        ax.semilogx(centres[ok], rho[ok, 0], "o-", label="radial (along the line of sight)")
        ax.semilogx(centres[ok], rho[ok, 1], "s-", label="tangential")
        ax.axhline(0.0, color="grey", lw=0.8)
        ax.set_xlabel(label)
        ax.set_ylabel("correlation of the errors [-]")
        ax.set_ylim(-0.2, 1.05)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.suptitle(a.title + f" ({n} detections, {len(per)} reflectors)")
    fig.tight_layout()
    fig.savefig(stem + ".png", dpi=110)
    fig.savefig(stem + ".svg")
    print(f"wrote {stem}.png, .svg and .csv")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
