"""``exactsym ledger [--json] [--check] [--write] [--root DIR]`` (also ``python -m
exactsym.ledger``).

Loads and validates ``proofs/statements.toml`` (an unknown label exits 2 naming the
nearest known one), builds the dependency graph, writes ``docs/audit.md`` from it (only
with ``--write``: a command that reads should not change the tree), and prints a summary -- or, with ``--json``, ``{"statements": [{"label",
"kind", "grade", "readings", "uses", "evidence", "rests_on_refuted"}, ...]}``.  Every
file the evidence names must exist (exit 1 otherwise); ``--check`` also re-runs every
piece of evidence (exit 1 on any mismatch, each printed on standard error).

``--write-matrix CASE`` (repeatable) runs the gathering reading matrix of a witness case
and stores it as ``proofs/gathering/STEM.json``, ready to be cited as
``{matrix = "proofs/gathering/STEM.json"}`` (:mod:`.gathering_matrices`; seconds to a few
minutes per case); ``--write-matrix all`` rewrites every matrix the ledger cites.

``--export-coq DIR`` writes, for every refuted statement with a refutation certificate, its
refutation as a Coq file ``DIR/LABEL.v`` (``-`` as ``_``) that ``coqc`` checks on its own
(:mod:`exactsym.certificates.coq_refutation`); ``proofs/coq/refutations/`` holds them, cited
as ``{coq = ...}`` evidence.

``--sweep EVIDENCE.json`` (repeatable) reads a sweep's evidence file and says, for every
statement of the ledger it reports on, what the sweep found and whether that is
consistent with the grade (:mod:`.sweeps`; exit 1 if not); ``--save NAME`` then copies it
into the tree as ``proofs/sweeps/NAME.json`` with the smallest counterexamples in
``cases/sweeps/NAME/``, ready to be cited as ``{sweep = "proofs/sweeps/NAME.json"}``.

The lead wires it into ``exactsym`` with :func:`add_arguments` and :func:`run`.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from ..errors import InputError
from .audit_doc import render
from ..progress import Progress
from .evidence import check_evidence, coq_export, missing_files
from .gathering_matrices import MatrixError, compute_matrix, implied_grade, load_matrix
from .graph import dependency_graph, support
from .model import load_ledger
from .sweeps import SweepError, import_sweep, load_sweep, sweep_item

__all__ = ["add_arguments", "run", "main", "find_root", "ledger_json"]

LEDGER = Path("proofs") / "statements.toml"
AUDIT = Path("docs") / "audit.md"
MATRICES = Path("proofs") / "gathering"
EXIT_OK, EXIT_FALSE, EXIT_INPUT = 0, 1, 2


def find_root(start: Path | None = None) -> Path:
    """The nearest directory at or above ``start`` (default: the working directory)
    holding proofs/statements.toml, else the source tree this package is in (an editable
    install); raises :class:`InputError` when neither holds it (an installed package
    outside a checkout has no ledger)."""
    here = (start or Path.cwd()).resolve()
    for d in (here, *here.parents):
        if (d / LEDGER).is_file():
            return d
    tree = Path(__file__).resolve().parents[2]
    if (tree / LEDGER).is_file():
        return tree
    raise InputError(f"no {LEDGER.as_posix()} here or above: run it inside a checkout of "
                     "exactsym, or name one with --root DIR")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="print the ledger as JSON")
    parser.add_argument("--check", action="store_true",
                        help="re-run every piece of evidence (exit 1 on a mismatch)")
    parser.add_argument("--write", action="store_true",
                        help="also write docs/audit.md from the ledger (by default nothing "
                        "is written)")
    parser.add_argument("--no-write", action="store_true",
                        help="write nothing (the default; kept for old scripts)")
    parser.add_argument("--sweep", metavar="EVIDENCE", action="append", default=[],
                        help="a sweep's evidence file (RESULTS.evidence.json): say what it "
                        "finds for each statement and whether the grade agrees")
    parser.add_argument("--save", metavar="NAME", default=None,
                        help="with one --sweep: copy it to proofs/sweeps/NAME.json and its "
                        "smallest counterexamples to cases/sweeps/NAME/")
    parser.add_argument("--no-cases", action="store_true",
                        help="with --save: copy no case file (a summary cited for what "
                        "holds only)")
    parser.add_argument("--write-matrix", metavar="CASE", action="append", default=[],
                        help="run a gathering case's reading matrix and store it in "
                        "proofs/gathering/ (\"all\": every matrix the ledger cites)")
    parser.add_argument("--export-coq", metavar="DIR", default=None,
                        help="write each refutation certificate of the ledger as a Coq "
                        "file DIR/LABEL.v that coqc checks on its own")
    parser.add_argument("--root", metavar="DIR", default=None,
                        help="the repository root (default: found from the working "
                        "directory)")


def ledger_json(ledger, sup) -> dict:
    return {"statements": [
        {"label": s.label, "kind": s.kind, "grade": s.grade, "readings": list(s.readings),
         "uses": list(s.uses) + [c for c in s.calls if c not in s.uses],
         "evidence": [e.as_dict() for e in s.evidence],
         "rests_on_refuted": list(sup[s.label].rests_on_refuted)}
        for s in ledger.statements],
        "findings": [{"id": f.id, "about": list(f.about), "lines": list(f.lines),
                      "claim": f.claim, "evidence": [e.as_dict() for e in f.evidence]}
                     for f in ledger.findings],
        "claims": [{"id": c.id, "about": list(c.about), "grade": c.grade, "claim": c.claim,
                    "evidence": [e.as_dict() for e in c.evidence]} for c in ledger.claims]}


def sweep_texts(ledger, root: Path) -> dict:
    """(label, path) -> what the cited sweep summary says about the label."""
    out = {}
    for s in ledger.statements:
        for e in s.evidence:
            if e.kind == "sweep":
                try:
                    item = sweep_item(load_sweep(root / e.path), s.label)
                except (SweepError, OSError):
                    continue
                if item:
                    out[(s.label, e.path)] = item["text"]
    return out


def sweep_report(ledger, root: Path, paths: list, save: str | None,
                 no_cases: bool = False) -> list[str]:
    """Print what each sweep evidence file finds against the ledger's grades; returns the
    inconsistencies."""
    by = ledger.by_label()
    problems = []
    for path in paths:
        try:
            data = load_sweep(path)
        except (SweepError, OSError) as err:
            raise InputError(f"not a sweep evidence file: {err}", str(path)) from None
        print(f"sweep {data['family']} --what {data.get('what')}: "
              f"{data['configurations']:,} configurations")
        for item in data["evidence"]:
            s = by.get(item["statement"])
            if s is None or item["verdict"] == "vacuous":
                continue
            # only a failure can contradict a grade; a citation is checked by --check
            said = [f"grade {s.grade!r} must change"] if item["verdict"] == "fails" and \
                s.grade not in ("refuted", "refuted-under-reading") else []
            mark = "ok " if not said else "BAD"
            print(f"  {mark} {s.label} ({s.grade}): {item['text']}"
                  + (f" -- {'; '.join(said)}" if said else ""))
            problems += [f"{s.label}: sweep {path}: {p}" for p in said]
        if save:
            out, cases = import_sweep(path, root, save, () if no_cases else None)
            print(f"saved {out.relative_to(root)} and {len(cases)} case file(s) in "
                  f"cases/sweeps/{save}/")
    return problems


def write_matrices(ledger, root: Path, cases: list) -> int:
    """``--write-matrix``: store each case's reading matrix; print what each implies."""
    cited = sorted({e.path for s in ledger.statements for e in s.evidence
                    if e.kind == "matrix"})
    if cases == ["all"]:
        cases = []
        for path in cited:
            try:
                cases.append(root / load_matrix(root / path)["case"])
            except MatrixError:
                cases.append(root / "cases" / "gathering" / (Path(path).stem + ".toml"))
    for case in map(Path, cases):
        case = case if case.is_absolute() else Path.cwd() / case
        if not case.is_file():
            raise InputError("no such case file", str(case))
        print(f"{case.name}: running the reading matrix ...", file=sys.stderr, flush=True)
        data = compute_matrix(case.resolve(), root.resolve())
        target = root / MATRICES / (case.stem + ".json")
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
        print(f"wrote {target.relative_to(root).as_posix()} ({data['cpu_seconds']} s CPU)")
    for s in ledger.statements:
        stored = [load_matrix(root / e.path) for e in s.evidence
                  if e.kind == "matrix" and (root / e.path).is_file()]
        if stored:
            grade, why = implied_grade(stored, s.label)
            print(f"  {s.label} ({s.grade}): the matrices imply {grade or 'no grade'}: {why}")
    return EXIT_OK


