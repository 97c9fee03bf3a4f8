"""Gathering statements graded from the reading matrix (issue 30, point 4; docs/ledger.md).

A ``{matrix = "proofs/gathering/NAME.json"}`` evidence entry names a stored reading matrix:
``exactsym gather CASE --readings all --json`` for one witness case (every named reading
of the paper's algorithm, both handednesses; :mod:`exactsym.gathering.reading_matrix`),
with the case, the search bounds of each row, whether the start is the paper's (separated
robots) or a state inside a run (``gather_mid_run``: counted for no grade), whether the
ground truth elects a leader at the start, and the CPU seconds it took.  ``exactsym
ledger --write-matrix CASE`` (``all``: every matrix the ledger cites) writes such a file from
its case; ``--check`` re-runs them and compares the outcomes.

What a row says about a statement S (:func:`row_verdict`):

* ``fails`` -- the run violates S (the violation's label begins with one of
  :data:`LABELS_OF` [S]), or the algorithm fails to gather on a start with a leader: a
  proved stall (nobody moves in any frame, or an exact state repeats), or "not possible".
  A reading under which nobody moves, or the run loops, is a failure of the algorithm,
  never a rescue of the statement (the house rule of issue 32);
* ``passes`` -- the run gathers;
* ``open`` -- anything else: another statement's violation stops the run first, the
  kernel cannot hold a number (``undecided``), or the event limit (``undecided-at-budget``).

The grade the matrices imply (:func:`implied_grade`), reading by whole reading (the
switches' values, and the handedness when a row fixes one; the rows of single-valued
switches are copies of the base row and count once per witness): ``refuted`` when every
reading fails on some witness and some row violates S itself; ``refuted-under-reading``
when some reading was run on every witness and gathers on each while another violates S;
``holds-on-cases`` when nothing violates S and some reading gathers everywhere; otherwise
none.  :func:`grade_problems` holds the ledger to it: the ledger may be stricter (more
against the paper), never more lenient.  A ledger grade ``refuted-under-reading`` against
an implied ``refuted`` is allowed only when its rescue is a reading of the statement's own
scope (what the lemma's words cover), not one of the algorithm's readings: a
``rescued_by`` naming ("A3=first", "A3: first") a reading under which the algorithm fails
on a witness is refused.
"""

from __future__ import annotations

import json
import re
import time
from pathlib import Path

__all__ = ["LABELS_OF", "MatrixError", "load_matrix", "row_verdict", "reading_name",
           "implied_grade",
           "grade_problems", "rerun_problems", "compute_matrix", "FORMAT"]

FORMAT = 1

#: The violation labels that contradict a statement (the first word of the label an
#: invariant reports, :data:`exactsym.gathering.invariants.LABELS`).  GatheringPattern is
#: the whole algorithm: every violation is its failure.  FormGPattern's moves are the
#: leader's: a collision of its path (gather-no-obstacle), a fresh Look naming another
#: mover (L1642-1643), a stale target.
LABELS_OF = {
    "gather-no-obstacle": ("gather-no-obstacle",),
    "gather-min-distance": ("gather-min-distance",),
    "FormGPattern": ("FormGPattern", "gather-no-obstacle", "gathering_pattern"),
    "GatheringPattern": None,            # None: every label
    "Make_SymToAsym": ("obs-v-move", "Make_SymToAsym"),
}

_SWITCH = re.compile(r"\b(A\d|lone|EL|hand)\s*[:=]\s*([A-Za-z0-9-]+)")
_OUTCOMES = {"violated", "gathered", "stalled", "not-possible", "undecided",
             "undecided-at-budget"}


class MatrixError(ValueError):
    """A stored reading matrix is malformed."""


