"""Refutations checked by Coq (issue 35; exactsym/certificates/coq_refutation.py).

Every test that runs ``coqc`` skips, saying why, when it is not installed (Debian: ``apt-get
install coq``; ``.ci/run`` installs it when it can).  A ``coqc`` run takes about 1.4 s: by
default the library, three representative exports (a configuration in O_A; a pair of
polygons; an algorithm, with the proof that its printed loop never ends) and their
tampered versions are run; ``EXACTSYM_COQ_ALL=1``
(set by ``.ci/run``) runs every exported file and tampers with each.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from fractions import Fraction
from pathlib import Path

import pytest

from exactsym.certificates.coq_refutation import (
    CASE_STATEMENTS, STATEMENTS, CoqExportError, coq_file_name, coq_refutation,
    coq_refutation_of_points, coqc_accepts, library_text, source_of)
from exactsym.certificates.coq_gathering import GATHERING_STATEMENTS
from exactsym.ledger.evidence import coq_export
from exactsym.ledger.model import load_ledger

ROOT = Path(__file__).resolve().parents[2]
EXPORTS = ROOT / "proofs" / "coq" / "refutations"
COQC = shutil.which("coqc")
needs_coqc = pytest.mark.skipif(COQC is None, reason="coqc is not installed (apt-get install "
                                "coq): the Coq refutations are not run")
ALL = os.environ.get("EXACTSYM_COQ_ALL") == "1"
REPRESENTATIVE = ("Pasym-Pord", "obs-merg-asym-pair", "Check_Symmetry_Even")
SPECS = {**STATEMENTS, **CASE_STATEMENTS, **GATHERING_STATEMENTS}


def _ledger_coq() -> dict:
    """label -> (certificate paths, Coq file paths, statement) of every statement with
    coq evidence."""
    out = {}
    for s in load_ledger(ROOT / "proofs" / "statements.toml").statements:
        coq = [e.path for e in s.evidence if e.kind == "coq"]
        certs = [e.path for e in s.evidence if e.kind == "certificate"]
        if coq:
            out[s.label] = (certs, coq, s)
    return out


LEDGER = _ledger_coq()
RUN = sorted(LEDGER) if ALL else list(REPRESENTATIVE)


def _export(label: str) -> str:
    _, coq, s = LEDGER[label]
    return coq_export(s, ROOT, (ROOT / coq[0]).read_text())


# ------------------------------------------------------------------ no coqc needed

def test_every_certified_refutation_is_exported_and_cited():
    """Each refuted statement with a refutation certificate cites exactly its Coq file,
    and the stored file is the fresh export of the certificate."""
    ledger = load_ledger(ROOT / "proofs" / "statements.toml")
    certified = {s.label for s in ledger.statements if s.grade.startswith("refuted")
                 and any(e.kind == "certificate" for e in s.evidence)}
    assert certified == set(STATEMENTS) and set(LEDGER) == set(SPECS)
    for label, (certs, coq, s) in LEDGER.items():
        assert s.grade.startswith("refuted") and len(certs) == (label in STATEMENTS)
        # refuted under a reading: the file names it (a refuted statement may be
        # Coq-checked under one of its readings only, named too)
        assert SPECS[label]["reading"] is not None or s.grade == "refuted"
        assert coq == [f"proofs/coq/refutations/{coq_file_name(label)}"]
        source = source_of((ROOT / coq[0]).read_text())
        assert source == (certs[0] if certs else source) and (ROOT / source).is_file()
        assert (ROOT / coq[0]).read_text() == _export(label), label
    assert sorted(p.name for p in EXPORTS.glob("*.v")) == sorted(
        coq_file_name(x) for x in LEDGER)


def test_the_library_is_inlined_and_the_theorem_states_the_label():
    for label in LEDGER:
        text = _export(label)
        assert library_text().rstrip() in text
        assert "Require Import Exactsym" not in text      # self-contained
        theorem = re.search(r"Theorem (\w+) :\n(.*?)\.\nProof\.", text, re.S)
        assert theorem and theorem.group(1) == "refutes_" + re.sub(r"\W", "_", label)
        last = SPECS[label]["conclusion"][-1][0]
        assert theorem.group(2).rstrip().endswith(f"({last})" if last.startswith("forall")
                                                  else last)
        assert "Admitted" not in text and "Axiom" not in text


def test_outside_the_scope_is_an_error():
    obj = json.loads((ROOT / LEDGER["Pasym-Pord"][0][0]).read_text())
    with pytest.raises(CoqExportError, match="no Coq statement"):
        coq_refutation({**obj, "label": "Psym-Gsym"})
    with pytest.raises(CoqExportError, match="no Coq statement"):
        coq_refutation_of_points("Pasym-Pord", [("1", "0")])
    with pytest.raises(CoqExportError, match="not rational"):
        coq_refutation_of_points("Elect_Leader_Asym", [("1", "sqrt(2)")])
    cartesian = json.loads(json.dumps(obj))
    cartesian["certificate"]["configuration"]["coordinates"] = "cartesian"
    with pytest.raises(CoqExportError, match="rational polar"):
        coq_refutation(cartesian)
    pair = json.loads((ROOT / LEDGER["lem-asym-pair-ord"][0][0]).read_text())
    del pair["parts"]
    with pytest.raises(CoqExportError, match="names no part"):
        coq_refutation(pair)


def test_the_inner_level_is_g_i_whatever_the_order_of_the_parts():
    obj = json.loads((ROOT / LEDGER["obs-merg-asym-pair"][0][0]).read_text())
    swapped = {**obj, "parts": {**obj["parts"], "pair": obj["parts"]["pair"][::-1]}}
    assert coq_refutation(swapped) == coq_refutation(obj)


# ------------------------------------------------------------------ coqc

def _accepted(text: str, name: str = "Refutation.v") -> bool:
    ok, messages, _ = coqc_accepts(text, name, COQC)
    return ok


@needs_coqc
def test_the_library_compiles_on_its_own(tmp_path):
    shutil.copy(ROOT / "proofs" / "coq" / "Exactsym.v", tmp_path)
    run = subprocess.run([COQC, "-q", "Exactsym.v"], capture_output=True, text=True,
                         cwd=tmp_path, timeout=300)
    assert run.returncode == 0 and (tmp_path / "Exactsym.vo").is_file(), run.stderr


@needs_coqc
@pytest.mark.parametrize("label", RUN)
def test_coqc_accepts_the_export(label):
    ok, messages, seconds = coqc_accepts(_export(label), coq_file_name(label), COQC)
    assert ok, messages
    assert messages == "Closed under the global context"     # no axiom, nothing admitted


_LAST = re.compile(r"(  Pt )\(Qmake (\d+) (\d+)\) \(Qmake (\d+) (\d+)\)(\]\.\n)")


def _moved(text: str) -> str:
    """Every point of P turned by its own small angle (point i by (i + 1)^2/997 of a
    turn): no symmetry survives such a move, while an open set of witnesses does."""
    head, rest = text.split("Definition P : list pt := [\n", 1)
    block, tail = rest.split("].\n", 1)
    moved = []
    for i, line in enumerate(block.split(";\n")):
        m = re.fullmatch(r"(  Pt \(Qmake \d+ \d+\) )\(Qmake (\d+) (\d+)\)", line)
        t = Fraction(int(m.group(2)), int(m.group(3))) + Fraction((i + 1) ** 2, 997)
        moved.append(f"{m.group(1)}(Qmake {t.numerator} {t.denominator})")
    return f"{head}Definition P : list pt := [\n" + ";\n".join(moved) + "].\n" + tail


def _pushed_out(text: str) -> str:
    """The last point of P moved outwards, to 4 times the largest squared distance: C is
    no longer the centre of the SEC."""
    top = max(Fraction(int(a), int(b)) for a, b in
              re.findall(r"  Pt \(Qmake (\d+) (\d+)\)", text.split("Definition P :")[1]))
    def out(m):
        r = 4 * top
        return (f"{m.group(1)}(Qmake {r.numerator} {r.denominator}) "
                f"(Qmake {m.group(4)} {m.group(5)}){m.group(6)}")
    return _LAST.sub(out, text, count=1)


#: Statements whose witnesses are open sets: any scalene triangle has no leader, any
#: one-robot G_1 stays symmetric, two robots within 2 of C stay so, so small turns keep the
#: refutation (and coqc must still accept it).
_OPEN = {"Elect_Leader_Asym", "ElectLeader", "Make_SymToAsym",
         "gather-no-obstacle", "FormGPattern"}


def _flipped(text: str, label: str) -> str:
    """The theorem's last conjunct (a false conclusion of the paper) negated."""
    last = SPECS[label]["conclusion"][-1][0]
    shown = f"({last})" if last.startswith("forall") else last
    i = text.rindex(shown + ".\nProof.")
    return text[:i] + f"~ ({last})" + text[i + len(shown):]


