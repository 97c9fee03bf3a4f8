"""The reading matrix (issue 30, point 4): one run per named reading of the paper.

The readings are the switches of :data:`.robot.READINGS` (``docs/interpretations.md``,
``docs/gathering.md``, "The robot (readings)").  The matrix has a row for the base reading
(the case's, by default every switch at its default), one row per other value of each
switch (the base with that one switch changed), a row for each switch that has a single
value (it is the base row's reading: not run again), and the two senses of the
handedness the paper leaves open (every Look in a frame of the plain handedness, or every
Look mirrored: the run on the configuration's mirror image, robots numbered alike), for
the base reading and for the other value of A3.  The other rows let the adversary give a
robot either handedness at each Look (the weak model's frames may change between
activations; the paper says only that each robot has "its own local coordinate system").

Each row is the adversary search (:func:`.search.search`, the row's share of the budget)
and, when it finds no violation, the case's seeded scheduler run: its outcome is
``violated`` (with the label and the shortest schedule found, shrunk), ``gathered``,
``stalled``, ``not-possible``, ``undecided`` (the kernel cannot hold a number), or
``undecided-at-budget`` (the seeded run reached its event limit).  :func:`reading_matrix`
returns plain data (the ledger grades statements from it).
"""

from __future__ import annotations

from fractions import Fraction

from .adversary import FRAMES
from .invariants import Checker
from .robot import READINGS, Readings
from .schedulers import run
from .search import Bounds, search

__all__ = ["reading_rows", "reading_matrix", "differs_from_base", "HANDEDNESS"]

#: the two senses of the observer's handedness: (row name, frames of the search, mirror
#: the configuration for the seeded run)
HANDEDNESS = (("hand=plain", tuple(f for f in FRAMES if not f.reflect), False),
              ("hand=mirrored", tuple(f for f in FRAMES if not f.reflect), True))


def reading_rows(base: dict) -> list:
    """``[(name, readings dict, frames or None, mirrored, same_as_base)]`` in table order."""
    rows = [("base", dict(base), None, False, False)]
    for switch, values in READINGS.items():
        if len(values) == 1:
            rows.append((f"{switch}={values[0]}", dict(base), None, False, True))
            continue
        for value in values:
            if value != base[switch]:
                rows.append((f"{switch}={value}", {**base, switch: value}, None, False,
                             False))
    for name, frames, mirrored in HANDEDNESS:
        rows.append((name, dict(base), frames, mirrored, False))
    # a robot keeping one handedness from Look to Look is a reading of the model (L210-214:
    # "its own local coordinate system"); the rows above allow it to change.  A3 decides
    # whether an epsilon move loops (in both senses it is a proved cycle, in one sense it is
    # not an exact repeat), so the fixed handedness is run under both values of A3
    for value in READINGS["A3"]:
        if value != base["A3"]:
            for name, frames, mirrored in HANDEDNESS:
                rows.append((f"A3={value}, {name}", {**base, "A3": value}, frames, mirrored,
                             False))
    return rows


def _mirror(points) -> list:
    return [(-x, y) for x, y in points]


def _seeded(points, settings: dict, readings: dict, reflections: bool):
    delta = settings.get("delta")
    return run(points, settings["scheduler"], settings["seed"], Readings(**readings),
               settings["rigid"], None if delta is None else Fraction(delta),
               settings["max_events"], Checker(enabled=frozenset(settings["invariants"])),
               reflections=reflections, algorithm=settings.get("algorithm", "paper"))


def _row(points, settings: dict, name, readings, frames, mirrored, bounds: Bounds) -> dict:
    pts = _mirror(points) if mirrored else points
    s = {**settings, "readings": readings}
    report = search(pts, s, bounds, frames if frames is not None else FRAMES)
    out = {"reading": name, "readings": readings, "mirrored": mirrored,
           "search": report.as_dict()}
    if report.result is not None:
        res = report.result
        out.update(outcome="violated", label=res.label,
                   invariant=res.violation["invariant"], robots=res.violation["robots"],
                   schedule=report.actions, length=len(report.actions), detail=res.detail)
        return out
    res = _seeded(pts, s, readings, reflections=frames is None)
    outcome = "undecided-at-budget" if res.outcome == "max-events" else res.outcome
    out.update(outcome=outcome, label=res.label,
               invariant=res.violation["invariant"] if res.violation else None,
               robots=res.violation["robots"] if res.violation else None,
               schedule=res.actions if res.outcome == "violated" else None,
               length=res.events, detail=res.detail)
    return out


def reading_matrix(points, settings: dict, bounds: Bounds = Bounds(budget=400),
                   progress=None) -> list:
    """One dict per row of :func:`reading_rows` (keys: ``reading``, ``readings``,
    ``mirrored``, ``outcome``, ``label``, ``invariant``, ``robots``, ``schedule`` (the
    violating actions, or None), ``length`` (actions of the schedule, or events of the
    seeded run), ``detail``, ``search`` (:meth:`.search.SearchReport.as_dict`),
    ``same_as`` (for a single-valued switch: ``"base"``)); ``bounds`` apply per row;
    ``progress``: called with ``(done, total, name)`` before each row."""
    rows, base_row = [], None
    table = list(reading_rows(settings["readings"]))
    for k, (name, readings, frames, mirrored, same) in enumerate(table):
        if progress is not None:
            progress(k, len(table), name)
        if same:
            rows.append({**base_row, "reading": name, "same_as": "base"})
            continue
        row = _row(points, settings, name, readings, frames, mirrored, bounds)
        row["same_as"] = None
        if name == "base":
            base_row = row
        rows.append(row)
    return rows


def differs_from_base(rows: list) -> list:
    """The rows whose outcome (and violated label) differ from the base row's."""
    base = rows[0]
    return [r for r in rows[1:] if (r["outcome"], r["label"]) != (base["outcome"], base["label"])]
