"""Benchmark of the ground truth: load + rings + symmetry_group, against a float NumPy
pipeline (parse, centroid, polar sort by atan2, tolerant string matching) on the same
text file.  Run: ``python bench/bench_truth.py`` (add ``--quick`` to skip the 1,000,000
point case).

Targets (issue 9): the whole truth at most 3 times the float pipeline on 100,000 random
rational points and at most 4 times on the D4 set; on 1,000,000 random rational points
under 15 s and 1.5 GB (issue 3 asked for 10x, 60 s and 4 GB).
Also timed: a D4-symmetric rational set of 100,000 points and a polar C7-symmetric set
of 70,000 points with turn denominators near 10,000.  Each case runs in a child
process of its own, so that its peak RSS (``resource.getrusage``) is its own.
"""

from __future__ import annotations

import json
import math
import random
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from float_points import read_float_points

D4 = [((1, 0), (0, 1)), ((0, -1), (1, 0)), ((-1, 0), (0, -1)), ((0, 1), (-1, 0)),
      ((1, 0), (0, -1)), ((0, 1), (1, 0)), ((-1, 0), (0, 1)), ((0, -1), (-1, 0))]


# ---------------------------------------------------------------- inputs

def _q(num: int, den: int) -> str:
    g = math.gcd(num, den)
    num, den = num // g, den // g
    return str(num) if den == 1 else f"{num}/{den}"


def random_text(n: int, seed: int) -> str:
    rnd = random.Random(seed)
    return "".join(f"{rnd.randint(-10**6, 10**6)}/{rnd.randint(1, 1000)} "
                   f"{rnd.randint(-10**6, 10**6)}/{rnd.randint(1, 1000)}\n" for _ in range(n))


def d4_text(n: int, seed: int) -> str:
    """Orbits under D4 of n/8 generic rational seeds, about the centre (1/3, -2/7)."""
    rnd = random.Random(seed)
    seen, lines = set(), []
    while len(lines) < n:
        den = rnd.randint(1, 1000)
        x, y = rnd.randint(1, 10**6), rnd.randint(1, 10**6)
        if x == y or (x, y, den) in seen:
            continue
        seen.add((x, y, den))
        for (a, b), (c, d) in D4:
            px, py = a * x + b * y, c * x + d * y          # in units of 1/den
            lines.append(f"{_q(21 * px + 7 * den, 21 * den)} {_q(21 * py - 6 * den, 21 * den)}\n")
    return "".join(lines[:n])


