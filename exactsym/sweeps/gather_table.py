"""The gathering sweep's tables: per family chunk and per robot count (issue 31).

A results file of ``exactsym sweep gather:EVENTS+STATES:FAMILY --what gather-corrected``
(:mod:`.results`) holds one record per start with ``gather.class`` (the searching
adversary's verdict, :func:`.analysis_bridge._adversary`).  :func:`tally` counts one file:
configurations, and per class (gathered, no leader, not possible with a leader, violated,
stalled, undecided, other), errors, starts whose search could not run, and the events of
the gathered runs; :func:`merge` adds tallies; :func:`events_by_n` gives the median and
maximum events to gather per robot count.  Each configuration is counted once (its
enumeration index).  Plain data in, plain data out: the script
``proofs/sweeps/gather_corrected.py`` writes the tables.
"""

from __future__ import annotations

from statistics import median

from .results import IndexSet, read_header, read_records

__all__ = ["CLASSES", "tally", "merge", "events_by_n", "median_events", "failures"]

#: the classes of ``gather.class``, in table order (docs/sweeps.md)
CLASSES = ("gathered", "no-leader", "not-possible-with-leader", "violated", "stalled",
           "undecided", "other")


def _empty(family: str) -> dict:
    return {"family": family, "configurations": 0, "errors": 0, "search_errors": 0,
            **{c: 0 for c in CLASSES}, "labels": {}, "events": {}}


def tally(path) -> dict:
    """The counts of one results file (see the module docstring); ``events`` maps a robot
    count (as text, JSON's keys) to the sorted events of its gathered runs."""
    head = read_header(path)
    if head is None:
        raise ValueError(f"{path}: not a sweep results file")
    out = _empty(head["family"])
    seen = IndexSet()
    for record in read_records(path):
        if not seen.add(record["index"]):
            continue
        if record["status"] != "ok":
            out["errors"] += 1
            continue
        g = record.get("gather") or {}
        kind = g.get("class")
        if kind is None:                       # fewer than 5 robots: not applicable
            continue
        out["configurations"] += 1
        out[kind] += 1
        if (g.get("search") or {}).get("stopped") == "error":
            out["search_errors"] += 1
        if kind == "violated":
            out["labels"][g["label"]] = out["labels"].get(g["label"], 0) + 1
        if kind == "gathered":
            out["events"].setdefault(str(record["n"]), []).append(g["events"])
    for v in out["events"].values():
        v.sort()
    return out


def merge(tallies, family: str = "all") -> dict:
    """The sum of several tallies."""
    out = _empty(family)
    for t in tallies:
        for key in ("configurations", "errors", "search_errors", *CLASSES):
            out[key] += t[key]
        for label, k in t["labels"].items():
            out["labels"][label] = out["labels"].get(label, 0) + k
        for n, v in t["events"].items():
            out["events"].setdefault(n, []).extend(v)
    for v in out["events"].values():
        v.sort()
    return out


def median_events(t: dict):
    """The median events of the gathered runs of a tally (None when none gathered)."""
    every = [e for v in t["events"].values() for e in v]
    return median(every) if every else None


def events_by_n(t: dict) -> list[dict]:
    """Per robot count, increasing: gathered runs, median and maximum events."""
    return [{"n": int(n), "gathered": len(v), "median": median(v), "max": max(v)}
            for n, v in sorted(t["events"].items(), key=lambda kv: int(kv[0])) if v]


def failures(t: dict) -> int:
    """Starts that count against the claim: neither gathered nor without a leader
    (violations, stalls, undecided, not possible with a leader, other) and errors."""
    return sum(t[c] for c in CLASSES if c not in ("gathered", "no-leader")) + t["errors"]
