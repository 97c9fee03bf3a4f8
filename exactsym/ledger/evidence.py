"""Re-run the ledger's evidence and confirm each verdict (``--check``).

* a case: analysed once per file (:mod:`.analysis_bridge`); its ``[expect]`` block must
  hold, and for ``audit-false`` / ``audit-true`` the audit must (not) list the label;
* a proof text: the file exists;
* a script: ``check(*args)`` of the proofs/ module returns without AssertionError;
* witnesses: ``proofs/witnesses.py`` refutes the label under exactly ``refuted_readings``
  readings;
* a refutation certificate: the standalone checker accepts it, for this label;
* a Coq refutation: the file is what ``exactsym ledger --export-coq`` writes from the
  statement's certificate, and ``coqc`` accepts it (when no ``coqc`` is installed, that
  run is skipped and said once on standard error);
* a sweep summary (:mod:`.sweeps`): well formed, reports on the label, its verdict is
  consistent with the grade, and a failure's smallest case is re-run like an
  ``audit-false`` case (and has the summary's number of robots);
* a gathering sweep summary (:mod:`.gather_sweep`, claims): well formed, and the claim's
  grade follows from its counts;
* a stored gathering reading matrix (:mod:`.gathering_matrices`): well formed; the grade
  its statement's matrices imply is no stricter than the ledger's; re-run from its case
  (those that took at most ``matrix_seconds`` CPU seconds when written; None: all), every
  row's outcome as stored.

:func:`missing_files` is the cheap part (every file named exists), run on every
invocation; :func:`check_evidence` runs everything.
"""

from __future__ import annotations

import importlib.util
import json
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from .gather_sweep import GatherSweepError, load_gather_sweep
from .gather_sweep import grade_problems as gather_grade_problems
from .gathering_matrices import MatrixError, grade_problems, load_matrix, rerun_problems
from .model import Evidence, Ledger
from .sweeps import SweepError, consistency, load_sweep, needs_case

__all__ = ["Mismatch", "missing_files", "check_evidence", "coq_export", "load_sweep"]


@dataclass(frozen=True)
class Mismatch:
    label: str
    evidence: str
    message: str

    def __str__(self) -> str:
        return f"{self.label}: {self.evidence}: {self.message}"


def _describe(e: Evidence) -> str:
    extra = f" ({e.verdict})" if e.verdict else ""
    args = f" {list(e.args)}" if e.args else ""
    return f"{e.kind} {e.path}{args}{extra}"


def missing_files(ledger: Ledger, root: Path) -> list[Mismatch]:
    out = []
    for s in (*ledger.statements, *ledger.findings, *ledger.claims):
        for e in s.evidence:
            if not (root / e.path).is_file():
                out.append(Mismatch(s.label, _describe(e), "file not found"))
    return out