@needs_coqc
@pytest.mark.parametrize("label", RUN)
def test_a_tampered_export_is_rejected(label):
    text = _export(label)
    assert _moved(text) != text and _pushed_out(text) != text
    # three independent coqc processes at once: the CI runs this for every export
    with ThreadPoolExecutor(3) as pool:
        pushed, moved, flipped = pool.map(
            _accepted, [_pushed_out(text), _moved(text), _flipped(text, label)])
    assert not pushed, "a point moved off the SEC passed"
    assert moved == (label in _OPEN), "a moved point"
    assert not flipped, "the flipped claim passed"
    if label != RUN[0]:
        return                          # the axiom is one more coqc run: once is enough
    name = "refutes_" + re.sub(r"\W", "_", label)
    cheat = re.sub(r"(Theorem " + name + r" :.*?Proof\.).*?Qed\.",
                   lambda m: m.group(1) + " exact (False_ind _ cheat). Qed.", text, flags=re.S)
    cheat = cheat.replace(f"Theorem {name} :", f"Axiom cheat : False.\nTheorem {name} :")
    assert "exact (False_ind _ cheat)" in cheat
    assert not _accepted(cheat), "a proof by an axiom passed"


def _transform(obj: dict, turn=lambda t: t, r2=lambda r: r) -> dict:
    """The refutation with every point (of P and of its parts) moved by a similarity
    about C: the turns by ``turn``, the squared radii by ``r2``."""
    obj = json.loads(json.dumps(obj))
    configs = [obj["certificate"]["configuration"]]
    for part in (obj.get("parts") or {}).values():
        configs += [c["configuration"] for c in (part if isinstance(part, list) else [part])]
    for c in configs:
        c["points"] = [[str(r2(Fraction(r))), str(turn(Fraction(t)))] for r, t in c["points"]]
    return obj


