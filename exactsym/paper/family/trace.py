"""The trace of the family algorithms: entries, names of polygons, and the cap on
its length.

The trace is a list of dicts ``{"algorithm", "line", "polygons", "statement", "detail"}``
with, where they apply, ``"robots"`` (configuration indices selected or moved), ``"branch"``
(a stable name of the branch taken, :data:`BRANCHES`), ``"holds"`` (False when the step's
claim is false on this configuration: a finding; the audit collects them) and ``"round"``.

Printed line numbers: ``line`` counts, in the printed algorithm, every ``if``/``while``/
``for`` header and every statement ending in ``\\;``, in order; ``else`` and ``end`` are not
counted (``docs/interpretations.md``).
"""

from __future__ import annotations

from typing import Sequence

from .concentric import Ring, lines_text


#: Every branch of the family algorithms, as recorded in the trace's ``"branch"`` key
#: (the test of the case library asserts that each is reached by some case).
BRANCHES = {
    "Preprocess": ("odd-merge-type4", "odd-pair-not-type4", "skip-j-even-or-same",
                   "skip-i-even", "skip-centre", "literal-nontermination"),
    "MakeAsym": ("asym-polygon-large", "asym-polygon-small-asym", "asym-polygon-small-sym",
                 "asym-pair-large", "asym-pair-small-asym", "asym-pair-small-sym",
                 "single-vertex", "not-orderable"),
    "ElectLeader": ("sym-degree-one", "asymmetric", "project-1t", "centre"),
    "GatheringPattern": ("not-possible", "possible"),
}


def trace_entry(trace: list, algorithm: str, line, polygons, statement: str, detail: str,
                **extra) -> dict:
    e = {"algorithm": algorithm, "line": line, "polygons": list(polygons),
         "statement": statement, "detail": detail}
    e.update({k: v for k, v in extra.items() if v is not None})
    trace.append(e)
    return e


def few_names(rings: Sequence[Ring], k: int = 8) -> list:
    """The names of ``rings``, at most k of them (the first and the last)."""
    if len(rings) <= k:
        return [g.name for g in rings]
    return [g.name for g in rings[:k // 2]] + ["..."] + [g.name for g in rings[-(k // 2):]]


def describe(rings: Sequence[Ring], polar: bool, limit: int | None = None) -> list:
    """One dict per polygon; above ``limit`` polygons the first and last limit/2, with
    ``{"omitted": k}`` between them."""
    def one(g):
        return {"name": g.name, "vertices": g.n, "robots": list(g.robots),
                "levels": list(g.levels), "lines": lines_text(g, polar)}
    if limit is None or len(rings) <= limit:
        return [one(g) for g in rings]
    head, tail = rings[:limit // 2], rings[len(rings) - limit // 2:]
    return [one(g) for g in head] + [{"omitted": len(rings) - len(head) - len(tail)}] + \
        [one(g) for g in tail]


def family_text(rings: Sequence[Ring], k: int = 8) -> str:
    """``"G1: 3, G2: 5, ..."`` for at most k polygons (the first and last)."""
    if len(rings) <= k:
        return ", ".join(f"{g.name}: {g.n}" for g in rings)
    part = lambda gs: ", ".join(f"{g.name}: {g.n}" for g in gs)     # noqa: E731
    return (f"{part(rings[:k // 2])}, ... ({len(rings)} polygons), "
            f"{part(rings[-(k // 2):])}")


#: Trace entries always kept by :func:`compact_trace` (findings, selections, budgets).
def _essential(e: dict) -> bool:
    return e.get("holds") is False or bool(e.get("robots")) or "uses" in e or \
        e.get("kind") == "budget" or e.get("algorithm") == "Section 3"


def compact_trace(trace: list, limit: int | None) -> tuple[list, int]:
    """At most ``limit`` entries (plus the essential ones: findings, robots selected or
    moved, steps over a budget, the Section-3 summaries): the other entries are kept in
    order until the limit and a final entry counts the omitted ones by algorithm and
    branch.  Returns ``(trace, omitted)``."""
    if limit is None or len(trace) <= limit:
        return trace, 0
    essential = sum(1 for e in trace if _essential(e))
    room = max(0, limit - essential - 1)
    out, omitted, counts = [], 0, {}
    for e in trace:
        if _essential(e) or room > 0:
            if not _essential(e):
                room -= 1
            out.append(e)
            continue
        omitted += 1
        key = f"{e['algorithm']}" + (f"/{e['branch']}" if e.get("branch") else "")
        counts[key] = counts.get(key, 0) + 1
    out.append({"algorithm": "exactsym", "line": None, "polygons": [],
                "statement": "trace", "detail": f"{omitted} trace entries omitted (limit "
                f"{limit}): " + ", ".join(f"{v} {k}" for k, v in sorted(counts.items())),
                "omitted": omitted, "omitted_by_kind": dict(sorted(counts.items()))})
    return out, omitted