def _module(path: Path):
    """A proofs/*.py file as a module (proofs/ is not a package: loaded by path, with its
    folder on sys.path for its own sibling imports)."""
    name = "exactsym_proofs_" + path.stem
    if name in sys.modules:
        return sys.modules[name]
    folder = str(path.parent)
    if folder not in sys.path:
        sys.path.insert(0, folder)
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def check_evidence(ledger: Ledger, root: Path,
                   analyse: Callable | None = None,
                   progress: Callable[[str], None] | None = None,
                   matrix_seconds: float | None = None) -> list[Mismatch]:
    """Every mismatch between the ledger's evidence and what re-running it shows."""
    if analyse is None:
        from .analysis_bridge import analyse_case as analyse
    cases: dict[str, object] = {}
    scripts: dict[tuple, str | None] = {}
    witness_result = None
    matrices: dict[str, dict] = {}
    coq_state: dict = {}
    out = missing_files(ledger, root)
    missing = {(m.label, m.evidence) for m in out}
    for s in (*ledger.statements, *ledger.findings, *ledger.claims):
        for e in s.evidence:
            if (s.label, _describe(e)) in missing:
                continue
            path = root / e.path
            if e.kind == "case":
                if e.path not in cases:
                    if progress:
                        progress(e.path)
                    cases[e.path] = analyse(path)
                a = cases[e.path]
                if a.error:
                    out.append(Mismatch(s.label, _describe(e), f"cannot be read: {a.error}"))
                    continue
                for failure in a.expect_failures:
                    out.append(Mismatch(s.label, _describe(e), f"[expect] fails: {failure}"))
                listed = s.label in a.audit_false
                if e.verdict == "audit-false" and not listed:
                    out.append(Mismatch(s.label, _describe(e), "the audit does not find "
                                        f"{s.label} false here (it lists: "
                                        f"{', '.join(sorted(a.audit_false)) or 'nothing'})"))
                if e.verdict == "audit-true" and listed:
                    out.append(Mismatch(s.label, _describe(e), f"the audit finds {s.label} "
                                        "false here"))
            elif e.kind == "script":
                key = (e.path, e.args)
                if key not in scripts:
                    if progress:
                        progress(f"{e.path} {list(e.args)}")
                    try:
                        _module(path).check(*e.args)
                        scripts[key] = None
                    except AssertionError as err:
                        scripts[key] = f"check{tuple(e.args)} failed: {err}"
                if scripts[key]:
                    out.append(Mismatch(s.label, _describe(e), scripts[key]))
            elif e.kind == "witnesses":
                if witness_result is None:
                    if progress:
                        progress(e.path)
                    witness_result = _module(path).check()
                got = len(witness_result["refutations"].get(s.label, {}))
                if got != e.refuted_readings:
                    out.append(Mismatch(s.label, _describe(e), f"refuted under {got} "
                                        f"readings, the ledger says {e.refuted_readings}"))
            elif e.kind == "certificate":
                from .. import checker      # the standalone checker, standard library only
                try:
                    obj = json.loads(path.read_text(encoding="utf-8"))
                except ValueError as err:
                    out.append(Mismatch(s.label, _describe(e), f"not JSON: {err}"))
                    continue
                ok, why = checker.verify_refutation(obj)
                if not ok or obj.get("label") != s.label:
                    out.append(Mismatch(s.label, _describe(e), why if not ok else
                                        f"it refutes {obj.get('label')!r}"))
                elif s.grade != "refuted":
                    out.append(Mismatch(s.label, _describe(e), "a valid refutation of a "
                                        f"statement graded {s.grade!r}"))
            elif e.kind == "sweep":
                try:
                    sweep = load_sweep(path)
                except (SweepError, OSError) as err:
                    out.append(Mismatch(s.label, _describe(e), str(err)))
                    continue
                problems = consistency(s, e.path, sweep, root)
                out.extend(Mismatch(s.label, _describe(e), p) for p in problems)
                small = None if problems else needs_case(s, sweep)
                if small:
                    case, robots = small
                    if case not in cases:
                        if progress:
                            progress(case)
                        cases[case] = analyse(root / case)
                    out.extend(Mismatch(s.label, _describe(e), f"smallest case {case}: {p}")
                               for p in _case_problems(cases[case], s.label, robots))
            elif e.kind == "coq":
                out.extend(Mismatch(s.label, _describe(e), p)
                           for p in _coq_problems(s, path, root, coq_state, progress))
            elif e.kind == "gather_sweep":
                try:
                    data = load_gather_sweep(path)
                except (GatherSweepError, OSError) as err:
                    out.append(Mismatch(s.label, _describe(e), str(err)))
                    continue
                out.extend(Mismatch(s.label, _describe(e), p)
                           for p in gather_grade_problems(getattr(s, "grade", ""), data))
            elif e.kind == "matrix":
                out.extend(Mismatch(s.label, _describe(e), p) for p in
                           _matrix_problems(e.path, root, matrices, matrix_seconds, progress))
        stored = [matrices[e.path] for e in s.evidence
                  if e.kind == "matrix" and isinstance(matrices.get(e.path), dict)]
        if stored:
            out.extend(Mismatch(s.label, "matrix evidence", p)
                       for p in grade_problems(s, stored))
    return out