@needs_coqc
@pytest.mark.parametrize("label", ["lem-all-pair-asym-ord", "lemma-sym-regular"] if ALL
                         else ["lem-all-pair-asym-ord"])
def test_a_similar_configuration_is_refuted_too(label):
    """Rotated by 2/7 of a turn, mirrored and scaled by 9 (radii by 3): still accepted."""
    obj = json.loads((ROOT / LEDGER[label][0][0]).read_text())
    moved = _transform(obj, turn=lambda t: Fraction(2, 7) - t, r2=lambda r: 9 * r)
    text = coq_refutation(moved)
    assert text != coq_refutation(obj)
    assert _accepted(text)


@needs_coqc
def test_certify_writes_a_file_coqc_accepts(tmp_path):
    out = tmp_path / "Hexagon.v"
    run = subprocess.run([sys.executable, "-m", "exactsym", "certify", "--refutes",
                          "obs-exh-poly", str(ROOT / "cases/discrepancies/d3-hexagon.toml"),
                          "--coq", str(out)], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    assert _accepted(out.read_text(), "Hexagon.v")


def test_certify_coq_needs_refutes(tmp_path):
    run = subprocess.run([sys.executable, "-m", "exactsym", "certify",
                          str(ROOT / "cases/discrepancies/d3-hexagon.toml"),
                          "--coq", str(tmp_path / "X.v")], capture_output=True, text=True,
                         timeout=300)
    assert run.returncode == 2 and "--refutes" in run.stderr
    assert not (tmp_path / "X.v").exists()


def test_ledger_export_coq_writes_the_stored_files(tmp_path):
    run = subprocess.run([sys.executable, "-m", "exactsym", "ledger", "--root", str(ROOT),
                          "--export-coq", str(tmp_path)], capture_output=True, text=True,
                         timeout=300)
    assert run.returncode == 0, run.stderr
    written = {p.name: p.read_text() for p in tmp_path.glob("*.v")}
    assert written == {p.name: p.read_text() for p in EXPORTS.glob("*.v")}


def test_a_statement_about_strings_is_written_from_its_case_only(tmp_path):
    """certify writes the Coq file alone (no Python certificate), naming the case."""
    case = "cases/discrepancies/scalene-triangle.toml"
    out = tmp_path / "E.v"
    run = subprocess.run([sys.executable, "-m", "exactsym", "certify", "--refutes",
                          "Elect_Leader_Asym", case, "--coq", str(out)], cwd=ROOT,
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    assert source_of(out.read_text()) == case
    run = subprocess.run([sys.executable, "-m", "exactsym", "certify", "--refutes",
                          "Elect_Leader_Asym", case, "--coq", str(out), "-o", "-"], cwd=ROOT,
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 2 and "no certificate" in run.stderr


def test_certify_needs_an_output():
    run = subprocess.run([sys.executable, "-m", "exactsym", "certify",
                          str(ROOT / "cases/discrepancies/d3-hexagon.toml")],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 2 and "-o CERT.json" in run.stderr


#: A mirror inside a half-turn: three robots symmetric only in the line at 1/4 turn
#: (Mirror 1/2), six only under the half-turn; (r^2, turn).
_PAIR_POINTS = [(1, "1/4"), (1, "1/20"), (1, "9/20"), (4, "0"), (4, "1/10"), (4, "1/4"),
                (4, "1/2"), (4, "3/5"), (4, "3/4")]


def test_an_orderable_pair_is_proved_by_the_library_theorem():
    """The proof kind 'P is orderable': orderable_of_only_identity, never by computation
    of an ordering in the file."""
    text = coq_refutation_of_points("lem-sym-notord", _PAIR_POINTS)
    assert text.rstrip().endswith("Print Assumptions refutes_lem_sym_notord.")
    assert "orderable (G1 ++ G2).\nProof." in text
    assert "apply orderable_of_only_identity; vm_compute; reflexivity.\nQed." in text
    assert "Theorem orderable_of_only_identity : forall P, sec_centred P = true ->\n" \
        "  only_identity P = true -> orderable P." in library_text()


@needs_coqc
def test_orderable_is_accepted_and_a_symmetric_union_rejected():
    """The pair turned by 2/7, mirrored and scaled is still orderable (accepted); with
    one robot of the outer ring moved from 3/5 to 2/5 of a turn the pair is still
    symmetric (the line at 1/4 turn is now a mirror of both), but the mirror maps the
    union onto itself and moves robots: orderable_of_only_identity does not apply and
    coqc rejects the file; the negation, "not orderable", is proved instead
    (not_orderable_by_candidates)."""
    moved = [(9 * r, Fraction(2, 7) - Fraction(t)) for r, t in _PAIR_POINTS]
    assert _accepted(coq_refutation_of_points("lem-sym-notord", moved))
    symmetric = [(r, "2/5" if (r, t) == (4, "3/5") else t) for r, t in _PAIR_POINTS]
    text = coq_refutation_of_points("lem-sym-notord", symmetric)
    assert "symmetric_pair G1 G2 = true" in text
    assert not _accepted(text)
    negated = text.replace("  orderable (G1 ++ G2).\nProof.", "  ~ orderable (G1 ++ G2).\nProof.")
    negated = negated.replace("apply orderable_of_only_identity; vm_compute; reflexivity.\nQed.",
                              "apply not_orderable_by_candidates; vm_compute; reflexivity.\nQed.")
    assert negated != text and _accepted(negated)       # provably not orderable


def _library_goal(points, claim: str, tactic: str) -> str:
    """The library, a configuration Q (canonical (r^2, turn) pairs) and one theorem."""
    block = ";\n".join(f"  Pt (Qmake {Fraction(r).numerator} {Fraction(r).denominator}) "
                       f"(Qmake {Fraction(t).numerator} {Fraction(t).denominator})"
                       for r, t in points)
    return (library_text().rstrip() + f"\n\nDefinition Q : list pt := [\n{block}].\n"
            f"Theorem t : {claim}.\nProof. {tactic}. Qed.\nPrint Assumptions t.\n")


@needs_coqc
def test_no_leader_is_not_just_not_orderable():
    """MakeAsym's conclusion '~ electable P' (a symmetry moves every robot) is not
    '~ orderable P': five robots with one mirror through one of them are not orderable,
    yet that robot is fixed, so 'not electable' must not be provable; an orderable pair
    is electable (electable_of_only_identity)."""
    d1 = [(1, 0), (1, "1/5"), (1, "4/5"), (4, "1/3"), (4, "2/3")]
    assert _accepted(_library_goal(d1, "~ orderable Q",
                                   "apply not_orderable_by_candidates; vm_compute; reflexivity"))
    assert not _accepted(_library_goal(
        d1, "~ electable Q", "apply not_electable_by_candidates; vm_compute; reflexivity"))
    assert _accepted(_library_goal(
        _PAIR_POINTS, "electable Q",
        "apply electable_of_only_identity; vm_compute; reflexivity"))


@needs_coqc
def test_orderable_is_never_concluded_off_centre():
    """The library's orderable is the paper's only about the SEC's centre (T1): an
    isosceles triangle (Cartesian (1, 0), (2, 0), (3/2, 3/2), in O_S) and two points, with
    the origin off their SEC's centre, have the identity as their only symmetry about the
    origin, yet orderable_of_only_identity does not apply to them (it needs sec_centred)."""
    for off in ([(1, 0), (4, 0), ("9/2", "1/8")], [(1, 0), (4, 0)]):
        assert not _accepted(_library_goal(
            off, "orderable Q", "apply orderable_of_only_identity; vm_compute; reflexivity"))
        assert _accepted(_library_goal(off, "sec_centred Q = false /\\ only_identity Q = true",
                                       "split; vm_compute; reflexivity"))
    # an equilateral triangle about its SEC's centre, turned and scaled: not orderable
    tri = [(4, Fraction(2, 7) + Fraction(k, 3)) for k in range(3)]
    assert _accepted(_library_goal(tri, "~ orderable Q",
                                   "apply not_orderable_by_candidates; vm_compute; reflexivity"))


@needs_coqc
def test_the_empty_set_is_not_symmetric():
    """def-skewed-symmetric-conf needs a line not containing all of P: none for P empty
    (a half-turn maps [] onto itself only vacuously); a one-robot polygon minus its robot
    is then asymmetric, so Elect_Leader_Asym's loop stops at it."""
    assert _accepted(_library_goal([(1, 0)], "symmetric_conf [] = false /\\ "
                                   "symmetric_conf Q = true /\\ leader_candidates Q = Q",
                                   "vm_compute; split; [reflexivity | split; reflexivity]"))


def _scaled_export(label: str, factor: Fraction) -> str:
    """The stored export of ``label`` with every squared distance of P (and of the named
    levels) multiplied by ``factor``."""
    text = _export(label)
    head, rest = text.split("Definition P : list pt := [\n", 1)
    block, tail = rest.split("].\n", 1)
    def scaled(m):
        r = Fraction(int(m.group(2)), int(m.group(3))) * factor
        return f"{m.group(1)}Qmake {r.numerator} {r.denominator}"
    block = re.sub(r"(  Pt \()Qmake (\d+) (\d+)", scaled, block)
    tail = re.sub(r"(Definition r\w+ : Q := \()Qmake (\d+) (\d+)", scaled, tail)
    return f"{head}Definition P : list pt := [\n{block}].\n{tail}"


@needs_coqc
@pytest.mark.parametrize("label", ["GatheringPattern", "MakeAsym"])
def test_fat_robot_witnesses_are_separated_only_when_scaled(label):
    """GatheringPattern's input is 'R, the set of separated robots' (unit discs, more
    than 2 apart): the export is its source case scaled by 100 in r^2; at the source's
    scale (r^2 / 100) the robots overlap and coqc rejects the file; scaled by 4 more it is
    accepted (a scaled witness: nothing else changes)."""
    text = _export(label)
    assert "separated P = true" in text and "multiplied by 100" in text
    assert not _accepted(_scaled_export(label, Fraction(1, 100)))
    if ALL or label == "MakeAsym":
        assert _accepted(_scaled_export(label, Fraction(4)))
