"""What refloc-plot reads: the world and map files a run used, refloc-mission's path trace and
refloc-eval's measurement CSV. Every failure is a DataError naming the file and what is wrong."""

import csv
import json
import math
import os


class DataError(Exception):
    """A file that is missing or not what it should be (exit code 2)."""


def _without_comments(text):
    # The config readers accept // and /* */ comments (nlohmann-json's ignore_comments);
    # Python's json does not. Strings are copied untouched ("udpm://..." stays).
    out, i, n, in_string = [], 0, len(text), False
    while i < n:
        c = text[i]
        if in_string:
            out.append(c)
            if c == "\\" and i + 1 < n:
                out.append(text[i + 1])
                i += 1
            elif c == '"':
                in_string = False
        elif c == '"':
            in_string = True
            out.append(c)
        elif text.startswith("//", i):
            i = text.find("\n", i)
            i = n if i < 0 else i
            continue
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            i = n if end < 0 else end + 2
            continue
        else:
            out.append(c)
        i += 1
    return "".join(out)


def load_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.loads(_without_comments(f.read()))
    except OSError as e:
        raise DataError(f"{path}: cannot read ({e.strerror})") from e
    except json.JSONDecodeError as e:
        raise DataError(f"{path}: not JSON: {e}") from e


def _points(path, pointer, item):
    try:
        pts = [(float(p[0]), float(p[1])) for p in item["points"]]
    except (KeyError, TypeError, ValueError, IndexError) as e:
        raise DataError(f"{path}: {pointer}/points: expected a list of [x, y] in metres") from e
    if item.get("closed", False) and pts:
        pts.append(pts[0])
    return pts


def load_world(world_path, map_path=None):
    """Walls and obstacles (polylines [m]) of a world file and the reflectors of its map file
    (map_file relative to the world's folder, as the world loader resolves it), or of map_path."""
    world = load_json(world_path)
    if not isinstance(world, dict):
        raise DataError(f"{world_path}: expected a JSON object (a world file)")
    walls = [_points(world_path, f"/walls/{i}", w) for i, w in enumerate(world.get("walls", []))]
    obstacles = [_points(world_path, f"/obstacles/{i}", o) for i, o in enumerate(world.get("obstacles", []))]
    if map_path is None:
        if "map_file" not in world:
            raise DataError(f"{world_path}: /map_file missing; expected the path of a reflector map file")
        map_path = os.path.join(os.path.dirname(world_path), world["map_file"])
    reflector_map = load_json(map_path)
    default_radius = float(reflector_map.get("default_radius_m", 0.06))
    reflectors = []
    for i, r in enumerate(reflector_map.get("reflectors", [])):
        try:
            reflectors.append((r.get("id", i), float(r["x"]), float(r["y"]), float(r.get("radius_m", default_radius))))
        except (KeyError, TypeError, ValueError) as e:
            raise DataError(f"{map_path}: /reflectors/{i}: expected x and y in metres") from e
    return {"walls": walls, "obstacles": obstacles, "reflectors": reflectors, "world": world_path, "map": map_path}


def _rows(path, required):
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            missing = [c for c in required if c not in (reader.fieldnames or [])]
            if missing:
                raise DataError(f"{path}: columns {', '.join(missing)} missing (header: {reader.fieldnames})")
            return list(reader)
    except OSError as e:
        raise DataError(f"{path}: cannot read ({e.strerror})") from e


def _number(path, line, row, key):
    text = row[key]
    if text is None or text == "":
        return math.nan
    try:
        return float(text)
    except ValueError as e:
        raise DataError(f"{path}: line {line}: {key} = '{text}' is not a number") from e


def load_trace(path):
    """refloc-mission's trace (path_plot_trace.hpp): per kind, lists t_s, x_m, y_m, theta_rad, error_mm."""
    columns = ("t_s", "x_m", "y_m", "theta_rad", "error_mm")
    trace = {k: {c: [] for c in columns} for k in ("GROUND_TRUTH", "POSE", "LASER_POSE", "WAYPOINT")}
    for line, row in enumerate(_rows(path, ("kind",) + columns), start=2):
        kind = row["kind"]
        if kind not in trace:
            raise DataError(f"{path}: line {line}: unknown kind '{kind}'")
        for c in columns:
            trace[kind][c].append(_number(path, line, row, c))
    if not trace["GROUND_TRUTH"]["t_s"]:
        raise DataError(f"{path}: no GROUND_TRUTH rows: nothing to compare against")
    return trace


def load_eval_csv(path):
    """refloc-eval's measurements (accuracy_study.cpp measurements_csv), numbers as floats."""
    keys = ("mode", "pose_index", "true_x_m", "true_y_m", "published_ok", "wrong", "err_x_mm", "err_y_mm",
            "crlb_rmse_mm")
    rows = []
    for line, row in enumerate(_rows(path, keys), start=2):
        rows.append({"mode": row["mode"], **{k: _number(path, line, row, k) for k in keys[1:]}})
    if not rows:
        raise DataError(f"{path}: no measurements")
    return rows


def load_reference_csv(path):
    """Published errors to compare with (err_x_mm, err_y_mm), e.g. the paper's Table 1."""
    return [(_number(path, i, r, "err_x_mm"), _number(path, i, r, "err_y_mm"))
            for i, r in enumerate(_rows(path, ("err_x_mm", "err_y_mm")), start=2)]