def export_coq(ledger, root: Path, out: Path) -> int:
    """``--export-coq DIR``: each refuted statement's certificate as a Coq file, and each
    Coq refutation the ledger cites from a case (its source read from the cited file)."""
    from ..certificates.coq_refutation import STATEMENTS, CoqExportError, coq_file_name
    out.mkdir(parents=True, exist_ok=True)
    for s in ledger.statements:
        cited = [e.path for e in s.evidence if e.kind == "coq"]
        if not s.grade.startswith("refuted") or not (s.label in STATEMENTS or cited):
            continue
        current = (root / cited[0]).read_text(encoding="utf-8") \
            if cited and (root / cited[0]).is_file() else None
        try:
            text = coq_export(s, root, current)
        except (OSError, ValueError, CoqExportError) as err:
            raise InputError(f"{s.label}: cannot write it for Coq: {err}") from None
        (out / coq_file_name(s.label)).write_text(text, encoding="utf-8")
        print(f"wrote {(out / coq_file_name(s.label)).as_posix()} ({s.label})")
    return EXIT_OK


def run(args) -> int:
    root = Path(args.root) if args.root else find_root()
    ledger = load_ledger(root / LEDGER)
    graph = dependency_graph(ledger)
    sup = support(ledger, graph)
    if args.sweep:
        if args.save and len(args.sweep) != 1:
            raise InputError("--save takes exactly one --sweep")
        problems = sweep_report(ledger, root, args.sweep, args.save, args.no_cases)
        for p in problems:
            print(f"ledger: {p}", file=sys.stderr)
        return EXIT_FALSE if problems else EXIT_OK
    if args.write_matrix:
        return write_matrices(ledger, root, args.write_matrix)
    if args.export_coq:
        return export_coq(ledger, root, Path(args.export_coq))
    if args.write and args.no_write:
        raise InputError("command line: --write and --no-write do not go together")
    if args.write:
        text = render(ledger, sup, sweep_texts(ledger, root))
        target = root / AUDIT
        if not target.is_file() or target.read_text(encoding="utf-8") != text:
            try:
                target.write_text(text, encoding="utf-8")
            except OSError as err:      # a path, a permission, a full disk: exit 2
                raise InputError(f"cannot write {target}: {err.strerror or err}") from None
    problems = (_checked(ledger, root) if args.check else missing_files(ledger, root))
    if args.json:
        print(json.dumps(ledger_json(ledger, sup), indent=2))
    else:
        counts: dict[str, int] = {}
        for s in ledger.statements:
            counts[s.grade] = counts.get(s.grade, 0) + 1
        print(f"{len(ledger.statements)} statements: " +
              ", ".join(f"{k} {v}" for k, v in counts.items()) +
              f"; {len(ledger.findings)} findings without a label; "
              f"{len(ledger.claims)} claims of exactsym's own")
        resting = [s.label for s in ledger.statements if sup[s.label].rests_on_refuted
                   and s.grade not in ("refuted",)]
        print(f"{len(resting)} not refuted themselves but resting on a refuted statement: "
              + ", ".join(resting))
        if args.check:
            print(f"evidence re-run: {len(problems)} mismatch(es)")
    for p in problems:
        print(f"ledger: {p}", file=sys.stderr)
    return EXIT_FALSE if problems else EXIT_OK


def _checked(ledger, root: Path) -> list:
    """``check_evidence`` with a progress bar on stderr (one step per case file re-run)."""
    cases = {e.path for s in ledger.statements for e in s.evidence if e.kind == "case"}
    with Progress("ledger --check", total=len(cases), unit=" cases") as bar:
        return check_evidence(ledger, root, progress=lambda path: bar.update(note=path))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m exactsym.ledger",
                                     description="The statement ledger (proofs/).")
    add_arguments(parser)
    args = parser.parse_args(argv)
    try:
        return run(args)
    except InputError as err:
        print(f"exactsym ledger: {err}", file=sys.stderr)
        return EXIT_INPUT
