"""A gathering sweep's summary as evidence for a claim (``{gather_sweep = FILE}``).

``proofs/sweeps/gather_corrected.py table`` writes ``proofs/sweeps/gather_corrected.json``:
the corrected algorithm under the searching adversary on every configuration of a plan
of family chunks (``docs/sweeps.md``).  :func:`load_gather_sweep` validates it (counts
are counts, the classes add up to the configurations, the failures are the classes that
count against the claim plus the errors, what ran is at most what was planned);
:func:`grade_problems` says whether a grade follows from it:

* **failures** (a violation, a stall, an undecided run, not possible on a start with a
  leader, a run stopped at its event limit, an error): never ``proved`` or
  ``holds-on-cases``; ``refuted`` only when a violation, a stall or a not-possible with a
  leader is among them (an undecided run or an error refutes nothing);
* **no failure, every planned configuration run**: ``holds-on-cases`` (or ``open``), never
  ``refuted`` or ``proved`` (a sweep proves nothing);
* **no failure, part of the plan run**: ``open`` only -- the claim is about the plan.

The script's own ``check()`` (a ``{script = ...}`` evidence beside it) recomputes the
summary from the committed results files.
"""

from __future__ import annotations

import json
from pathlib import Path

__all__ = ["GatherSweepError", "load_gather_sweep", "grade_problems", "counterexamples",
           "CLASSES", "FAILING"]

#: the classes of a start's outcome (``exactsym.sweeps.gather_table.CLASSES``, kept here
#: as data: the ledger does not import the sweep)
CLASSES = ("gathered", "no-leader", "not-possible-with-leader", "violated", "stalled",
           "undecided", "other")
#: the classes that count against the claim; the first three refute it
FAILING = ("violated", "stalled", "not-possible-with-leader", "undecided", "other")
REFUTING = FAILING[:3]


class GatherSweepError(ValueError):
    """A gathering sweep summary that is malformed."""


def _count(value, what: str) -> int:
    if not isinstance(value, int) or isinstance(value, bool) or value < 0:
        raise GatherSweepError(f"{what} must be a count (a non-negative integer)")
    return value


def _check_tally(t, where: str) -> dict:
    if not isinstance(t, dict):
        raise GatherSweepError(f"{where}: no tally")
    total = _count(t.get("configurations"), f"{where}: configurations")
    parts = sum(_count(t.get(c), f"{where}: {c}") for c in CLASSES)
    if parts != total:
        raise GatherSweepError(f"{where}: the classes add up to {parts}, not {total}")
    _count(t.get("errors"), f"{where}: errors")
    return t


def load_gather_sweep(path) -> dict:
    """The summary at ``path``, validated (:class:`GatherSweepError` otherwise)."""
    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
    except ValueError as err:
        raise GatherSweepError(f"not JSON: {err}") from None
    if not isinstance(data, dict) or data.get("format") != 1:
        raise GatherSweepError("a gathering sweep summary is one JSON object of format 1")
    planned = _count(data.get("planned"), "planned")
    ran = _count(data.get("ran"), "ran")
    if ran > planned:
        raise GatherSweepError(f"ran {ran} of {planned} planned configurations")
    chunks = data.get("chunks")
    if not isinstance(chunks, list) or not chunks:
        raise GatherSweepError("a gathering sweep summary lists its chunks")
    for c in chunks:
        if c.get("ran"):
            _check_tally(c.get("tally"), f"chunk {c.get('chunk')}")
    total = _check_tally((data.get("total") or {}).get("tally"), "total")
    want = sum(total[c] for c in FAILING) + total["errors"]
    if data["total"].get("failures") != want:
        raise GatherSweepError(f"total failures {data['total'].get('failures')!r}, the "
                               f"counts say {want}")
    if total["configurations"] + total["errors"] != ran:
        raise GatherSweepError("the total's configurations and errors are not what ran")
    return data


def counterexamples(data: dict) -> int:
    """Starts whose outcome refutes the claim (violated, stalled, not possible with a
    leader)."""
    return sum(data["total"]["tally"][c] for c in REFUTING)


def grade_problems(grade: str, data: dict) -> list[str]:
    """Why ``grade`` does not follow from the summary ``data`` (empty: it does)."""
    failures, ran, planned = data["total"]["failures"], data["ran"], data["planned"]
    said = (f"{failures:,} failures on {ran:,} of {planned:,} planned configurations "
            f"({counterexamples(data):,} refuting)")
    if failures:
        if grade in ("proved", "holds-on-cases"):
            return [f"the sweep finds {said}: grade {grade!r} must change"]
        if grade == "refuted" and not counterexamples(data):
            return [f"'refuted' needs a violation, a stall or a not-possible start with a "
                    f"leader; the sweep finds {said}"]
        return []
    if grade in ("refuted", "proved"):
        return [f"a sweep without failures ({said}) backs neither 'refuted' nor 'proved'"]
    if grade == "holds-on-cases" and ran < planned:
        return [f"only part of the plan ran ({said}): 'open' until every planned "
                "configuration has"]
    return []
