"""Load and validate the ledger ``proofs/statements.toml`` (format: docs/ledger.md).

Validation: every label of :mod:`exactsym.labels` has exactly one entry and no other
label appears; ``uses`` and ``calls`` name known labels; ``kind`` and ``grade`` come from
their sets (grade ``definition`` only for definitions and types); a
``refuted-under-reading`` entry says under which readings it fails and which rescues it;
evidence entries have one of the documented forms; a ``[[finding]]`` (a finding with no
label of its own) has a new id, the labels it is about, and evidence.  Every failure is a
:class:`LedgerError` (an :class:`~exactsym.errors.InputError`: exit 2) naming the file, the
entry and, for an unknown label, the nearest known one.
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from pathlib import Path

from ..errors import InputError
from ..labels import ALGORITHMS, LABELS, STATEMENTS, unknown_label_message

__all__ = ["GRADES", "KINDS", "EVIDENCE_VERDICTS", "Evidence", "Statement", "Finding", "Claim",
           "CLAIM_GRADES", "Ledger",
           "LedgerError", "load_ledger", "parse_ledger"]

#: Grades, strongest claim against the paper first.
GRADES = ("refuted", "refuted-under-reading", "holds-on-cases", "proved", "open",
          "definition")
KINDS = ("definition", "type", "observation", "lemma", "theorem", "corollary", "algorithm")
#: What a case file must show: its [expect] block holds; and the audit lists the label
#: as false on it, or does not.
EVIDENCE_VERDICTS = ("expect", "audit-false", "audit-true")
_FIELDS = {"label", "kind", "lines", "claim", "uses", "uses_note", "calls", "hypotheses",
           "readings", "grade", "fails_under", "rescued_by", "finding", "evidence",
           "checked_by", "changed"}
_REQUIRED = ("label", "kind", "lines", "claim", "uses", "hypotheses", "readings", "grade",
             "finding", "evidence", "checked_by")


class LedgerError(InputError):
    """The ledger is malformed (exit code 2)."""


@dataclass(frozen=True)
class Evidence:
    """One piece of evidence: exactly one of ``case`` (with ``verdict``), ``proof`` (a
    text in proofs/), ``script`` (a proofs/*.py whose ``check(*args)`` must not raise),
    ``witnesses`` (proofs/witnesses.py: ``refuted_readings`` readings refute the label),
    ``sweep`` (a sweep summary file, docs/ledger.md), ``certificate`` (a refutation
    certificate that exactsym.checker.verify_refutation accepts for this label),
    ``matrix`` (a stored gathering reading matrix, :mod:`.gathering_matrices`), ``coq``
    (the statement's refutation as a Coq file, written from its certificate, that
    ``coqc`` accepts: the refutation is Coq-checked), ``gather_sweep`` (a gathering
    sweep's summary, :mod:`.gather_sweep`; claims only)."""
    kind: str
    path: str
    verdict: str | None = None
    args: tuple = ()
    refuted_readings: int | None = None

    def as_dict(self) -> dict:
        out = {self.kind: self.path}
        if self.verdict is not None:
            out["verdict"] = self.verdict
        if self.args:
            out["args"] = list(self.args)
        if self.refuted_readings is not None:
            out["refuted_readings"] = self.refuted_readings
        return out


@dataclass(frozen=True)
class Statement:
    label: str
    kind: str
    lines: tuple[int, int]
    claim: str
    uses: tuple[str, ...]
    calls: tuple[str, ...]
    hypotheses: tuple[str, ...]
    readings: tuple[str, ...]
    grade: str
    fails_under: tuple[str, ...]
    rescued_by: str | None
    finding: str
    evidence: tuple[Evidence, ...]
    checked_by: str
    uses_note: str | None = None
    changed: str | None = None


@dataclass(frozen=True)
class Finding:
    """A finding about the paper with no ``\\label`` of its own (``[[finding]]``): ``id``
    names it, ``about`` lists the labelled statements it concerns; its evidence is
    re-run like a statement's (case, proof or script)."""
    id: str
    about: tuple[str, ...]
    lines: tuple[int, int]
    claim: str
    finding: str
    evidence: tuple[Evidence, ...]
    checked_by: str

    @property
    def label(self) -> str:
        """The name a mismatch is reported under (its id)."""
        return self.id


#: The grades of exactsym's own claims (``[[claim]]``): no definition, no reading.
CLAIM_GRADES = ("proved", "holds-on-cases", "open", "refuted")


@dataclass(frozen=True)
class Claim:
    """A statement of exactsym's own, not the paper's (``[[claim]]``): the corrected
    gathering algorithm's (issue 31).  ``id`` names it, ``about`` lists the paper's
    labels it repairs; its grade must follow from its evidence -- cases (verdict
    expect), proofs, scripts and ``gather_sweep`` summaries (:mod:`.gather_sweep`)."""
    id: str
    about: tuple[str, ...]
    claim: str
    grade: str
    finding: str
    evidence: tuple[Evidence, ...]
    checked_by: str

    @property
    def label(self) -> str:
        """The name a mismatch is reported under (its id)."""
        return self.id


@dataclass(frozen=True)
class Ledger:
    source: str
    statements: tuple[Statement, ...]
    findings: tuple[Finding, ...] = ()
    claims: tuple[Claim, ...] = ()

    def by_label(self) -> dict[str, Statement]:
        return {s.label: s for s in self.statements}


def load_ledger(path) -> Ledger:
    """Read and validate the ledger file ``path``."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as err:
        raise LedgerError(f"cannot read the ledger: {err.strerror}", str(path)) from None
    return parse_ledger(text, str(path))


def parse_ledger(text: str, source: str = "<ledger>") -> Ledger:
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        raise LedgerError(f"malformed TOML: {err}", source) from None
    if data.get("format") != 1:
        raise LedgerError("format must be 1", source)
    extra = set(data) - {"format", "statement", "finding", "claim"}
    if extra:
        raise LedgerError(f"unknown top-level key(s) {sorted(extra)}", source)
    entries = data.get("statement", [])
    statements = tuple(_statement(e, k, source) for k, e in enumerate(entries, 1))
    seen: dict[str, int] = {}
    for k, s in enumerate(statements, 1):
        if s.label in seen:
            raise LedgerError(f"entry {k}: label {s.label!r} already has entry {seen[s.label]}",
                              source)
        seen[s.label] = k
    missing = [label for label in STATEMENTS + ALGORITHMS if label not in seen]
    if missing:
        raise LedgerError(f"no entry for label(s) {', '.join(missing)} (every label of "
                          "exactsym.labels has exactly one entry)", source)
    findings = tuple(_finding(e, k, source) for k, e in enumerate(data.get("finding", []), 1))
    claims = tuple(_claim(e, k, source) for k, e in enumerate(data.get("claim", []), 1))
    ids = [f.id for f in findings] + [c.id for c in claims]
    if len(set(ids)) != len(ids):
        raise LedgerError(f"finding and claim ids must be unique (got {ids})", source)
    return Ledger(source, statements, findings, claims)


_CLAIM_FIELDS = {"id", "about", "claim", "grade", "finding", "evidence", "checked_by"}


def _claim(entry, k: int, source: str) -> Claim:
    where = f"claim {k}"
    if not isinstance(entry, dict) or set(entry) != _CLAIM_FIELDS:
        raise LedgerError(f"{where}: the fields are exactly {sorted(_CLAIM_FIELDS)}", source)
    cid = entry["id"]
    if not isinstance(cid, str) or not cid or cid in LABELS \
            or not all(c.isalnum() or c == "-" for c in cid):
        raise LedgerError(f"{where}: id must be a new name of letters, digits and '-' (not a "
                          f"label of the paper): {cid!r}", source)
    where = f"claim {k} ({cid})"
    about = tuple(_label(a, f"{where}: about", source)
                  for a in _strings(entry, "about", where, source))
    if not about:
        raise LedgerError(f"{where}: about must list the paper's labels it concerns", source)
    if entry["grade"] not in CLAIM_GRADES:
        raise LedgerError(f"{where}: grade must be one of {', '.join(CLAIM_GRADES)}", source)
    evidence = tuple(_evidence(e, where, source) for e in entry["evidence"])
    if not evidence or any(e.kind not in ("case", "proof", "script", "gather_sweep") or
                           e.verdict not in (None, "expect") for e in evidence):
        raise LedgerError(f"{where}: a claim needs evidence: cases (verdict expect), "
                          "proofs, scripts or gather_sweep summaries", source)
    if entry["grade"] == "proved" and not any(e.kind in ("proof", "script") for e in evidence):
        raise LedgerError(f"{where}: grade 'proved' needs a proof or a script", source)
    for key in ("claim", "finding", "checked_by"):
        if not isinstance(entry[key], str) or not entry[key]:
            raise LedgerError(f"{where}: {key} must be a non-empty string", source)
    return Claim(cid, about, entry["claim"], entry["grade"], entry["finding"], evidence,
                 entry["checked_by"])


_FINDING_FIELDS = {"id", "about", "lines", "claim", "finding", "evidence", "checked_by"}


def _finding(entry, k: int, source: str) -> Finding:
    where = f"finding {k}"
    if not isinstance(entry, dict):
        raise LedgerError(f"{where}: not a table", source)
    if set(entry) != _FINDING_FIELDS:
        raise LedgerError(f"{where}: the fields are exactly {sorted(_FINDING_FIELDS)} (got "
                          f"{sorted(entry)})", source)
    fid = entry["id"]
    if not isinstance(fid, str) or not fid or fid in LABELS \
            or not all(c.isalnum() or c == "-" for c in fid):
        raise LedgerError(f"{where}: id must be a new name of letters, digits and '-' (not a "
                          f"label of the paper): {fid!r}", source)
    where = f"finding {k} ({fid})"
    about = tuple(_label(a, f"{where}: about", source)
                  for a in _strings(entry, "about", where, source))
    lines = entry["lines"]
    if not (isinstance(lines, list) and len(lines) == 2 and all(isinstance(x, int)
                                                                 for x in lines)
            and 0 < lines[0] <= lines[1]) or not about:
        raise LedgerError(f"{where}: lines must be [first, last] line numbers and about a "
                          "non-empty list of labels", source)
    evidence = tuple(_evidence(e, where, source) for e in entry["evidence"])
    if not evidence or any(e.kind not in ("case", "proof", "script") or
                           e.verdict not in (None, "expect") for e in evidence):
        raise LedgerError(f"{where}: a finding needs evidence: cases (verdict expect), "
                          "proofs or scripts", source)
    for key in ("claim", "finding", "checked_by"):
        if not isinstance(entry[key], str) or not entry[key]:
            raise LedgerError(f"{where}: {key} must be a non-empty string", source)
    return Finding(fid, about, (lines[0], lines[1]), entry["claim"], entry["finding"],
                   evidence, entry["checked_by"])


def _label(value, where: str, source: str) -> str:
    if not isinstance(value, str):
        raise LedgerError(f"{where}: a label must be a string, not {value!r}", source)
    if value not in LABELS:
        raise LedgerError(f"{where}: {unknown_label_message(value)}", source)
    return value


def _strings(entry, key, where, source) -> tuple:
    value = entry.get(key, [])
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise LedgerError(f"{where}: {key} must be an array of strings", source)
    return tuple(value)


def _statement(entry: dict, k: int, source: str) -> Statement:
    where = f"entry {k}"
    if not isinstance(entry, dict):
        raise LedgerError(f"{where}: not a table", source)
    label = _label(entry.get("label"), where, source)
    where = f"entry {k} ({label})"
    unknown = set(entry) - _FIELDS
    if unknown:
        raise LedgerError(f"{where}: unknown field(s) {sorted(unknown)}", source)
    for key in _REQUIRED:
        if key not in entry:
            raise LedgerError(f"{where}: missing field {key!r}", source)
    kind, grade = entry["kind"], entry["grade"]
    if kind not in KINDS:
        raise LedgerError(f"{where}: kind {kind!r} is not one of {', '.join(KINDS)}", source)
    if grade not in GRADES:
        raise LedgerError(f"{where}: grade {grade!r} is not one of {', '.join(GRADES)}",
                          source)
    if (grade == "definition") != (kind in ("definition", "type")):
        raise LedgerError(f"{where}: grade 'definition' is for definitions and types only "
                          f"(kind {kind!r}, grade {grade!r})", source)
    if (kind == "algorithm") != (label in ALGORITHMS):
        raise LedgerError(f"{where}: kind 'algorithm' is for the algorithms of "
                          "exactsym.labels.ALGORITHMS", source)
    lines = entry["lines"]
    if not (isinstance(lines, list) and len(lines) == 2 and all(isinstance(x, int)
                                                                 for x in lines)
            and 0 < lines[0] <= lines[1]):
        raise LedgerError(f"{where}: lines must be [first, last] line numbers", source)
    uses = tuple(_label(u, f"{where}: uses", source) for u in _strings(entry, "uses", where,
                                                                          source))
    calls = tuple(_label(c, f"{where}: calls", source) for c in _strings(entry, "calls",
                                                                            where, source))
    if calls and kind != "algorithm":
        raise LedgerError(f"{where}: only algorithms have 'calls'", source)
    if any(c not in ALGORITHMS for c in calls):
        raise LedgerError(f"{where}: 'calls' names algorithms only", source)
    fails_under = _strings(entry, "fails_under", where, source)
    rescued_by = entry.get("rescued_by")
    if grade == "refuted-under-reading" and (not fails_under or not rescued_by):
        raise LedgerError(f"{where}: a refuted-under-reading entry says under which readings "
                          "it fails (fails_under) and which reading rescues it (rescued_by)",
                          source)
    if grade != "refuted-under-reading" and (fails_under or rescued_by):
        raise LedgerError(f"{where}: fails_under/rescued_by belong to refuted-under-reading",
                          source)
    evidence = tuple(_evidence(e, where, source) for e in entry["evidence"])
    if grade in ("refuted", "refuted-under-reading", "holds-on-cases", "proved") \
            and not evidence:
        raise LedgerError(f"{where}: grade {grade!r} needs evidence", source)
    if grade == "proved" and not any(e.kind in ("proof", "script") for e in evidence):
        raise LedgerError(f"{where}: 'proved' needs a proof or a script in proofs/", source)
    for key in ("claim", "finding", "checked_by"):
        if not isinstance(entry[key], str) or not entry[key]:
            raise LedgerError(f"{where}: {key} must be a non-empty string", source)
    return Statement(label=label, kind=kind, lines=(lines[0], lines[1]), claim=entry["claim"],
                     uses=uses, calls=calls,
                     hypotheses=_strings(entry, "hypotheses", where, source),
                     readings=_strings(entry, "readings", where, source), grade=grade,
                     fails_under=fails_under, rescued_by=rescued_by,
                     finding=entry["finding"], evidence=evidence,
                     checked_by=entry["checked_by"], uses_note=entry.get("uses_note"),
                     changed=entry.get("changed"))


def _evidence(e, where: str, source: str) -> Evidence:
    if not isinstance(e, dict):
        raise LedgerError(f"{where}: evidence entries are tables", source)
    kinds = [k for k in ("case", "proof", "script", "witnesses", "sweep", "certificate",
                         "matrix", "coq", "gather_sweep") if k in e]
    if len(kinds) != 1 or not isinstance(e[kinds[0]], str):
        raise LedgerError(f"{where}: an evidence entry has exactly one of case, proof, "
                          f"script, witnesses, sweep, certificate, matrix, coq, gather_sweep "
                          f"(got {sorted(e)})", source)
    kind = kinds[0]
    allowed = {"case": {"case", "verdict"}, "proof": {"proof"}, "script": {"script", "args"},
               "witnesses": {"witnesses", "refuted_readings"}, "sweep": {"sweep"},
               "certificate": {"certificate"}, "matrix": {"matrix"}, "coq": {"coq"},
               "gather_sweep": {"gather_sweep"}}[kind]
    if set(e) - allowed:
        raise LedgerError(f"{where}: unknown evidence field(s) {sorted(set(e) - allowed)}",
                          source)
    verdict = e.get("verdict")
    if kind == "case" and verdict not in EVIDENCE_VERDICTS:
        raise LedgerError(f"{where}: case verdict must be one of "
                          f"{', '.join(EVIDENCE_VERDICTS)} (got {verdict!r})", source)
    refuted = e.get("refuted_readings")
    if kind == "witnesses" and not isinstance(refuted, int):
        raise LedgerError(f"{where}: witnesses evidence needs refuted_readings (an integer)",
                          source)
    args = e.get("args", [])
    if not isinstance(args, list):
        raise LedgerError(f"{where}: script args must be an array", source)
    return Evidence(kind=kind, path=e[kind], verdict=verdict, args=tuple(args),
                    refuted_readings=refuted)
