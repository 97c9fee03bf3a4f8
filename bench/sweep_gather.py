"""Sweep: the paper's algorithm on random separated rational configurations (n = 5..10,
six each) under a seeded ASYNC adversary, every invariant on, for the default readings
and for A3=all with EL=unordered; prints how the runs end.
Run: ``python bench/sweep_gather.py`` (about two minutes)."""

from __future__ import annotations

import collections
import time

from bench_gather import random_config

from exactsym.gathering.robot import Readings
from exactsym.gathering.schedulers import run


def main() -> None:
    tally: collections.Counter = collections.Counter()
    start = time.perf_counter()
    for readings in (Readings(), Readings(A3="all", EL="unordered")):
        for n in (5, 6, 7, 8, 10):
            for seed in range(6):
                res = run(random_config(n, seed=seed + 100 * n), "async", seed, readings,
                          max_events=400)
                why = res.label if res.outcome == "violated" else res.detail.split("(")[0][:48]
                tally[(f"A3={readings.A3} EL={readings.EL}", res.outcome, why)] += 1
    for key, count in sorted(tally.items()):
        print(f"{count:3d}  {' | '.join(key)}")
    print(f"{sum(tally.values())} runs in {time.perf_counter() - start:.0f} s")


if __name__ == "__main__":
    main()
