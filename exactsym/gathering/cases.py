"""Gathering expectations of case files (``cases/gathering/``).

``[expect]`` keys read here (validated by :data:`exactsym.io.fileformat.EXPECT_KEYS`):

* ``gather_outcome`` -- gathered | stalled | violated | not-possible | undecided | undecided-at-budget | max-events;
* ``gather_label`` -- the violated statement's label (``gather-no-obstacle``, ...);
* ``gather_invariant`` -- the invariant that fires (``I1`` ... ``I10``);
* ``gather_robots`` -- the robots the violation names (e.g. the colliding pair);
* ``gather_time`` -- the instant inside the violation's piece or step (exact text, in
  [0, 1]) when it is seen at a critical instant of a motion (``Violation.time``);
* the run's setting, so the expectation is reproducible: ``gather_scheduler``,
  ``gather_seed``, ``gather_readings`` (``["A3=all", ...]``), ``gather_invariants``
  (the invariants checked; default all), ``gather_max_events``, ``gather_non_rigid``
  (delta, an expression string; absent: rigid), ``gather_mid_run`` (true: the points are a
  state inside a run, robots of a partial pattern touch; not the paper's separated start),
  ``gather_algorithm`` (``paper``, the
  default, or ``corrected``).
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from .invariants import ALL, Checker
from .paper_bridge import read_case
from .robot import Readings
from .schedulers import Result, run
from .start_numbers import certified

#: The keys compared with a run (the others, :data:`SETTING_KEYS`, set the run up).
CHECKED_KEYS = ("gather_outcome", "gather_label", "gather_invariant", "gather_robots",
                "gather_time")
SETTING_KEYS = ("gather_scheduler", "gather_seed", "gather_readings", "gather_invariants",
                "gather_max_events", "gather_non_rigid", "gather_algorithm", "gather_mid_run")


@dataclass(frozen=True)
class CaseRun:
    path: str
    result: Result
    failures: tuple


def settings_of(expect: dict) -> dict:
    delta = expect.get("gather_non_rigid")
    return {"scheduler": expect.get("gather_scheduler", "async"),
            "seed": int(expect.get("gather_seed", 0)),
            "readings": Readings.parse(expect.get("gather_readings", ())).as_dict(),
            "invariants": list(expect.get("gather_invariants", ALL)),
            "max_events": int(expect.get("gather_max_events", 2000)),
            "rigid": delta is None, "delta": None if delta is None else str(Fraction(delta)),
            "algorithm": expect.get("gather_algorithm", "paper")}


def run_settings(points, settings: dict, progress: bool = False) -> Result:
    """The run ``settings`` describe from ``points``.  From a start beyond the rationals
    and square roots (nested radicals, numbers of K(alpha): :mod:`.start_numbers`) a
    ``gathered`` or ``stalled`` that rests on critical instants seen on both sides only
    is ``undecided`` (:func:`.start_numbers.certified`)."""
    delta = settings.get("delta")
    res = run(points, settings["scheduler"], settings["seed"],
              Readings(**settings["readings"]), settings["rigid"],
              None if delta is None else Fraction(delta), settings["max_events"],
              Checker(enabled=frozenset(settings["invariants"])), progress,
              algorithm=settings.get("algorithm", "paper"))
    res = certified(res, points)
    return res


def expectation_failures(expect: dict, res: Result) -> list:
    out = []
    got = dict(zip(CHECKED_KEYS, (
        res.outcome, res.label, res.violation["invariant"] if res.violation else None,
        sorted(res.violation["robots"]) if res.violation else None,
        res.violation.get("time") if res.violation else None)))
    for key, value in got.items():
        if key in expect:
            want = sorted(expect[key]) if key == "gather_robots" else expect[key]
            if want != value:
                out.append(f"[expect] {key} = {expect[key]!r} is false: the simulator finds "
                           f"{value!r} ({res.detail})")
    return out


def run_case_file(path) -> CaseRun:
    points, _name, expect, source = read_case(path)
    res = run_settings(points, settings_of(expect))
    return CaseRun(str(path), res, tuple(expectation_failures(expect, res)))
