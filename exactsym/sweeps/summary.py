"""What a sweep found: counts per statement, smallest counterexamples, ledger evidence.

:func:`summarise` reads a results file (:mod:`.results`) and returns a :class:`Summary`:
the configurations examined, and per statement label the configurations where its
hypotheses hold (``None`` when the analysis does not say), where it fails, and the
smallest counterexample (:func:`.families.rank`: fewest robots, then smallest
denominators, then smallest M).  :func:`write_cases` writes each smallest counterexample
as a case file for ``cases/`` with its ``[expect]`` block; :func:`ledger_evidence` turns
the summary into the plain data the ledger reads (``docs/sweeps.md``).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from . import analysis_bridge as bridge
from .casefile import case_text
from .job import SET_ASIDE
from .results import IndexSet, read_header, read_records

__all__ = ["Summary", "LabelSummary", "summarise", "write_cases", "ledger_evidence",
           "summary_json", "summary_table", "EVIDENCE_FORMAT"]

EVIDENCE_FORMAT = 1


@dataclass(frozen=True)
class LabelSummary:
    label: str
    applicable: int | None            # configurations where its hypotheses hold
    failures: int                     # configurations where it is false
    smallest: dict | None = None      # the record of the smallest counterexample
    outside: int = 0                  # false only outside its hypotheses (not counted)
    reading: int = 0                  # false only under a reading the audit names
    procedure: int = 0                # the claim holds; the audit blames the procedure


@dataclass(frozen=True)
class Summary:
    family: str
    what: str
    configurations: int               # distinct configurations analysed
    errors: int                       # distinct configurations whose analysis raised
    labels: tuple
    error_examples: tuple = ()        # (key, message) of the first few errors
    groups: dict = field(default_factory=dict)   # truth: group name -> configurations


def _rank(record: dict) -> tuple:
    return (record["n"], record["denominator"], record["size"], record["key"])


def summarise(path) -> Summary:
    """Summarise the results file at ``path`` (each configuration counted once: records
    are told apart by their enumeration index)."""
    head = read_header(path)
    if head is None:
        raise ValueError(f"{path}: not a sweep results file")
    what = head["what"]
    seen = IndexSet()
    configurations = errors = 0
    error_examples: list = []
    applicable: dict = {}
    failures: dict = {}
    smallest: dict = {}
    aside: dict = {k: {} for k in SET_ASIDE}
    groups: dict = {}
    tracks = what in ("audit", "paper")
    for record in read_records(path):
        key = record["key"]
        if not seen.add(record["index"]):
            continue
        if record["status"] != "ok":
            errors += 1
            if len(error_examples) < 5:
                error_examples.append((key, record.get("error", "")))
            continue
        configurations += 1
        if record.get("truth") and what == "truth":
            name = record["truth"]["group"]
            groups[name] = groups.get(name, 0) + 1
        for label in record.get("applicable") or ():
            applicable[label] = applicable.get(label, 0) + 1
        for kind, counts in aside.items():
            for label in record.get(kind) or ():
                counts[label] = counts.get(label, 0) + 1
        for label in record["failed"]:
            failures[label] = failures.get(label, 0) + 1
            best = smallest.get(label)
            if best is None or _rank(record) < _rank(best):
                smallest[label] = record
    order = list(bridge.statement_labels(what))
    order += sorted((set(failures) | set(applicable) | set().union(*aside.values()))
                    - set(order))
    labels = tuple(LabelSummary(label, applicable.get(label, 0) if tracks else None,
                                failures.get(label, 0), smallest.get(label),
                                **{k: aside[k].get(label, 0) for k in SET_ASIDE})
                   for label in order)
    return Summary(head["family"], what, configurations, errors, labels,
                   tuple(error_examples), dict(sorted(groups.items())))


def _case_name(label: str) -> str:
    return "sweep-" + re.sub(r"[^A-Za-z0-9_-]", "_", label) + ".toml"


def write_cases(summary: Summary, directory) -> dict:
    """Write the smallest counterexample of every failing label to ``directory`` (one
    ``.toml`` case per label, ready for ``cases/``); returns label -> path."""
    out: dict = {}
    directory = Path(directory)
    for entry in summary.labels:
        record = entry.smallest
        if record is None:
            continue
        directory.mkdir(parents=True, exist_ok=True)
        points = [tuple(p) for p in record["points"]]
        said = bridge.discrepancy_text(summary.what, points, entry.label)
        scale = (record.get("gather") or {}).get("scale", 1)
        if scale != 1:               # the simulator's start: every two robots > 2 apart
            points = list(bridge.scaled_points(points, scale))
            said = (f"{said} The sweep's points scaled by {scale} (the least integer that "
                    "puts every two robots more than 2 apart).").strip()
        g = record.get("gather") or {}
        if g.get("found_by") == "run":
            said = f"{said} The seeded run: {g.get('outcome')}, {g.get('detail', '')}".strip()
        elif g.get("found_by") == "search":
            said = (f"{said} Found by the searching adversary ({g['search']['states']} "
                    f"states): exactsym gather FILE --search --budget "
                    f"{g['search']['states']}; {g.get('detail', '')}").strip()
        notes = (f"Found by exactsym sweep {summary.family} --what {summary.what}: the "
                 f"smallest configuration of the family (fewest robots, then smallest "
                 f"denominators, then smallest M) on which {entry.label} is false; it fails "
                 f"on {entry.failures} of the {summary.configurations} configurations "
                 f"examined. Canonical form: {record['key']}. False here: "
                 f"{', '.join(record['failed'])}. {said}").strip()
        text = case_text(points, name=f"{entry.label}: smallest counterexample in "
                         f"{summary.family}", notes=notes,
                         lemmas=[entry.label] if bridge.is_label(entry.label) else [],
                         expect=bridge.expect_block(summary.what, record))
        path = directory / _case_name(entry.label)
        path.write_text(text, encoding="utf-8")
        out[entry.label] = str(path)
    return out


def _smallest_data(entry: LabelSummary, cases: dict) -> dict | None:
    r = entry.smallest
    if r is None:
        return None
    return {"robots": r["n"], "denominator": r["denominator"], "size": r["size"],
            "key": r["key"], "case": cases.get(entry.label)}


def summary_json(summary: Summary, cases: dict) -> dict:
    """The ``--json`` object: configurations, failures per label, smallest per label."""
    return {"family": summary.family, "what": summary.what,
            "configurations": summary.configurations, "errors": summary.errors,
            "failures": {e.label: e.failures for e in summary.labels if e.failures},
            "applicable": {e.label: e.applicable for e in summary.labels
                           if e.applicable is not None},
            "smallest": {e.label: _smallest_data(e, cases) for e in summary.labels
                         if e.smallest is not None},
            **{k: {e.label: getattr(e, k) for e in summary.labels if getattr(e, k)}
               for k in SET_ASIDE},
            "groups": summary.groups}


_ASIDE_TEXT = {"outside": "outside its hypotheses",
               "reading": "only under a reading the audit names (rescued by another)",
               "procedure": "by the paper's procedure while the claim holds"}


def _aside_text(e: LabelSummary) -> str:
    """What was found false but not counted, in words (empty when nothing)."""
    parts = [f"{getattr(e, k):,} {_ASIDE_TEXT[k]}" for k in SET_ASIDE if getattr(e, k)]
    return f"; false, not counted: {', '.join(parts)}" if parts else ""


def ledger_evidence(summary: Summary, cases: dict, results: str | None = None) -> dict:
    """Evidence per statement, as plain data for the ledger (``docs/sweeps.md``)."""
    n = summary.configurations
    fam = summary.family
    items = []
    caveat = (f"; {summary.errors:,} configuration(s) could not be analysed"
              if summary.errors else "")
    for e in summary.labels:
        if e.failures:
            verdict = "fails"
            s = e.smallest
            text = (f"fails on {e.failures:,} of {n:,} configurations of {fam}; smallest "
                    f"counterexample: {s['n']} robot{'s' if s['n'] != 1 else ''}"
                    + (f" ({cases[e.label]})" if e.label in cases else ""))
        elif e.applicable == 0:
            verdict = "vacuous"
            text = f"not tested: its hypotheses hold on none of the {n:,} configurations of {fam}"
        else:
            verdict = "holds"
            text = f"holds on all {n:,} configurations of {fam}"
            if e.applicable is not None and e.applicable != n:
                text += f" (its hypotheses hold on {e.applicable:,} of them)"
        text += _aside_text(e)
        items.append({"statement": e.label, "verdict": verdict, "text": text + caveat,
                      "configurations": n, "applicable": e.applicable,
                      "failures": e.failures, "outside": e.outside,
                      "reading": e.reading, "procedure": e.procedure,
                      "smallest": _smallest_data(e, cases)})
    return {"format": EVIDENCE_FORMAT, "source": "exactsym sweep", "family": fam,
            "what": summary.what, "results": results, "configurations": n,
            "errors": summary.errors, "evidence": items}


def summary_table(summary: Summary, cases: dict) -> str:
    """The plain-text table: label, hypotheses hold, failures, smallest counterexample."""
    lines = [f"sweep {summary.family} --what {summary.what}: {summary.configurations:,} "
             f"configurations examined, {summary.errors:,} error(s)"]
    for key, message in summary.error_examples:
        lines.append(f"  error on {key}: {message}")
    if summary.groups:
        lines.append("groups: " + ", ".join(f"{g} {c:,}" for g, c in summary.groups.items()))
    rows = [("statement", "hypotheses hold", "fails", "smallest counterexample")]
    for e in summary.labels:
        if not e.failures and not e.applicable and not _aside_text(e):
            continue
        s = e.smallest
        small = "-" if s is None else \
            f"{s['n']} robot{'s' if s['n'] != 1 else ''}, denominator {s['denominator']}: {s['key']}"
        if s is not None and e.label in cases:
            small += f"  -> {cases[e.label]}"
        small += _aside_text(e).replace("; false, not counted", "  (not counted")
        if _aside_text(e):
            small += ")"
        rows.append((e.label, "-" if e.applicable is None else f"{e.applicable:,}",
                     f"{e.failures:,}", small))
    if len(rows) > 1:
        widths = [max(len(r[i]) for r in rows) for i in range(3)]
        for r in rows:
            lines.append("  ".join(r[i].ljust(widths[i]) for i in range(3)) + "  " + r[3])
    return "\n".join(lines)