def load_matrix(path) -> dict:
    """Read and check the shape of a stored matrix (raises :class:`MatrixError`)."""
    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, ValueError) as err:
        raise MatrixError(f"cannot read {path}: {err}") from None
    need = {"format", "case", "bounds", "settings", "start", "start_has_leader", "matrix"}
    if not isinstance(data, dict) or set(data) - need - {"cpu_seconds"} or need - set(data):
        raise MatrixError(f"{path}: keys must be {sorted(need)} (+ cpu_seconds)")
    if data["format"] != FORMAT:
        raise MatrixError(f"{path}: format must be {FORMAT}")
    if data["start"] not in ("separated", "mid-run"):
        raise MatrixError(f"{path}: start must be 'separated' or 'mid-run'")
    for row in data["matrix"]:
        if not isinstance(row, dict) or row.get("outcome") not in _OUTCOMES \
                or not isinstance(row.get("reading"), str) \
                or not isinstance(row.get("readings"), dict):
            raise MatrixError(f"{path}: a row needs a reading, its readings and an outcome "
                              f"of {sorted(_OUTCOMES)}")
    return data


def _violates(label: str | None, statement: str) -> bool:
    if label is None:
        return False
    wanted = LABELS_OF.get(statement, (statement,))
    first = label.split(" ")[0]
    return wanted is None or first in wanted


def row_verdict(row: dict, statement: str, start_has_leader: bool) -> str:
    """``"fails"``, ``"passes"`` or ``"open"`` (module docstring)."""
    outcome = row["outcome"]
    if outcome == "violated":
        return "fails" if _violates(row.get("label"), statement) else "open"
    if outcome == "gathered":
        return "passes"
    if outcome in ("stalled", "not-possible"):
        return "fails" if start_has_leader else "open"
    return "open"


def reading_name(row: dict) -> str:
    """A row's whole reading, named by what differs from the defaults (the witnesses'
    base readings differ: "base" of one case is "A3=first" of another), with the sense
    of the handedness when the row fixes one."""
    from ..gathering.robot import Readings
    default = Readings().as_dict()
    name = ", ".join(f"{k}={v}" for k, v in row["readings"].items() if default[k] != v)
    hand = next((t for t in row["reading"].split(", ") if t.startswith("hand=")), "")
    return ", ".join(x for x in (name or "defaults", hand) if x)


def _has(row: dict, token: str) -> bool:
    """Whether the row's whole reading includes ``token`` ("A3=first", "hand=plain")."""
    key, _, value = token.partition("=")
    return token in row["reading"].split(", ") if key == "hand" else \
        row["readings"].get(key) == value


def _counted(matrices: list) -> list:
    """The matrices that meet the paper's hypothesis of a separated start."""
    return [m for m in matrices if m.get("start", "separated") == "separated"]


def _table(matrices: list, statement: str) -> dict:
    """whole reading -> [its verdict on each witness that ran it]: one verdict per witness
    (the rows of single-valued switches are copies of the base row, not more witnesses)."""
    out: dict = {}
    for m in matrices:
        mine = {reading_name(row): row_verdict(row, statement, m["start_has_leader"])
                for row in m["matrix"]}
        for name, verdict in mine.items():
            out.setdefault(name, []).append(verdict)
    return out


def implied_grade(matrices: list, statement: str) -> tuple[str | None, str]:
    """``(grade or None, why)`` from the stored matrices of the statement's witnesses.  A
    matrix run from a state inside a run (``start: mid-run``) does not meet the paper's
    hypothesis of a separated start: it is shown, never counted."""
    matrices = _counted(matrices)
    table = _table(matrices, statement)
    if not table:
        return None, "no matrix"
    violated = any(_violates(row.get("label"), statement) for m in matrices
                   for row in m["matrix"] if row["outcome"] == "violated")
    # a rescue must be run, and gather, on every witness
    rescuing = [r for r, v in table.items()
                if len(v) == len(matrices) and all(x == "passes" for x in v)]
    if rescuing and not violated:
        return "holds-on-cases", f"no reading violates it; {'; '.join(rescuing)} gather"
    if rescuing:
        return "refuted-under-reading", f"passes under {'; '.join(rescuing)} on every witness"
    open_rows = [r for r, v in table.items() if "fails" not in v]
    if violated and not open_rows:
        return "refuted", f"every one of {len(table)} readings fails on some witness"
    if open_rows:
        return None, f"no witness settles {'; '.join(open_rows)}"
    return None, "the algorithm fails under every reading but no run violates it"


