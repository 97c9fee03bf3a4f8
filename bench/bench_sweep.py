"""Benchmark of sweeps: configurations per second per worker, speed-up on Dask, projection.

Run: ``python bench/bench_sweep.py`` (about a minute on two cores; ``--quick`` skips the
Dask part).  Prints

1. for each family and analysis, configurations per second in one process (the serial
   loop ``job.analyse_batch`` over the family's items: what one worker does);
2. the speed-up of ``run_sweep`` on a LocalCluster of 1 and 2 workers against that serial
   loop over the same configurations, in the same process (the cluster is started before
   the clock, as a long sweep amortises it);
3. the enumeration rate of the canonical generator for roots:60 with 10 robots, and the
   projected time of ``roots:60:<=10 --what audit`` on 100 workers: the number of classes
   (Burnside) times the mean time per configuration measured on random samples of each
   robot count (weighted by the count of each), divided by 100 workers and by the
   measured 2-worker efficiency.
"""

from __future__ import annotations

import random
import sys
import tempfile
import time
from itertools import islice
from pathlib import Path

from exactsym.sweeps.canonical import burnside_count, dihedral_permutations, gap_bracelets
from exactsym.sweeps.engine import SweepOptions, run_sweep
from exactsym.sweeps.families import SweepItem, family_items, parse_family
from exactsym.sweeps.job import analyse_batch

FAMILIES = ["roots:12:<=6", "grid:4:<=4", "random:3..6:1:150"]
WHATS = ["truth", "paper", "audit"]


def serial_rate(items: list, what: str) -> tuple[float, float]:
    start = time.perf_counter()
    analyse_batch(items, what)
    seconds = time.perf_counter() - start
    return len(items) / seconds, seconds


def _sample_item(m: int, k: int, rng: random.Random) -> SweepItem:
    from fractions import Fraction
    positions = sorted(rng.sample(range(m), k))
    j0 = positions[0]
    points = tuple(("polar", "1", str(Fraction(j - j0, m))) for j in positions)
    return SweepItem(f"sample:{positions}", k, m, m, points)


def projection(efficiency: float) -> None:
    m, kmax, workers = 60, 10, 100
    perms = dihedral_permutations(m)
    counts = {k: burnside_count(perms, k) for k in range(1, kmax + 1)}
    total = sum(counts.values())
    start = time.perf_counter()
    enumerated = sum(1 for _ in islice(gap_bracelets(m, kmax), 100_000))
    enum_us = (time.perf_counter() - start) / enumerated * 1e6
    rng = random.Random(60)
    mean = 0.0
    for k in range(1, kmax + 1):
        sample = [_sample_item(m, k, rng) for _ in range(6)]
        _, seconds = serial_rate(sample, "audit")
        mean += counts[k] / total * seconds / len(sample)
    compute = total * mean / (workers * efficiency)
    enum_total = total * enum_us / 1e6
    print(f"\nroots:60:<=10: {total:,} classes (Burnside); audit {mean * 1e3:.1f} ms per "
          f"configuration (weighted sample); enumeration {enum_us:.1f} us per class")
    print(f"projected on {workers} workers at {efficiency:.0%} efficiency: "
          f"{compute / 3600:,.1f} h of analysis; the client's enumeration alone "
          f"{enum_total / 3600:,.1f} h on one core (it runs alongside)")
    print(f"projected wall time: {max(compute, enum_total) / 3600:,.1f} h")


def main(argv: list[str]) -> None:
    quick = "--quick" in argv
    print("configurations per second per worker (serial loop in this process)")
    print(f"{'family':<22}{'classes':>8}" + "".join(f"{w:>10}" for w in WHATS))
    for text in FAMILIES:
        family = parse_family(text)
        items = list(family_items(family))
        rates = [serial_rate(items, what)[0] for what in WHATS]
        print(f"{text:<22}{len(items):>8}" + "".join(f"{r:>10.1f}" for r in rates))
    efficiency = 1.0
    if not quick:
        from distributed import LocalCluster
        text, what = "roots:20:<=6", "audit"
        family = parse_family(text)
        items = list(family_items(family))
        base_rate, base = serial_rate(items, what)
        print(f"\n{text} --what {what}: {len(items)} configurations; serial loop "
              f"{base:.2f} s ({base_rate:.0f}/s)")
        timings = {}
        for workers in (1, 2):
            with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                              dashboard_address=None) as cluster:
                with tempfile.TemporaryDirectory() as tmp:
                    out = Path(tmp) / "r.jsonl"
                    start = time.perf_counter()
                    run = run_sweep(family, what, out,
                                    options=SweepOptions(scheduler=cluster.scheduler_address))
                    whole = time.perf_counter() - start
            timings[workers] = run.seconds
            print(f"  Dask, {workers} worker(s): {run.seconds:.2f} s from the first batch "
                  f"({whole:.2f} s with connecting and warming the workers), {run.batches} "
                  f"batches, workers analysing {run.utilisation:.0%} of the time; "
                  f"speed-up {base / run.seconds:.2f}x over the serial loop")
        efficiency = min(1.0, base / timings[2] / 2)
        print(f"  1 -> 2 workers: {timings[1] / timings[2]:.2f}x "
              f"(2-worker efficiency {efficiency:.0%}; this machine's 2 cores also run the "
              "client, the scheduler and other jobs)")
    projection(efficiency)


if __name__ == "__main__":
    main(sys.argv[1:])
