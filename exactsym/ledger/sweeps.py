"""Sweep summaries as ledger evidence (issue 13, "feeding the ledger").

A sweep (:mod:`exactsym.sweeps`) writes ``RESULTS.evidence.json``: per statement label a
verdict (``fails`` / ``holds`` / ``vacuous``), the counts and the smallest counterexample
(``docs/sweeps.md``).  The ledger cites a *committed* copy, ``proofs/sweeps/NAME.json``
(:func:`import_sweep` writes it: the results file's path dropped, the cited smallest
counterexamples copied to ``cases/sweeps/NAME/``), as ``{sweep = "proofs/sweeps/NAME.json"}``.

What a sweep can and cannot say about a grade (:func:`consistency`):

* ``holds`` is *holds on these configurations*, never a proof: it may stand beside any
  grade but ``refuted`` needs another witness of the refutation (a case the audit finds
  false, a refutation certificate, a witness under some reading, or a failing sweep);
* ``fails`` contradicts ``proved``, ``holds-on-cases``, ``open`` and ``definition`` (the
  grade must change), and backs ``refuted`` / ``refuted-under-reading`` only through its
  smallest counterexample, a case file in the tree that ``--check`` re-runs: the audit must
  list the label false on it, its ``[expect]`` block must hold, and it must have the
  number of robots the summary says;
* ``vacuous`` (its hypotheses held on none of the configurations) is no evidence at all.

The older one-label summary (``{"format": 1, "label", "family", "configurations",
"failures", "smallest_case"}``) is still read, as one item.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

__all__ = ["load_sweep", "sweep_item", "consistency", "needs_case", "import_sweep",
           "SweepError", "OLD_KEYS"]

#: Keys of the older one-label summary and their types.
OLD_KEYS = {"format": int, "label": str, "family": str, "configurations": int,
            "failures": int, "smallest_case": (str, type(None))}
VERDICTS = ("fails", "holds", "vacuous")


class SweepError(ValueError):
    """A sweep summary that is malformed or does not bear on what it is cited for."""


def _int(value, what: str) -> int:
    if not isinstance(value, int) or isinstance(value, bool) or value < 0:
        raise SweepError(f"{what} must be a count (a non-negative integer)")
    return value


def _from_old(data: dict) -> dict:
    for key, types in OLD_KEYS.items():
        if key not in data or not isinstance(data[key], types) or isinstance(data[key], bool):
            raise SweepError(f"sweep summary key {key!r} missing or of the wrong type")
    fails = data["failures"] > 0
    smallest = {"case": data["smallest_case"], "robots": None} if fails else None
    n = data["configurations"]
    return {"format": 1, "family": data["family"], "what": None, "configurations": n,
            "errors": 0, "evidence": [
                {"statement": data["label"], "verdict": "fails" if fails else "holds",
                 "configurations": n, "applicable": None, "failures": data["failures"],
                 "outside": 0, "smallest": smallest,
                 "text": (f"fails on {data['failures']:,} of {n:,} configurations of "
                          f"{data['family']}") if fails else
                         f"holds on all {n:,} configurations of {data['family']}"}]}


def load_sweep(path) -> dict:
    """A sweep summary (either format), validated: counts are counts, each verdict agrees
    with its counts.  :class:`SweepError` otherwise."""
    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
    except ValueError as err:
        raise SweepError(f"not JSON: {err}") from None
    if not isinstance(data, dict):
        raise SweepError("a sweep summary is one JSON object")
    if data.get("format") != 1:
        raise SweepError("sweep summary format must be 1")
    if "label" in data:
        data = _from_old(data)
    if not isinstance(data.get("family"), str) or not isinstance(data.get("evidence"), list):
        raise SweepError("a sweep summary names its family and lists its evidence")
    total = _int(data.get("configurations"), "configurations")
    _int(data.get("errors", 0), "errors")
    for item in data["evidence"]:
        if not isinstance(item, dict) or not isinstance(item.get("statement"), str):
            raise SweepError("each evidence item names its statement")
        label = item["statement"]
        failures = _int(item.get("failures"), f"{label}: failures")
        applicable = item.get("applicable")
        if applicable is not None:
            _int(applicable, f"{label}: applicable")
            if failures > applicable:
                raise SweepError(f"{label}: more failures than configurations where its "
                                 "hypotheses hold")
        if failures > total or item.get("configurations") != total:
            raise SweepError(f"{label}: its counts disagree with the sweep's "
                             f"{total} configurations")
        verdict = item.get("verdict")
        want = "fails" if failures else ("vacuous" if applicable == 0 else "holds")
        if verdict != want:
            raise SweepError(f"{label}: verdict {verdict!r} but the counts say {want!r}")
        if failures and not isinstance(item.get("smallest"), dict):
            raise SweepError(f"{label}: fails without a smallest counterexample")
        if not isinstance(item.get("text"), str):
            raise SweepError(f"{label}: no text")
    return data


def sweep_item(data: dict, label: str) -> dict | None:
    return next((i for i in data["evidence"] if i["statement"] == label), None)


def _refuted_elsewhere(statement, sweep_path: str, root: Path) -> bool:
    """Another piece of evidence witnesses the refutation (see the module docstring)."""
    for e in statement.evidence:
        if e.kind == "case" and e.verdict == "audit-false":
            return True
        if e.kind == "certificate" or (e.kind == "witnesses" and e.refuted_readings):
            return True
        if e.kind == "sweep" and e.path != sweep_path:
            try:
                other = sweep_item(load_sweep(root / e.path), statement.label)
            except (SweepError, OSError):
                continue
            if other and other["verdict"] == "fails":
                return True
    return False


def consistency(statement, sweep_path: str, data: dict, root: Path) -> list[str]:
    """What is wrong with citing the summary ``data`` for ``statement`` (empty: nothing);
    the smallest case's re-run is :func:`needs_case`'s, done by the caller."""
    item = sweep_item(data, statement.label)
    if item is None:
        return [f"the sweep of {data['family']} does not report on {statement.label}"]
    grade, verdict = statement.grade, item["verdict"]
    if verdict == "vacuous":
        return [f"the sweep does not test it ({item['text']})"]
    if verdict == "holds":
        if grade == "refuted" and not _refuted_elsewhere(statement, sweep_path, root):
            return ["a sweep where it holds cannot back 'refuted' without another witness "
                    "of the refutation"]
        return []
    if grade not in ("refuted", "refuted-under-reading"):
        return [f"the sweep finds it false ({item['text']}): grade {grade!r} must change"]
    case = (item.get("smallest") or {}).get("case")
    if not case:
        return ["fails, but the smallest counterexample is not a case file"]
    if Path(case).is_absolute() or ".." in Path(case).parts or not (root / case).is_file():
        return [f"the smallest counterexample {case} is not a case file of the tree"]
    return []


def needs_case(statement, data: dict) -> tuple[str, int | None] | None:
    """``(case path, robots)`` of the smallest counterexample ``--check`` must re-run."""
    item = sweep_item(data, statement.label)
    if item is None or item["verdict"] != "fails":
        return None
    small = item.get("smallest") or {}
    return (small["case"], small.get("robots")) if small.get("case") else None


def _slug(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_-]+", "_", text.replace("<=", "le")).strip("_")


def _lemmas_line(text: str, labels: list) -> str:
    """The case file ``text`` with its ``lemmas`` line naming every label in ``labels``."""
    line = "lemmas = [" + ", ".join(json.dumps(x) for x in labels) + "]"
    return re.sub(r"(?m)^lemmas = \[.*\]$", line, text, count=1)


def import_sweep(evidence_path, root, name: str | None = None,
                 labels: tuple | None = None) -> tuple[Path, list[Path]]:
    """Copy the sweep evidence at ``evidence_path`` into the tree: ``proofs/sweeps/NAME.json``
    (NAME from the family by default), without the results file's path; the smallest
    counterexamples of the failing ``labels`` (default: every failing label) copied to
    ``cases/sweeps/NAME/``, one file per configuration (named by the first label, its
    ``lemmas`` listing every label it is the smallest counterexample of), and named by
    their tree path; the others' ``case`` set to null.  Returns (the summary's path, the
    case files written)."""
    source = Path(evidence_path)
    data = load_sweep(source)
    root = Path(root)
    name = name or _slug(data["family"])
    cases_dir = Path("cases") / "sweeps" / name
    by_key: dict = {}                                # smallest key -> (target, labels)
    for item in data["evidence"]:
        small = item.get("smallest")
        if not small:
            continue
        case = small.get("case")
        found = None
        if case and (labels is None or item["statement"] in labels):
            found = Path(case) if Path(case).is_absolute() else source.parent / case
            found = found if found.is_file() else Path(case)
        if found is not None and found.is_file():
            key = small.get("key") or str(found)
            if key not in by_key:
                by_key[key] = (cases_dir / found.name, found, [])
            by_key[key][2].append(item["statement"])
            small["case"] = by_key[key][0].as_posix()
        else:
            small["case"] = None
        if case and case in item["text"]:           # the text named the machine's path
            item["text"] = item["text"].replace(
                f" ({case})" if small["case"] is None else case, small["case"] or "")
    written = []
    for target, found, named in by_key.values():
        (root / cases_dir).mkdir(parents=True, exist_ok=True)
        text = _lemmas_line(found.read_text(encoding="utf-8"), named)
        (root / target).write_text(text, encoding="utf-8")
        written.append(root / target)
    data["results"] = None                       # a path of the machine that ran it
    out = root / "proofs" / "sweeps" / f"{name}.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
    return out, written
