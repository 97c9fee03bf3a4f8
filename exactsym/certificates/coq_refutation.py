"""Refutations that Coq re-checks (issue 35; docs/certificates.md, "Coq").

``coq_refutation(refutation)`` turns a refutation certificate of
:mod:`.refutation` (``certify --refutes LABEL``) into one self-contained Coq file: the
library ``proofs/coq/Exactsym.v`` (the paper's definitions as decision procedures, each
citing its \\label) inlined, the configuration as exact rationals, and one theorem stating
in the paper's terms that the configuration meets the statement's hypotheses and that its
conclusion is false, proved by ``vm_compute`` (and, for "not orderable", by the library's
theorem ``not_orderable_by_candidates``).  ``coqc FILE.v`` accepting it is the check;
nothing of exactsym is trusted by it.

Scope: the statements of :data:`STATEMENTS` on rational polar configurations (every
shipped refutation certificate is one).  Which levels of P the theorem names is read from
the certificate's parts; Coq recomputes the levels from P itself, so a wrong part makes
the file fail, not pass.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

__all__ = ["CoqExportError", "STATEMENTS", "coq_file_name", "coq_refutation", "coqc_accepts",
           "library_text", "theorem_name"]

#: The library every exported file inlines, in the source tree (issue 35: one copy).
LIBRARY = Path(__file__).resolve().parents[2] / "proofs" / "coq" / "Exactsym.v"


class CoqExportError(ValueError):
    """The refutation cannot be written as a Coq file (a label or a configuration
    outside the exporter's scope)."""


#: label -> (the paper's words, the names the theorem needs besides P, its hypotheses
#: (Coq boolean terms, each ``= true``), the negated conclusion (a Coq proposition)).
#: ``Gi``/``Gj``/``G`` are levels of P named by the certificate's parts.
STATEMENTS = {
    "Pasym-Pord": (
        "Theorem Pasym-Pord, 'if': P is orderable if P is in O_A.",
        (), ["Nat.leb 2 (length P)", "in_O_A P"], "~ orderable P"),
    "lem-asym-ord": (
        "Lemma lem-asym-ord: an asymmetric polygon is orderable.",
        (), ["polygon P", "asymmetric_polygon P"], "~ orderable P"),
    "cor-Pasym-Pord": (
        "Corollary cor-Pasym-Pord, 'if': P is orderable if calG_P is in O_A.",
        (), ["forallb polygon (polygons P)", "calG_in_O_A (polygons P)"], "~ orderable P"),
    "lem-one-pair-asym-ord": (
        "Lemma lem-one-pair-asym-ord: if calG contains at least one asymmetric polygon "
        "then calG is orderable.",
        ("G",), ["existsb (Qeq_bool rG) (radii P)", "polygon G", "asymmetric_polygon G"],
        "~ orderable P"),
    "lem-asym-pair-ord": (
        "Lemma lem-asym-pair-ord: an asymmetric pair is orderable.",
        ("Gi", "Gj"), ["existsb (Qeq_bool rGi) (radii P)", "existsb (Qeq_bool rGj) (radii P)",
                       "negb (Qeq_bool rGi rGj)", "polygon Gi", "polygon Gj",
                       "asymmetric_pair Gi Gj"], "~ orderable (Gi ++ Gj)"),
    "lem-all-pair-asym-ord": (
        "Lemma lem-all-pair-asym-ord: if there exists an asymmetric pair in calG, then "
        "calG is orderable.",
        ("Gi", "Gj"), ["existsb (Qeq_bool rGi) (radii P)", "existsb (Qeq_bool rGj) (radii P)",
                       "negb (Qeq_bool rGi rGj)", "polygon Gi", "polygon Gj",
                       "asymmetric_pair Gi Gj"], "~ orderable P"),
    "obs-merg-asym-pair": (
        "Observation obs-merg-asym-pair: if <G_i, G_j> is an asymmetric pair, then the "
        "polygon G_ij is asymmetric.",
        ("Gi", "Gj"), ["existsb (Qeq_bool rGi) (radii P)", "existsb (Qeq_bool rGj) (radii P)",
                       "Qlt_bool rGi rGj", "polygon Gi", "polygon Gj",
                       "asymmetric_pair Gi Gj", "polygon (merged Gi Gj)"],
        "asymmetric_polygon (merged Gi Gj) = false"),
    "lemma-sym-regular": (
        "Lemma lemma-sym-regular: if a polygon G is convex and has more than one line of "
        "symmetry such that each line of symmetry passes through at least one vertex of G, "
        "then G is regular.",
        (), ["polygon P", "negb (is_symmetry half_turn P)", "Nat.leb 2 (length (mirrors P))",
             "forallb (through_vertex P) (mirrors P)"], "regular P = false"),
    "obs-exh-poly": (
        "Observation obs-exh-poly: the above characterization (types 0-4) of straight "
        "symmetric polygons is exhaustive.",
        (), ["polygon P", "straight_symmetric P"], "some_type P = false"),
}

#: What each hypothesis list reads as, for the file's comment (informative).
_NOTES = {
    "lemma-sym-regular": "No half-turn: otherwise every line through C is a line of skew "
                         "symmetry, and one misses every vertex; so the lines of symmetry "
                         "are exactly the mirrors, under either reading of 'line of symmetry'.",
    "obs-merg-asym-pair": "G_i is the inner polygon (i < j); G_ij its vertices projected "
                          "radially onto G_j's circle, with G_j ([polygon] also checks that "
                          "no projected vertex falls on a vertex of G_j).",
}


def library_text() -> str:
    """The Coq library, ``proofs/coq/Exactsym.v``."""
    try:
        return LIBRARY.read_text(encoding="utf-8")
    except OSError as err:
        raise CoqExportError(f"the Coq library {LIBRARY.name} is not here (it lives in "
                             "the source tree, proofs/coq/)") from err


def theorem_name(label: str) -> str:
    return "refutes_" + "".join(c if c.isalnum() else "_" for c in label)


def _q(value) -> str:
    """A rational as a Coq term of type Q."""
    f = Fraction(str(value))
    return f"(Qmake {f.numerator} {f.denominator})" if f.numerator >= 0 else \
        f"(Qmake ({f.numerator}) {f.denominator})"


def _points(config: dict) -> list[tuple[Fraction, Fraction]]:
    if config.get("coordinates") != "polar" or config.get("field") is not None:
        raise CoqExportError("only rational polar configurations are exported to Coq "
                             "(number fields: not yet)")
    try:
        return [(Fraction(str(r)), Fraction(str(t))) for r, t in config["points"]]
    except (ValueError, TypeError) as err:
        raise CoqExportError(f"a coordinate is not rational: {err}") from None


def _level_radii(refutation: dict, names: tuple) -> dict:
    """The squared radius of each level the theorem names, from the certificate's parts."""
    parts = refutation.get("parts") or {}
    if names == ("G",):
        certs = [parts.get("level")]
    elif names == ("Gi", "Gj"):
        certs = list(parts.get("pair") or [])
    else:
        return {}
    if len(certs) != len(names) or any(not isinstance(c, dict) for c in certs):
        raise CoqExportError(f"the certificate names no part for {', '.join(names)}")
    radii = [_points(c["configuration"])[0][0] for c in certs]
    if names == ("Gi", "Gj") and radii[0] > radii[1]:
        radii.reverse()                 # G_i is the inner polygon (obs-merg-asym-pair)
    return dict(zip(names, radii))


def coq_refutation(refutation: dict, statement: str | None = None) -> str:
    """The Coq file refuting ``refutation["label"]`` on its configuration.  ``statement``
    (the ledger's claim) is quoted in the header when given."""
    label = refutation.get("label")
    if label not in STATEMENTS:
        raise CoqExportError(f"no Coq statement for {label!r} (exported: "
                             f"{', '.join(sorted(STATEMENTS))})")
    words, names, hypotheses, negated = STATEMENTS[label]
    cert = refutation["certificate"]
    points = _points(cert["configuration"])
    levels = _level_radii(refutation, names)
    source = (cert.get("source") or {}).get("file") or refutation.get("source", {}).get("file")
    out = [f"(* Refutation of {label}, checked by Coq: `coqc` on this file alone.",
           f"   The paper: {words}"]
    if statement:
        out.append(f"   The ledger (proofs/statements.toml): {statement}")
    if source:
        out.append(f"   The configuration: {source}.")
    out += ["   Written by `exactsym certify --refutes` (exactsym/certificates/coq_refutation.py)",
            "   from its refutation certificate; the library below is proofs/coq/Exactsym.v,",
            "   inlined: it holds every definition the theorem uses. *)", ""]
    out.append(library_text().rstrip())
    out += ["", "(* ================================================= the configuration *)", "",
            "(* P: (squared distance from C, turn) of each point. *)",
            "Definition P : list pt := ["]
    out.append(";\n".join(f"  Pt {_q(r)} {_q(t)}" for r, t in points) + "].")
    for name, r in levels.items():
        out.append(f"Definition r{name} : Q := {_q(r)}.")
        out.append(f"Definition {name} : list pt := level P r{name}.")
    out.append("")
    if label in _NOTES:
        out.append(f"(* {_NOTES[label]} *)")
    hypotheses = ["distinct P", "sec_centred P", *hypotheses]
    claim = " /\\\n  ".join([f"{h} = true" for h in hypotheses] + [negated])
    tactic = "apply not_orderable_by_candidates; vm_compute; reflexivity" \
        if negated.startswith("~ orderable") else "vm_compute; reflexivity"
    splits = ["vm_compute; reflexivity"] * len(hypotheses) + [tactic]
    out += [f"(* P is a set about C, the centre of its SEC (T1); the hypotheses of {label}",
            "   hold and its conclusion is false. *)",
            f"Theorem {theorem_name(label)} :\n  {claim}.", "Proof."]
    out += [f"  split; [{t} |]." for t in splits[:-1]] + [f"  {splits[-1]}."]
    out += ["Qed.", "", f"Print Assumptions {theorem_name(label)}.", ""]
    return "\n".join(out)


def coq_file_name(label: str) -> str:
    """The file name of a label's Coq refutation (a Coq module name: no '-')."""
    return "".join(c if c.isalnum() else "_" for c in label) + ".v"


def coqc_accepts(text: str, name: str = "Refutation.v",
                 coqc: str | None = None) -> tuple[bool, str, float]:
    """``(accepted, coqc's messages, seconds)``: run ``coqc`` on ``text`` alone in a
    fresh temporary directory (nothing else on its load path).  Raises
    :class:`CoqExportError` when no ``coqc`` is installed."""
    import shutil
    import subprocess
    import tempfile
    import time
    coqc = coqc or shutil.which("coqc")
    if not coqc:
        raise CoqExportError("coqc is not installed (Debian: apt-get install coq)")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / name
        path.write_text(text, encoding="utf-8")
        start = time.perf_counter()
        run = subprocess.run([coqc, "-q", path.name], cwd=tmp, capture_output=True,
                             text=True, timeout=600)
        seconds = time.perf_counter() - start
    messages = (run.stdout + run.stderr).strip()
    accepted = run.returncode == 0 and "Closed under the global context" in messages
    return accepted, messages, seconds
