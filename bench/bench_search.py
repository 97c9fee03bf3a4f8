"""Benchmark of the searching adversary and of one exact event (issue 30's targets).

Run: ``python bench/bench_search.py [--quick | --full]`` (CPU time, so that other
processes on the machine change the figures less; ``--quick``: budget 2,000 and n = 8
only; ``--full``: the joint-step rows with the budget of 10,000 too, about 10 minutes at
n = 12).

1. ``gather --search`` with a budget of 10,000 states on random configurations of
   n = 8, 10, 12 robots (``bench_gather.random_config``), every invariant on, default
   readings; and the same under A3 = all with I2 and I9 off (several robots move at
   once: joint steps, the costliest states; budget 2,000 unless ``--full``).  Target:
   under 60 s CPU each.  Joint steps: n = 12, budget 2,000, 79.1 s before the stops of a
   joint motion shared its instants and verdicts (``invariants._covered_points``), 7.7 s
   after; with the budget of 10,000 the search goes deeper into states whose paper-layer
   decisions are made in Q(gamma) (``gathering/algebraic_kernel``), and took more than
   8 minutes at n = 12.  Since the strings of a polygon off one circle there hold their
   keys undivided (``paper/ratio_keys.chord_key``) and inverses are remembered per
   field, the first ~1,560 states of that run cost 105 s CPU under cProfile instead of
   270 s.  Then the stops of one joint motion were found to compute and check its
   instants again whenever an instant was a nested radical or a number of K(alpha)
   (``stops.motion_roots``, ``stops.covered_points``): one state's children at n = 12,
   112 s for 32 of them before, 14 s for all 84 after; the first 1,560 states at n = 12,
   84.6 s -> 28.6 s CPU (side by side); a K(alpha) snapshot is written in Q(gamma) by
   one linear solve.  Still far from the 60 s target with the budget of
   10,000 (docs/gathering.md, "The search": where the time goes).  ``PREVIOUS`` holds
   the figures of the run before, printed beside each row that has one.
2. One exact event at n = 30 (a Look with its invariant checks, or an advance along a
   piece with its checks at every critical instant): the median CPU time over an ASYNC
   run with every invariant on (``schedulers.run``, at most 300 events), against the
   float replay of the same actions (``bench_gather.float_replay``: what an epsilon-based
   simulator pays per event).  Target: at most 10 ms median.
"""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_gather import float_replay, random_config  # noqa: E402

from exactsym.gathering import robot  # noqa: E402
from exactsym.gathering.cases import settings_of  # noqa: E402
from exactsym.gathering.invariants import ALL, Checker  # noqa: E402
from exactsym.gathering.robot import Readings  # noqa: E402
from exactsym.gathering.schedulers import run  # noqa: E402
from exactsym.gathering.search import Bounds, search  # noqa: E402
from exactsym.gathering.world import World  # noqa: E402

SEVERAL = {"gather_readings": ["A3=all"],
           "gather_invariants": sorted(set(ALL) - {"I2", "I9"})}

#: CPU seconds of the previous run by (row, n, budget): the ratio printed beside a row
#: (default readings: docs/gathering.md's "after" column, the slowest figure;
#: joint steps at budget 10,000 -- before the shared instants of a joint motion's stops,
#: n = 8 more than 210 s, n = 12 more than 15.7 min (not finished); after, n = 8
#: 408.7 s (10,000 states, depth 16), n = 12 220.9 s (10,000 states, depth 6)
PREVIOUS = {("default", 8, 10_000): 9.0, ("default", 10, 10_000): 12.7,
            ("default", 12, 10_000): 11.7, ("joint", 12, 2000): 8.5,
            ("joint", 8, 10_000): 408.7, ("joint", 12, 10_000): 220.9}


def time_search(n: int, budget: int, expect: dict, seed: int = 1):
    """``(report, CPU seconds)`` of a search on ``random_config(n, seed)``."""
    settings = settings_of(expect)
    robot.decide.cache_clear()
    t = time.process_time()
    rep = search(random_config(n, seed), settings, Bounds(budget=budget, seconds=3600))
    return rep, time.process_time() - t


def event_times(n: int = 30, cap: int = 300, seed: int = 1):
    """``(result, [CPU seconds of each event])`` of an ASYNC run with every invariant on."""
    times: list = []
    originals = {name: getattr(World, name) for name in ("look", "advance",
                                                         "advance_together")}

    def timed(f):
        def wrapper(self, *args, **kw):
            if getattr(self, "_timing", False):          # advance_together -> advance
                return f(self, *args, **kw)
            self._timing = True
            t = time.process_time()
            try:
                return f(self, *args, **kw)
            finally:
                times.append(time.process_time() - t)
                self._timing = False
        return wrapper
    for name, f in originals.items():
        setattr(World, name, timed(f))
    try:
        robot.decide.cache_clear()
        res = run(random_config(n, seed), "async", seed, Readings(), max_events=cap,
                  checker=Checker())
    finally:
        for name, f in originals.items():
            setattr(World, name, f)
    return res, times


def main() -> None:
    quick = "--quick" in sys.argv[1:]
    budget = 2000 if quick else 10_000
    sizes = (8,) if quick else (8, 10, 12)
    print("search (CPU time; target: budget 10,000 under 60 s):")
    full = "--full" in sys.argv[1:]
    for row, label, expect, states in (
            ("default", "default readings, every invariant", {}, budget),
            ("joint", "A3=all, I2 and I9 off (joint steps)", SEVERAL,
             budget if full else 2000)):
        for n in sizes:
            rep, cpu = time_search(n, states, expect)
            before = PREVIOUS.get((row, n, states))
            ratio = "" if before is None else \
                f"; previous run {before:.1f} s: ratio {cpu / before:.2f}"
            print(f"  n = {n:2d}, {label}, budget {states}: {rep.states} states, {rep.expanded} expanded, "
                  f"depth {rep.depth}, {rep.stopped}, {cpu:.1f} s CPU "
                  f"({cpu / max(rep.states, 1) * 1000:.1f} ms a state){ratio}")
    res, times = event_times()
    t = time.process_time()
    float_replay(random_config(30, 1), res.actions)
    flt = max(time.process_time() - t, 1e-6) / max(len(times), 1)
    med = statistics.median(times)
    print(f"one exact event at n = 30 (ASYNC, every invariant on; {res.outcome} after "
          f"{res.events} events): median {med * 1000:.2f} ms, mean "
          f"{statistics.fmean(times) * 1000:.2f} ms, max {max(times) * 1000:.1f} ms; float "
          f"replay {flt * 1000:.3f} ms an event: ratio {med / flt:.0f}x (median against "
          f"mean); target: median at most 10 ms")


if __name__ == "__main__":
    main()
