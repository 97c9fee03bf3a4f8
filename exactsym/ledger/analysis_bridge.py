"""The one place where the ledger calls the analysis (to re-run evidence cases).

It loads a configuration, runs :func:`exactsym.analysis.analyse` (truth, paper, audit)
and the ``[expect]`` comparison; a case with ``gather_*`` claims also runs the gathering
simulator on the run it describes (:func:`exactsym.gathering.cases.run_case_file`).  Nothing else in :mod:`exactsym.ledger` imports the
analysis.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..errors import InputError

__all__ = ["CaseAnalysis", "analyse_case", "has_leader"]


@dataclass(frozen=True)
class CaseAnalysis:
    """What the ledger needs from one case file: whether it could be read, the failed
    ``[expect]`` claims, and the labels the audit lists as false on it."""
    path: str
    error: str | None
    expect_failures: tuple[str, ...]
    audit_false: frozenset[str]
    n: int | None = None              # robots


def analyse_case(path) -> CaseAnalysis:
    """Load ``path`` and analyse it once (the caller caches per file)."""
    from ..analysis import analyse
    from ..geometry.configuration import load
    from ..report.check import GATHER_PREFIX, failed_expectations, report_json
    try:
        config = load(Path(path))
    except InputError as err:
        return CaseAnalysis(str(path), str(err), (), frozenset())
    report = report_json(analyse(config))
    audit = report.get("audit") or {}
    false = frozenset(d["statement"] for d in audit.get("discrepancies", ()))
    failures = list(failed_expectations(config, report))
    if any(key.startswith(GATHER_PREFIX) for key in config.expect):
        # the simulator's claims (gather_outcome, gather_label, ...): run the case's run
        from ..gathering.cases import run_case_file
        failures += run_case_file(path).failures
    return CaseAnalysis(str(path), None, tuple(failures), false, config.n)


def has_leader(path) -> bool:
    """Whether the ground truth elects a leader for the configuration of ``path`` (a
    reading matrix's "not possible" or stall is then the algorithm's failure)."""
    from ..analysis import analyse
    from ..geometry.configuration import load
    from ..report.check import report_json
    return report_json(analyse(load(Path(path))))["leader"] is not None
