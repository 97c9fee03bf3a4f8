"""The family layer's section of ``exactsym check`` and the ``exactsym audit`` command.

Importing this module appends :func:`family_section` to :data:`exactsym.report.SECTIONS`
(it adds ``report["paper"]`` -- updated in place when another section created it --
with ``orderable``, ``leader``, ``trace``, ``bounded`` (what the work budgets cut) and
more, and ``report["audit"]``), registers
the ``[expect]`` keys ``paper_leader`` (an integer, ``-1`` for "no leader") and
``audit_agrees`` (a boolean), and the command ``exactsym audit FILE [--json]`` (exit 1
when the audit finds a discrepancy).
"""

from __future__ import annotations

import json
import sys

from .. import cli as _cli
from .. import report as _report
from ..config import EXPECT_KEYS
from ..configuration import no_cycle_collection
from . import family as F

#: Options of the section: the readings passed to the paper's algorithms.
DEFAULT_OPTIONS = {"reading": "literal", "degree": "paper", "invariance": True}


def _paper_dict(res: F.PaperResult) -> dict:
    return {"orderable": res.orderable, "leader": res.leader,
            "gathering_possible": res.gathering_possible, "moves": res.moves,
            "first_actor": res.first_actor, "complete": res.complete,
            "make_asym": res.make_asym, "elect_leader": res.elect_leader,
            "G": res.G, "G_prime": res.Gprime, "bounded": res.bounded, "trace": res.trace}


def _trivial_truth(rings, report: dict):
    """The ground-truth section's group when it is the trivial group C1, rebuilt from the
    report (its name, ordering and leader are all there is to it: no rotation generator,
    no mirror), so that the audit need not compute the same group again; None otherwise
    (the audit then computes it)."""
    from ..symmetry import SymmetryGroup
    if report.get("group") != "C1" or report.get("orderable") is not True or \
            report.get("symmetries") != {"rotations": 1, "mirrors": 0} or \
            report.get("ordering") is None:
        return None
    return SymmetryGroup(name="C1", rotations=1, mirrors=0, centre=rings.sec.centre,
                         polar=rings.polar, rotation_generator=None, mirror=None,
                         reference=None, orderable=True, ordering=tuple(report["ordering"]),
                         leader=report.get("leader"))


def family_section(config, rings, report: dict, options: dict | None = None) -> None:
    """Add ``paper`` (the family algorithms) and ``audit`` to ``report``."""
    with no_cycle_collection():
        _family_section(config, rings, report, options)


def _family_section(config, rings, report: dict, options: dict | None = None) -> None:
    from ..audit import audit
    opts = dict(DEFAULT_OPTIONS)
    opts.update({k: v for k, v in (options or {}).items() if k in DEFAULT_OPTIONS})
    res = F.paper_procedure(config, rings, reading=opts["reading"], degree=opts["degree"])
    paper = report.get("paper")
    if not isinstance(paper, dict):
        paper = report["paper"] = {}
    paper.update(_paper_dict(res))
    report["audit"] = audit(config, rings, res, opts, group=_trivial_truth(rings, report))
    lines = report.setdefault("_table_lines", [])
    lines.append(f"paper (family): {'orderable' if res.orderable else 'not orderable'}"
                 f"; gathering {'possible' if res.gathering_possible else 'not possible'}"
                 f"; leader {res.leader}; moves {[m['robot'] for m in res.moves]}")
    disc = report["audit"]["discrepancies"]
    lines.append(f"audit: {'agrees' if not disc else f'{len(disc)} discrepancy(ies)'}")
    for d in disc[:6]:
        lines.append(f"  {d['statement']}: says {d['says']}; truth: {d['truth']}")
    if len(disc) > 6:
        lines.append(f"  ... ({len(disc)} in all)")


def _paper_leader(report: dict):
    paper = report.get("paper")
    if not isinstance(paper, dict) or "leader" not in paper:
        return None
    return -1 if paper["leader"] is None else paper["leader"]


def _audit_agrees(report: dict):
    return (report.get("audit") or {}).get("agrees")


# ---------------------------------------------------------------- the audit command
def _cmd_audit(args) -> int:
    from ..audit import audit
    from ..configuration import load
    from ..levels import rings as compute_rings
    config = load(args.file)
    ring_data = compute_rings(config)
    res = F.paper_procedure(config, ring_data)
    result = audit(config, ring_data, res)
    if args.json:
        print(json.dumps({"paper": _paper_dict(res), "audit": result}, indent=2))
    else:
        truth = result["truth"]
        print(f"truth: group {truth['group']}, "
              f"{'orderable' if truth['orderable'] else 'not orderable'}, leader "
              f"{truth['leader']}")
        print(f"paper: {'orderable' if res.orderable else 'not orderable'}, leader "
              f"{res.leader}, moves {[m['robot'] for m in res.moves]}")
        if result["agrees"]:
            print("audit: the paper agrees with the truth on this configuration")
        for d in result["discrepancies"]:
            print(f"- {d['statement']} ({d['kind']})\n    says:  {d['says']}\n"
                  f"    truth: {d['truth']}")
            if d.get("witness"):
                print(f"    witness: {json.dumps(d['witness'], default=str)}")
    if not result["agrees"]:
        print(f"{config.source}: the audit finds {len(result['discrepancies'])} "
              f"discrepancy(ies); the first: {result['discrepancies'][0]['statement']}",
              file=sys.stderr)
        return _cli.EXIT_FALSE
    return _cli.EXIT_OK


def _register(sub) -> None:
    p = sub.add_parser("audit", help="the paper's family algorithms against the ground truth "
                       "(exit 1 when some statement fails on the configuration)")
    p.add_argument("file")
    p.add_argument("--json", action="store_true", help="one JSON object on standard output")


if family_section not in _report.SECTIONS:
    _report.SECTIONS.append(family_section)
if _register not in _cli.EXTRA_COMMANDS:
    _cli.EXTRA_COMMANDS.append(_register)
_cli.COMMANDS.setdefault("audit", _cmd_audit)
# the [expect] keys paper_leader and audit_agrees live in config.EXPECT_KEYS and
# report.EXPECT_CHECKS (so that files read without the plugins validate); these are
# fallbacks for an older tree
EXPECT_KEYS.setdefault("paper_leader", int)
EXPECT_KEYS.setdefault("audit_agrees", bool)
_report.EXPECT_CHECKS.setdefault("paper_leader", (_paper_leader, lambda want, got: want == got))
_report.EXPECT_CHECKS.setdefault("audit_agrees", (_audit_agrees, lambda want, got: want == got))
