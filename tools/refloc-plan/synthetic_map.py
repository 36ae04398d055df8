#!/usr/bin/python3
"""A synthetic reflector map for refloc-plan's runtime figure: N reflectors (default 1000)
placed uniformly at random in a SIZE x SIZE m hall (default 100 m), at least 1 m apart, with the
hall's outline as an occluder (map format 2). Deterministic for a seed.

  tools/refloc-plan/synthetic_map.py [--n 1000] [--size-m 100] [--seed 1] --out MAP.json

Exit codes: 0 written, 64 usage error (argparse's 2 is mapped), 1 cannot place them or write."""

import argparse
import json
import random
import sys


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--n", type=int, default=1000, help="reflectors [-]")
    parser.add_argument("--size-m", type=float, default=100.0, help="side of the square hall [m]")
    parser.add_argument("--min-gap-m", type=float, default=1.0, help="least distance between reflectors [m]")
    parser.add_argument("--seed", type=int, default=1, help="random seed")
    parser.add_argument("--out", required=True, help="map file to write")
    try:
        args = parser.parse_args(argv)
    except SystemExit as e:
        return 64 if e.code else 0
    rng = random.Random(args.seed)
    cell = args.min_gap_m
    taken = {}
    reflectors = []
    for _ in range(200 * args.n):
        if len(reflectors) == args.n:
            break
        x, y = rng.uniform(0.5, args.size_m - 0.5), rng.uniform(0.5, args.size_m - 0.5)
        key = (int(x / cell), int(y / cell))
        near = [taken.get((key[0] + i, key[1] + j)) for i in (-1, 0, 1) for j in (-1, 0, 1)]
        if any(p and (p[0] - x) ** 2 + (p[1] - y) ** 2 < cell * cell for p in near):
            continue
        taken[key] = (x, y)
        reflectors.append({"id": len(reflectors) + 1, "x": round(x, 3), "y": round(y, 3)})
    if len(reflectors) < args.n:
        print(f"synthetic_map: placed only {len(reflectors)} of {args.n}", file=sys.stderr)
        return 1
    s = args.size_m
    doc = {"format": 2, "map_id": f"synthetic_{args.n}", "version": 1, "created": "2026-12-03T00:00:00Z",
           "source": "typed", "default_radius_m": 0.06, "reflectors": reflectors,
           "occluders": [{"name": "hall", "closed": True, "points": [[0, 0], [s, 0], [s, s], [0, s]]}]}
    try:
        with open(args.out, "w", encoding="utf-8") as f:
            json.dump(doc, f, indent=1)
    except OSError as e:
        print(f"synthetic_map: {args.out}: cannot write ({e.strerror})", file=sys.stderr)
        return 1
    print(f"synthetic_map: wrote {args.out} ({len(reflectors)} reflectors, {s:g} x {s:g} m)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
