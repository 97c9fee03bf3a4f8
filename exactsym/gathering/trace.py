"""Trace files: a run's adversary choices as JSON, and their exact replay.

A trace holds the starting points (exact rationals as strings), the run's settings
(scheduler, seed, readings, rigidity, the invariants checked), every adversary action in
order (``look`` with its frame, ``advance`` with its stop -- a fraction, or an exact
critical instant recorded by its index and an isolating interval, :mod:`.stops` -- and
end flag, ``step`` with one such triple per mover) and the
result the run reported.  :func:`replay` applies the actions to the same points and
returns the new result; :func:`same_result` says whether the two agree event for event
(outcome, number of events and Looks, invariant counts, violation).
"""

from __future__ import annotations

import json
from fractions import Fraction

from .invariants import ALL, Checker
from .robot import Readings
from .schedulers import Result, TraceMismatch, run
from .start_numbers import certified

FORMAT = "exactsym-gather-trace"
VERSION = 1


def result_dict(res: Result) -> dict:
    return {"outcome": res.outcome, "label": res.label, "detail": res.detail,
            "events": res.events, "looks": res.looks, "checks": res.checks,
            "violation": res.violation, "pattern": res.pattern}


def trace_dict(points, res: Result, settings: dict, name: str | None = None) -> dict:
    """``name``: what the run is called in pictures (the case file's name)."""
    return {"format": FORMAT, "version": VERSION, "name": name,
            "points": [[point_text(x), point_text(y)] for x, y in points],
            "settings": settings, "actions": res.actions, "result": result_dict(res)}


def point_text(v) -> str:
    """A start coordinate as the trace writes it: a rational as a fraction, any other
    number (an algebraic start, ``start_numbers``) as its exact text."""
    try:
        return str(Fraction(str(v)))
    except ValueError:
        return v.text()


def write_trace(path, points, res: Result, settings: dict, name: str | None = None) -> None:
    with open(path, "w", encoding="utf-8") as fh:
        json.dump(trace_dict(points, res, settings, name), fh, indent=1)
        fh.write("\n")


def read_trace(path) -> dict:
    """Raises :class:`TraceMismatch` for a file that is not a readable trace."""
    try:
        with open(path, encoding="utf-8") as fh:
            data = json.load(fh)
    except (OSError, json.JSONDecodeError) as err:
        raise TraceMismatch(f"{path}: not a readable trace ({err})") from None
    if not isinstance(data, dict) or data.get("format") != FORMAT or \
            data.get("version") != VERSION:
        raise TraceMismatch(f"{path}: not an {FORMAT} file of version {VERSION}")
    for key in ("points", "settings", "actions", "result"):
        if key not in data:
            raise TraceMismatch(f"{path}: the trace has no {key!r}")
    return data


def trace_points(data: dict) -> list:
    try:
        return [(Fraction(x), Fraction(y)) for x, y in data["points"]]
    except (ValueError, TypeError, ZeroDivisionError) as err:
        raise TraceMismatch(f"trace points are not exact rationals ({err}); a trace of an "
                            "algebraic start replays with its file: replay TRACE FILE") from None


def replay(data: dict, points=None) -> Result:
    """Re-run the trace's actions; ``points`` (from a configuration file) must equal the
    trace's own points (else :class:`TraceMismatch`)."""
    if points is not None:
        if [[point_text(x), point_text(y)] for x, y in points] != data["points"]:
            raise TraceMismatch("the trace was recorded on other starting points than the "
                                "file's")
        own = list(points)
    else:
        own = trace_points(data)
    s = data["settings"]
    try:
        readings = Readings(**s.get("readings", {}))
        enabled = frozenset(s.get("invariants", ALL))
        delta = None if s.get("delta") is None else Fraction(s["delta"])
        if s.get("algorithm", "paper") not in ("paper", "corrected"):
            raise ValueError(f"unknown algorithm {s.get('algorithm')!r}")
    except (TypeError, ValueError) as err:
        raise TraceMismatch(f"trace settings are unusable ({err})") from None
    return certified(run(own, readings=readings, rigid=s.get("rigid", True), delta=delta,
                         max_events=int(s.get("max_events", 10 ** 9)),
                         checker=Checker(enabled=enabled), actions=data["actions"],
                         algorithm=s.get("algorithm", "paper")), own)


def same_result(recorded: dict, res: Result) -> list:
    """The keys on which a replay differs from the recorded result (empty: identical)."""
    now = result_dict(res)
    diff = [k for k in ("outcome", "label", "events", "looks", "checks", "violation")
            if recorded.get(k) != now.get(k)]
    if now["outcome"] == "stopped" and recorded.get("outcome") in ("max-events", "stalled", "undecided-at-budget"):
        diff = [k for k in diff if k != "outcome"]   # scheduler-level verdicts, not events
    return diff
