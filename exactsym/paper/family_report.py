"""The family layer in the report of ``exactsym check`` (``docs/cli.md``).

:func:`paper_json` gives ``report["paper"]`` (``orderable``, ``leader``, ``trace``,
``bounded`` -- what the work budgets cut -- and more); :func:`family_lines` the lines of
the text report for the paper's procedure and the audit.
"""

from __future__ import annotations

from .family import PaperResult


def paper_json(res: PaperResult, described: bool = True) -> dict:
    """``report["paper"]`` of a :class:`~exactsym.paper.family.PaperResult` (without ``G``
    and ``G_prime`` unless ``described``)."""
    out = {"orderable": res.orderable, "leader": res.leader,
           "gathering_possible": res.gathering_possible, "moves": res.moves,
           "first_actor": res.first_actor, "complete": res.complete,
           "make_asym": res.make_asym, "elect_leader": res.elect_leader}
    if described:
        out.update({"G": res.G, "G_prime": res.Gprime})
    out.update({"bounded": res.bounded, "trace": res.trace})
    return out


def paper_lines(res: PaperResult) -> list[str]:
    """One line: the paper's conclusions on the whole configuration."""
    return [f"paper (family): {'orderable' if res.orderable else 'not orderable'}"
            f"; gathering {'possible' if res.gathering_possible else 'not possible'}"
            f"; leader {res.leader}; moves {[m['robot'] for m in res.moves]}"]


def audit_lines(audit: dict, shown: int = 6) -> list[str]:
    """The audit's verdict and its first ``shown`` discrepancies."""
    disc = audit["discrepancies"]
    lines = [f"audit: {'agrees' if not disc else f'{len(disc)} discrepancy(ies)'}"]
    for d in disc[:shown]:
        lines.append(f"  {d['statement']}: says {d['says']}; truth: {d['truth']}")
    if len(disc) > shown:
        lines.append(f"  ... ({len(disc)} in all)")
    return lines


__all__ = ["paper_json", "paper_lines", "audit_lines"]
