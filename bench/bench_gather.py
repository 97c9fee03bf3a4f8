"""Benchmark of the exact gathering simulator, against a float simulator of the same run in
the same process.  Run: ``python bench/bench_gather.py [--quick | --joint]`` (a few
minutes; ``--joint``: section 4 only; CPU time, so that other processes on the machine
change the figures less).

1. The cost of one Look as n grows, cache cleared: the paper's ``robot.decide`` (SEC,
   pattern recogniser, the paper layer's Preprocess / MakeAsym / ElectLeader,
   FormGPattern) and the corrected variant's ``decide_corrected`` on a random
   configuration, and the corrected variant on a complete pattern of n - 1 robots and
   one robot far out (the largest P: the costliest Look of a run).
2. Runs with every invariant on at n = 5, 30, 80 for both algorithms (centralised, and
   ASYNC at n = 30; default readings; at most 300 events, 600 for the corrected variant
   at n = 30 so that it gathers): events per second.
3. The float baseline: the same action sequence replayed with float positions, a float
   SEC, float segment/arc collision tests against every robot and a float "nearest robot
   to the SEC centre" leader per Look: what an epsilon-based simulator pays per event.
4. Joint steps (several robots moving at once): the critical instants of a step of two
   movers (``joint_instants.joint_look_points``: every family, symmetry included) and the
   whole check of the step (``Checker.after_step``: I1, then I3, I4, I6 and I9 at each
   instant), on random configurations at n = 5, 30 (two segments towards C; two arcs
   about C).  (Runs with every invariant on make no joint step: I2 stops the run at
   the second pending move.)
"""

from __future__ import annotations

import math
import random
import time
from fractions import Fraction

import sys

from exactsym.gathering import robot
from exactsym.gathering.corrected import decide_corrected
from exactsym.gathering.geometry import point
from exactsym.gathering.pattern import generate
from exactsym.gathering.invariants import Checker
from exactsym.gathering.robot import Readings
from exactsym.gathering.schedulers import run


