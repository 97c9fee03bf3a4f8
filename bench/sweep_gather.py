"""Sweep: where each gathering algorithm gathers and where not.

Random separated rational configurations (``bench_gather.random_config``, seeded), n = 5..12,
under the four schedulers, every invariant on, for the paper's algorithm (default
readings, and A3=all with EL=unordered) and for the corrected variant
(``exactsym.gathering.corrected``); and the paper's algorithm with A3=all, EL=unordered
and I2 (one pending move) off, so that runs go on with several robots moving at once and
show whether they collide (I1 over the joint motion).  Prints one table row per
algorithm and scheduler: gathered, violated (by label), stalled, not possible, other
(undecided, max-events), how many runs had robots moving at once, and how many of those
a violation stopped at an instant inside such a step.

Run: ``python bench/sweep_gather.py [--seeds K] [--n 5-12] [--setting K ...] [--json OUT]``
(the default, 3 seeds: 384 runs, some fifteen minutes on one core; ``--setting`` splits
them over processes; the table is in docs/gathering.md).
"""

from __future__ import annotations

import argparse
import collections
import json
import time

from bench_gather import random_config

from exactsym.gathering.invariants import ALL, Checker
from exactsym.gathering.robot import Readings
from exactsym.gathering.schedulers import SCHEDULERS, run

SETTINGS = (("paper", "paper (default readings)", Readings(), ALL),
            ("paper", "paper (A3=all, EL=unordered)", Readings(A3="all", EL="unordered"), ALL),
            ("paper", "paper (A3=all, EL=unordered), I2 off",
             Readings(A3="all", EL="unordered"), tuple(k for k in ALL if k != "I2")),
            ("corrected", "corrected", Readings(), ALL))


def sweep(ns, seeds: int, max_events: int = 3000, settings=SETTINGS):
    rows: dict = {}
    failures: list = []
    for algorithm, title, readings, invariants in settings:
        for scheduler in SCHEDULERS:
            tally: collections.Counter = collections.Counter()
            for n in ns:
                for seed in range(seeds):
                    res = run(random_config(n, seed=seed + 100 * n), scheduler, seed, readings,
                              max_events=max_events, algorithm=algorithm,
                              checker=Checker(enabled=frozenset(invariants)))
                    key = res.outcome if res.outcome != "violated" else f"violated {res.label}"
                    tally[key] += 1
                    steps = {k + 1 for k, a in enumerate(res.actions) if a["a"] == "step"}
                    tally["~together"] += bool(steps)
                    # the run's violation at an instant inside a step of several movers
                    tally["~inside"] += bool(res.violation) and res.violation["instant"] in steps
                    for key in ("instants", "nested", "algebraic", "sided", "skipped"):
                        tally["~" + key] += res.checks.get(key, 0)
                    if algorithm == "corrected" and res.outcome != "gathered":
                        failures.append({"n": n, "seed": seed, "scheduler": scheduler,
                                         "outcome": res.outcome, "label": res.label,
                                         "detail": res.detail[:200]})
            rows[(title, scheduler)] = tally
    return rows, failures


def table(rows) -> str:
    lines = ["| algorithm | scheduler | runs | gathered | violated (label: count) | stalled "
             "| not possible | other | moving at once | violated inside such a step |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for (title, scheduler), tally in rows.items():
        viol = ", ".join(f"{k[9:]}: {v}" for k, v in sorted(tally.items())
                         if k.startswith("violated"))
        other = sum(v for k, v in tally.items() if k not in ("gathered", "stalled",
                    "not-possible") and not k.startswith(("violated", "~")))
        runs = sum(v for k, v in tally.items() if not k.startswith("~"))
        lines.append(f"| {title} | {scheduler} | {runs} | "
                     f"{tally['gathered']} | {viol or '-'} | {tally['stalled']} | "
                     f"{tally['not-possible']} | {other} | {tally['~together']} | "
                     f"{tally['~inside']} |")
    lines += ["", "Fresh Looks at and between critical instants (nested: at nested radicals; "
              "algebraic: at roots of cubic or quartic factors; sided: instants seen on both "
              "sides only; skipped: Looks the kernel could not hold):", ""]
    for (title, scheduler), tally in rows.items():
        lines.append(f"- {title}, {scheduler}: " + ", ".join(
            f"{k} {tally['~' + k]}" for k in ("instants", "nested", "algebraic", "sided",
                                              "skipped")))
    return "\n".join(lines)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--n", default="5-12", help="a range a-b of robot counts")
    ap.add_argument("--setting", type=int, action="append", default=None,
                    help="only these rows of SETTINGS (0-3; repeatable), e.g. to split the "
                    "sweep over several processes")
    ap.add_argument("--json", default=None, help="also write the tallies and the corrected "
                    "variant's failures as JSON")
    args = ap.parse_args()
    lo, hi = (int(x) for x in args.n.split("-"))
    start = time.perf_counter()
    settings = [SETTINGS[k] for k in args.setting] if args.setting else SETTINGS
    rows, failures = sweep(range(lo, hi + 1), args.seeds, settings=settings)
    print(table(rows))
    for f in failures:
        print(f"corrected, not gathered: {f}")
    print(f"{sum(v for t in rows.values() for k, v in t.items() if not k.startswith('~'))} runs in "
          f"{time.perf_counter() - start:.0f} s")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as fh:
            json.dump({"rows": [{"algorithm": t, "scheduler": s, "tally": dict(v)}
                                for (t, s), v in rows.items()], "failures": failures},
                      fh, indent=1)


if __name__ == "__main__":
    main()