def coq_export(s, root: Path, current: str | None = None) -> str:
    """The Coq refutation of statement ``s``: from its one certificate evidence, or, for
    a statement about CW/ACW strings or an algorithm, from the case that ``current`` (the
    file as it stands) names as its source.  Raises ``CoqExportError``."""
    from ..certificates.coq_refutation import (CASE_STATEMENTS, STATEMENTS, CoqExportError,
                                               coq_refutation, coq_refutation_of_points,
                                               source_of)
    certs = [e.path for e in s.evidence if e.kind == "certificate"]
    if s.label in STATEMENTS:
        if len(certs) != 1:
            raise CoqExportError("needs exactly one certificate evidence to be written from")
        return coq_refutation(json.loads((root / certs[0]).read_text(encoding="utf-8")),
                              s.claim, source=certs[0])
    from ..certificates.coq_gathering import GATHERING_STATEMENTS, coq_gathering_of_points
    if s.label not in CASE_STATEMENTS and s.label not in GATHERING_STATEMENTS:
        raise CoqExportError(f"no Coq statement for {s.label}")
    source = source_of(current or "")
    if not source or not (root / source).is_file():
        raise CoqExportError(f"the file names no source case that exists ({source})")
    if source.endswith(".py"):
        return coq_refutation_of_points(s.label, _script_points(root / source), source,
                                        s.claim)
    from ..geometry.configuration import from_file
    from ..io.fileformat import read_config
    config = from_file(read_config(str(root / source)))
    if config.polar is None:
        raise CoqExportError(f"{source}: not a rational polar configuration")
    if s.label in GATHERING_STATEMENTS:
        return coq_gathering_of_points(s.label, config.polar, source, s.claim)
    return coq_refutation_of_points(s.label, config.polar, source, s.claim)


def _script_points(path: Path) -> list:
    """The witness ``POINTS`` of a proof script the ledger cites (``(r, turn)`` about C,
    r the distance, rational): as ``(r^2, turn)``, the squared distance Coq's points hold."""
    import importlib.util
    from fractions import Fraction
    spec = importlib.util.spec_from_file_location(f"_witness_{path.stem}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return [(Fraction(r) ** 2, Fraction(t)) for r, t in module.POINTS]


def _coq_problems(s, path: Path, root: Path, state: dict, progress) -> list[str]:
    """Why the Coq refutation at ``path`` is not the checked export of the statement's
    certificate (or source case)."""
    from ..certificates.coq_refutation import (CASE_STATEMENTS, STATEMENTS, CoqExportError,
                                               coqc_accepts)
    if s.grade not in ("refuted", "refuted-under-reading"):
        return [f"a Coq refutation of a statement graded {s.grade!r}"]
    from ..certificates.coq_gathering import GATHERING_STATEMENTS
    spec = (STATEMENTS.get(s.label) or CASE_STATEMENTS.get(s.label)
            or GATHERING_STATEMENTS.get(s.label) or {})
    if spec.get("reading") is None and s.grade == "refuted-under-reading":
        return ["a statement refuted under a reading needs the reading in its Coq file"]
    current = path.read_text(encoding="utf-8")
    try:
        text = coq_export(s, root, current)
    except (OSError, ValueError, KeyError, CoqExportError) as err:
        return [f"cannot be written: {err}"]
    if current != text:
        return ["differs from its fresh export (exactsym ledger --export-coq)"]
    if state.get("absent"):
        return []
    if progress:
        progress(f"{path.name} (coqc)")
    try:
        ok, messages, seconds = coqc_accepts(text, path.name)
    except CoqExportError as err:
        state["absent"] = True
        print(f"exactsym ledger: the Coq refutations are not run: {err}", file=sys.stderr)
        return []
    state[path.name] = seconds
    return [] if ok else [f"coqc rejects it: {messages[-300:]}"]


def _matrix_problems(path: str, root: Path, matrices: dict, limit, progress) -> list[str]:
    """Load (once) and re-run (once, when it is cheap enough) a stored reading matrix."""
    if path in matrices:
        return []
    try:
        data = load_matrix(root / path)
    except MatrixError as err:
        matrices[path] = None
        return [str(err)]
    matrices[path] = data
    if limit is not None and data.get("cpu_seconds", float("inf")) > limit:
        return []
    if progress:
        progress(f"{path} (re-running the reading matrix of {data['case']})")
    return rerun_problems(data, root)


def _case_problems(a, label: str, robots: int | None) -> list[str]:
    """Why the analysed case ``a`` is not a counterexample to ``label`` with ``robots``."""
    if a.error:
        return [f"cannot be read: {a.error}"]
    out = [f"[expect] fails: {f}" for f in a.expect_failures]
    if label not in a.audit_false:
        out.append(f"the audit does not find {label} false here")
    if robots is not None and a.n is not None and a.n != robots:
        out.append(f"it has {a.n} robots, the sweep says {robots}")
    return out