#: How strongly a grade speaks against the paper (the ledger may be stricter than its
#: matrices, never more lenient).
_AGAINST = {"refuted": 2, "refuted-under-reading": 1}


def _tokens(text: str) -> set:
    """The readings a text names, as ``K=V``: "A3=first", "A3: first", "A3 = first"."""
    return {f"{k}={v}" for k, v in _SWITCH.findall(text or "")}


def grade_problems(statement, matrices: list) -> list[str]:
    """Why the ledger's grade of ``statement`` is more lenient than its matrices."""
    implied, why = implied_grade(matrices, statement.label)
    grade, out = statement.grade, []
    if implied is None:
        return out
    need = _AGAINST.get(implied, 0)
    scope_rescue = implied == "refuted" and grade == "refuted-under-reading"
    if _AGAINST.get(grade, 0) < need and not scope_rescue:
        out.append(f"the reading matrix implies {implied} ({why}), the ledger says {grade}")
    if scope_rescue:
        counted = _counted(matrices)
        table = _table(counted, statement.label)
        failing = [row for m in counted for row in m["matrix"]
                   if "fails" in table[reading_name(row)]]
        named = sorted(t for t in _tokens(statement.rescued_by)
                       if any(_has(row, t) for row in failing))
        if named:
            out.append(f"rescued_by names {', '.join(named)}, under which the algorithm "
                       f"fails on a witness of the matrix ({why})")
    return out


def compute_matrix(case_path: Path, root: Path, bounds: dict | None = None) -> dict:
    """The stored form of a case's reading matrix (runs the search: seconds to minutes)."""
    from ..gathering.cases import settings_of
    from ..gathering.paper_bridge import read_case
    from ..gathering.reading_matrix import reading_matrix
    from ..gathering.search import Bounds
    from .analysis_bridge import has_leader
    # no wall-clock bound: a stored matrix must come out the same on every machine
    bounds = dict(bounds or {"budget": 400, "depth": 16, "seed": 0})
    points, _name, expect, _source = read_case(case_path)
    settings = settings_of(expect)
    start = time.process_time()
    rows = reading_matrix(points, settings, Bounds(**bounds))
    cpu = time.process_time() - start
    return {"format": FORMAT, "case": case_path.relative_to(root).as_posix(),
            "bounds": bounds, "settings": settings,
            "start": "mid-run" if expect.get("gather_mid_run") else "separated",
            "start_has_leader": has_leader(case_path),
            "matrix": [{k: row.get(k) for k in ("reading", "readings", "mirrored", "outcome",
                                                "label", "invariant", "robots", "length",
                                                "schedule", "detail")}
                       for row in rows],
            "cpu_seconds": round(cpu, 1)}


def _columns(data: dict) -> list:
    return [(r["reading"], r["outcome"], r.get("label"), r.get("robots"), r.get("length"))
            for r in data["matrix"]]


def rerun_problems(stored: dict, root: Path) -> list[str]:
    """Re-run a stored matrix from its case and name every row whose outcome changed."""
    fresh = compute_matrix(root / stored["case"], root, stored["bounds"])
    out = []
    if fresh["start"] != stored["start"]:
        out.append(f"the case's start is now {fresh['start']}")
    if fresh["start_has_leader"] != stored["start_has_leader"]:
        out.append(f"the truth now says start_has_leader={fresh['start_has_leader']}")
    if fresh["settings"] != stored["settings"]:
        out.append("the case's settings changed since the matrix was written")
    for old, new in zip(_columns(stored), _columns(fresh)):
        if old != new:
            out.append(f"row {old[0]}: stored {old[1]} {old[2] or ''} (robots {old[3]}, "
                       f"length {old[4]}), re-run {new[1]} {new[2] or ''} (robots {new[3]}, "
                       f"length {new[4]})")
    if len(stored["matrix"]) != len(fresh["matrix"]):
        out.append(f"{len(stored['matrix'])} rows stored, {len(fresh['matrix'])} re-run")
    return out
