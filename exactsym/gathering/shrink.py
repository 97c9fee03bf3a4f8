"""Shrinking a violating schedule: delta debugging over its actions (Zeller's ddmin).

A schedule found by the search (:mod:`.search`) may hold actions the violation does not
need (a Look of a robot that then stays far away, a move of a bystander).  :func:`shrink`
drops chunks of actions -- halves, then quarters, ... then single actions -- keeping a
candidate when its replay still violates the same invariant; a candidate that cannot be
applied (a robot advancing without a pending move) is simply not kept.  Every verdict is
a full exact replay (:func:`.schedulers.run` with the actions), so the shrunk schedule
is a trace that ``replay`` reproduces.
"""

from __future__ import annotations

from fractions import Fraction

from .invariants import Checker
from .robot import Readings
from .schedulers import Result, TraceMismatch, run

__all__ = ["replay_actions", "shrink"]


def replay_actions(points, settings: dict, actions: list) -> Result:
    """The run of ``actions`` on ``points`` under ``settings`` (raises
    :class:`.schedulers.TraceMismatch` for an action that cannot be applied)."""
    delta = settings.get("delta")
    return run(points, readings=Readings(**settings["readings"]),
               rigid=settings.get("rigid", True),
               delta=None if delta is None else Fraction(delta),
               max_events=len(actions) + 1,
               checker=Checker(enabled=frozenset(settings["invariants"])),
               actions=actions, algorithm=settings.get("algorithm", "paper"))


def _violates(points, settings, actions, invariant) -> list | None:
    """The actions up to the violation when ``actions`` violate ``invariant``."""
    try:
        res = replay_actions(points, settings, actions)
    except TraceMismatch:
        return None
    if res.outcome == "violated" and res.violation["invariant"] == invariant:
        return res.actions
    return None


def shrink(points, settings: dict, actions: list, max_replays: int = 200) -> tuple:
    """``(shorter actions, replays made)``: a schedule no longer than ``actions`` that
    violates the same invariant, from which no single action can be dropped (when the
    replay budget allows)."""
    try:
        first = replay_actions(points, settings, actions)
    except TraceMismatch:
        return list(actions), 1
    if first.outcome != "violated":
        return list(actions), 1
    invariant = first.violation["invariant"]
    best, replays, chunks = list(first.actions), 1, 2
    while len(best) >= 2 and replays < max_replays:
        size = max(1, len(best) // chunks)
        dropped = False
        for start in range(0, len(best), size):
            if replays >= max_replays:
                break
            candidate = best[:start] + best[start + size:]
            replays += 1
            got = _violates(points, settings, candidate, invariant) if candidate else None
            if got is not None:
                best, dropped = got, True
                chunks = max(chunks - 1, 2)
                break
        if not dropped:
            if size == 1:
                break
            chunks = min(chunks * 2, len(best))
    return best, replays