def c7_polar_text(n: int, seed: int) -> str:
    """Orbits under C7 of n/7 polar seeds; turn denominators 7 * c near 10,000."""
    rnd = random.Random(seed)
    seen, lines = set(), []
    while len(lines) < n:
        q = 7 * rnd.randint(1400, 1460)
        a = rnd.randint(0, q // 7 - 1)
        r = (rnd.randint(1, 10**4), rnd.randint(1, 100))
        if (r[0] * 1000 // r[1], a * 100000 // q) in seen:
            continue
        seen.add((r[0] * 1000 // r[1], a * 100000 // q))
        for j in range(7):
            lines.append(f"polar {_q(*r)} {_q(a + j * (q // 7), q)}\n")
    return "".join(lines[:n])


CASES = {
    "random100k": ("100,000 random rational points", lambda: random_text(100_000, 7)),
    "d4": ("D4-symmetric, 100,000 rational", lambda: d4_text(100_000, 8)),
    "c7polar": ("C7-symmetric polar, 70,000", lambda: c7_polar_text(70_000, 9)),
    "random1m": ("1,000,000 random rational points", lambda: random_text(1_000_000, 10)),
}


# ---------------------------------------------------------------- the float pipeline

def _cluster(values: np.ndarray, tol: float) -> np.ndarray:
    """Integer labels, equal for values closer than ``tol`` to a neighbour in sorted order."""
    order = np.argsort(values, kind="stable")
    labels = np.empty(len(values), dtype=np.int64)
    labels[order] = np.cumsum(np.concatenate(([0], np.diff(values[order]) > tol)))
    return labels


def float_pipeline(path: Path) -> str:
    """Parse as floats, centroid, sort by atan2, rays and symbols up to a tolerance,
    period and mirrors by comparing rotated symbol arrays: the group name."""
    xs, ys = read_float_points(path)
    x, y = np.array(xs), np.array(ys)
    dx, dy = x - x.mean(), y - y.mean()
    r2 = dx * dx + dy * dy
    scale = r2.max()
    keep = r2 > 1e-18 * scale
    dx, dy, r2 = dx[keep], dy[keep], r2[keep] / scale
    angle = np.arctan2(dy, dx) % (2 * math.pi)
    order = np.lexsort((r2, angle))
    angle, r2 = angle[order], r2[order]
    new_ray = np.empty(len(angle), dtype=bool)
    new_ray[0] = True
    new_ray[1:] = np.diff(angle) > 1e-9
    starts = np.flatnonzero(new_ray)
    ray_angle = angle[starts]
    gaps = np.diff(np.append(ray_angle, ray_angle[0] + 2 * math.pi))
    r2_id = _cluster(r2, 1e-9)
    gap_id = _cluster(gaps, 1e-9)
    ray_r2 = [tuple(sorted(ids)) for ids in np.split(r2_id, starts[1:])]
    codes: dict = {}
    ccw = np.array([codes.setdefault((r, g), len(codes)) for r, g in zip(ray_r2, gap_id)])
    m = len(ccw)
    cw = np.array([codes.setdefault((ray_r2[-i % m], gap_id[(-i - 1) % m]), len(codes))
                   for i in range(m)])
    period = next(p for p in range(1, m + 1)
                  if m % p == 0 and np.array_equal(ccw, np.roll(ccw, -p)))
    mirror = any(np.array_equal(np.roll(ccw, -j), cw)
                 for j in np.flatnonzero(ccw[:period] == cw[0]))
    return f"{'D' if mirror else 'C'}{m // period}"


# ---------------------------------------------------------------- one case, in a child

def run_case(key: str) -> dict:
    from exactsym.geometry.configuration import load
    from exactsym.geometry.levels import levels_of
    from exactsym.truth.symmetry import symmetry_group

    path = Path(tempfile.mkdtemp()) / f"{key}.txt"
    path.write_text(CASES[key][1]())
    c0 = time.process_time()
    t0 = time.perf_counter()
    config = load(path)
    t1 = time.perf_counter()
    ring = levels_of(config)
    t2 = time.perf_counter()
    group = symmetry_group(config, ring)
    t3 = time.perf_counter()
    cpu = time.process_time() - c0
    f0 = time.process_time()
    float_group = float_pipeline(path)
    t4 = time.perf_counter()
    float_cpu = time.process_time() - f0
    return {"load": t1 - t0, "rings": t2 - t1, "symmetry": t3 - t2, "exact": t3 - t0, "cpu": cpu,
            "float": t4 - t3, "float_cpu": float_cpu, "group": group.name,
            "float_group": float_group,
            "rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}


def main(argv: list[str]) -> int:
    if len(argv) == 2 and argv[0] == "--child":
        print(json.dumps(run_case(argv[1])))
        return 0
    keys = [k for k in CASES if not ("--quick" in argv and k == "random1m")]
    print("seconds (wall clock; 'cpu' and 'fl cpu' are the CPU times of the exact truth and of "
          "the float yardstick, and 'cpu r.' their ratio, less sensitive to a busy machine)")
    print(f"{'input':<34}{'load':>7}{'rings':>7}{'sym':>7}{'exact':>8}{'cpu':>7}{'float':>7}"
          f"{'ratio':>7}{'sym/fl':>7}{'fl cpu':>7}{'cpu r.':>7}{'RSS MB':>8}  group   target")
    ok = True
    for key in keys:
        out = subprocess.run([sys.executable, __file__, "--child", key], capture_output=True,
                             text=True)
        if out.returncode != 0:
            print(f"{CASES[key][0]:<34} failed:\n{out.stderr}")
            ok = False
            continue
        r = json.loads(out.stdout)
        ratio = r["exact"] / r["float"]
        if key in ("random100k", "d4"):   # issue 9
            limit = 3 if key == "random100k" else 4
            met, target = ratio <= limit, f"ratio <= {limit}"
        elif key == "random1m":
            met, target = r["exact"] < 15 and r["rss_mb"] < 1536, "< 15 s, < 1.5 GB"
        else:
            met, target = True, "(timed)"
        ok &= met
        agree = "" if r["group"] == r["float_group"] else f" (float says {r['float_group']})"
        print(f"{CASES[key][0]:<34}{r['load']:>7.2f}{r['rings']:>7.2f}{r['symmetry']:>7.2f}"
              f"{r['exact']:>8.2f}{r['cpu']:>7.2f}{r['float']:>7.2f}{ratio:>7.1f}"
              f"{r['symmetry'] / r['float']:>7.1f}{r['float_cpu']:>7.2f}"
              f"{r['cpu'] / r['float_cpu']:>7.1f}"
              f"{r['rss_mb']:>8.0f}  {r['group']:<6}  {target}"
              f"{'' if target == '(timed)' else (': met' if met else ': MISSED')}{agree}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