def random_config(n: int, seed: int = 1, spread: int = 12):
    rng = random.Random(seed)
    pts = []
    while len(pts) < n:
        p = (Fraction(rng.randint(-spread * n, spread * n), rng.randint(1, 3)),
             Fraction(rng.randint(-spread * n, spread * n), rng.randint(1, 3)))
        if all((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 > 9 for q in pts):
            pts.append(p)
    return pts


def time_one_look(n: int, repeat: int = 3, decide=robot.decide, pts=None) -> float:
    pts = pts if pts is not None else tuple(point(*p) for p in random_config(n))
    best = math.inf
    for _ in range(repeat):
        decide.cache_clear()
        t = time.process_time()
        decide(pts, Readings())
        best = min(best, time.process_time() - t)
    return best


def pattern_and_one(n: int) -> tuple:
    """A complete pattern of n - 1 robots about the origin and one robot far out."""
    return tuple(generate(n - 1)) + (point(Fraction(7, 3), 9 * n),)


# -- the float baseline ----------------------------------------------------------------
def _fsec(pts):
    order = list(range(len(pts)))
    random.Random(len(pts)).shuffle(order)
    P = [pts[i] for i in order]

    def c2(a, b):
        cx, cy = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
        return cx, cy, (a[0] - cx) ** 2 + (a[1] - cy) ** 2

    def c3(a, b, c):
        bx, by, cx, cy = b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]
        d = 2 * (bx * cy - by * cx)
        if abs(d) < 1e-12:
            return max((c2(a, b), c2(a, c), c2(b, c)), key=lambda t: t[2])
        b2, cc2 = bx * bx + by * by, cx * cx + cy * cy
        ux, uy = (cy * b2 - by * cc2) / d, (bx * cc2 - cx * b2) / d
        return a[0] + ux, a[1] + uy, ux * ux + uy * uy

    def inside(c, p):
        return (p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2 <= c[2] * (1 + 1e-12)
    c = (P[0][0], P[0][1], 0.0)
    for i in range(1, len(P)):
        if inside(c, P[i]):
            continue
        c = (P[i][0], P[i][1], 0.0)
        for j in range(i):
            if inside(c, P[j]):
                continue
            c = c2(P[i], P[j])
            for k in range(j):
                if not inside(c, P[k]):
                    c = c3(P[i], P[j], P[k])
    return c


def _fseg_hits(a, b, q):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = dx * dx + dy * dy
    t = 0.0 if L == 0 else max(0.0, min(1.0, ((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / L))
    x, y = a[0] + t * dx - q[0], a[1] + t * dy - q[1]
    return x * x + y * y < 4 - 1e-9


def float_replay(points, actions) -> int:
    """Replay the action list with floats: per Look a float SEC and nearest robot and a
    radial target; per advance a collision test of the segment against every robot."""
    pos = [(float(x), float(y)) for x, y in points]
    target = {}
    hits = 0
    for act in actions:
        if act["a"] == "step":          # robots moving at once: each its own part
            for i, stop, _end in act["moves"]:
                goal = target.get(i, pos[i])
                f = 0.5 if stop else 1.0
                new = (pos[i][0] + f * (goal[0] - pos[i][0]),
                       pos[i][1] + f * (goal[1] - pos[i][1]))
                hits += sum(_fseg_hits(pos[i], new, q) for k, q in enumerate(pos) if k != i)
                pos[i] = new
            _fsec(pos)
            continue
        i = act["robot"]
        if act["a"] == "look":
            cx, cy, _ = _fsec(pos)
            d = [(p[0] - cx) ** 2 + (p[1] - cy) ** 2 for p in pos]
            lead = min(range(len(pos)), key=d.__getitem__)
            if lead == i and d[i] > 1e-9:
                s = 2 / math.sqrt(d[i])
                target[i] = (cx + (pos[i][0] - cx) * s, cy + (pos[i][1] - cy) * s)
                hits += sum(_fseg_hits(pos[i], target[i], q) for k, q in enumerate(pos)
                            if k != i)
        else:
            goal = target.get(i, pos[i])
            f = 0.5 if act.get("stop") else 1.0
            new = (pos[i][0] + f * (goal[0] - pos[i][0]), pos[i][1] + f * (goal[1] - pos[i][1]))
            hits += sum(_fseg_hits(pos[i], new, q) for k, q in enumerate(pos) if k != i)
            pos[i] = new
            _fsec(pos)              # the I6 check recomputes C
    return hits


def main() -> None:
    quick = "--quick" in sys.argv[1:]
    print("one Look (decide, cache cleared, CPU time) as n grows:")
    print("      n   paper (random)   corrected (random)   corrected (pattern of n-1 + 1)")
    for n in (5, 10, 20, 30, 50, 80):
        a = time_one_look(n)
        b = time_one_look(n, decide=decide_corrected)
        c = time_one_look(n, decide=decide_corrected, pts=pattern_and_one(n))
        print(f"  {n:5d}   {a * 1000:10.2f} ms   {b * 1000:14.2f} ms   {c * 1000:20.2f} ms")
    runs = [(5, "paper", "centralised", 300), (5, "corrected", "centralised", 300),
            (30, "paper", "centralised", 300), (30, "corrected", "centralised", 600),
            (30, "paper", "async", 300), (30, "corrected", "async", 600),
            (80, "paper", "centralised", 300), (80, "corrected", "centralised", 300)]
    if quick:
        runs = [r for r in runs if r[0] != 80]
    for n, algorithm, scheduler, cap in runs:
        pts = random_config(n)
        robot.decide.cache_clear()
        decide_corrected.cache_clear()
        t = time.process_time()
        res = run(pts, scheduler, 1, Readings(), max_events=cap, checker=Checker(),
                  algorithm=algorithm)
        exact = time.process_time() - t
        t = time.process_time()
        float_replay(pts, res.actions)
        flt = max(time.process_time() - t, 1e-6)
        checks = sum(res.checks.values())
        print(f"n = {n}, {algorithm}, {scheduler}, every invariant on: {res.outcome} "
              f"({res.label or '-'}) after {res.events} events ({res.looks} Looks, "
              f"{checks} invariant checks) in {exact:.2f} s = {res.events / exact:.0f} "
              f"events/s, {exact / max(res.looks, 1) * 1000:.1f} ms per Look (with its "
              f"checks); float replay {flt * 1000:.1f} ms ({res.events / flt:.0f} events/s); "
              f"ratio {exact / flt:.0f}x")


def joint_steps(n: int, arcs: bool, seed: int = 1):
    """``(world, pieces)``: the two robots nearest the SEC centre C of a random
    configuration move at once, half way to C along segments, or (``arcs``) along arcs
    about C by the rational rotation (24/25, 7/25); both with the C and R of a Look."""
    from exactsym.exact.multiquadratic import MQ
    from exactsym.gathering import geometry as g
    from exactsym.gathering.world import World
    w = World(random_config(n, seed), Readings())
    c = g.smallest_enclosing_circle(list(w.positions()))[0]
    order = sorted(range(n), key=lambda k: float(g.dist2(w.robots[k].pos, c)))
    pieces = {}
    for i in order[:2]:
        p = w.robots[i].pos
        if arcs:
            q = g.add(c, g.rotate(g.sub(p, c), MQ.rational(Fraction(24, 25)),
                                  MQ.rational(Fraction(7, 25))))
            pieces[i] = g.Arc(c, p, q, 1)
        else:
            pieces[i] = g.Segment(p, g.scale(g.add(p, c), MQ.rational(Fraction(1, 2))))
        w.robots[i].path, w.robots[i].centre = [pieces[i]], c
        w.robots[i].r_set = frozenset(range(n))
    return w, pieces


def time_joint(n: int, arcs: bool, repeat: int = 3) -> tuple:
    """CPU seconds (best of ``repeat``) of the critical instants of the step and of the
    whole after-step check (decisions cache cleared), and the number of instants."""
    from exactsym.gathering.invariants import ALL
    from exactsym.gathering.joint_instants import joint_look_points
    best_i = best_c = math.inf
    count = 0
    for _ in range(repeat):
        w, pieces = joint_steps(n, arcs)
        t = time.process_time()
        pts, sided = joint_look_points(pieces, w)
        best_i = min(best_i, time.process_time() - t)
        count = len(pts) + sided
        robot.decide.cache_clear()
        chk = Checker(enabled=frozenset(ALL) - {"I2"})
        t = time.process_time()
        chk.after_step(w, pieces)
        best_c = min(best_c, time.process_time() - t)
    return best_i, best_c, count


def bench_joint() -> None:
    print("joint steps (two movers; CPU time, best of 3):")
    print("      n   pieces    Looks   instants (joint_look_points)   after_step (I1, I3, "
          "I4, I6, I9)")
    for n in (5, 30):
        for arcs in (False, True):
            ti, tc, k = time_joint(n, arcs)
            print(f"  {n:5d}   {'arcs' if arcs else 'segments':8s} {k:5d}   "
                  f"{ti * 1000:21.1f} ms   {tc * 1000:24.1f} ms")


if __name__ == "__main__":
    if "--joint" in sys.argv[1:]:
        bench_joint()
    else:
        main()
        bench_joint()
