"""The gathering statements as Coq refutations (issue 35; exactsym/certificates/coq_gathering.py,
proofs/coq/Gathering.v): each stored file is its fresh export, coqc accepts it, and a
tampered start or snapshot is rejected.  Tests that run ``coqc`` skip, saying why, when it
is not installed."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest

from exactsym.certificates.coq_gathering import (GATHERING_STATEMENTS,
                                                 coq_gathering_of_points,
                                                 gathering_library_text)
from exactsym.certificates.coq_refutation import (CoqExportError, coq_file_name,
                                                  coqc_accepts, library_text, source_of)
from exactsym.geometry.configuration import from_file
from exactsym.io.fileformat import read_config
from exactsym.ledger.evidence import coq_export
from exactsym.ledger.model import load_ledger

ROOT = Path(__file__).resolve().parents[2]
COQC = shutil.which("coqc")
needs_coqc = pytest.mark.skipif(COQC is None, reason="coqc is not installed (apt-get install "
                                "coq): the Coq refutations are not run")
STATEMENTS = {s.label: s for s in load_ledger(ROOT / "proofs" / "statements.toml").statements}


def _stored(label: str) -> str:
    return (ROOT / "proofs" / "coq" / "refutations" / coq_file_name(label)).read_text()


def _points(label: str) -> list:
    config = from_file(read_config(str(ROOT / source_of(_stored(label)))))
    return [(Fraction(str(r)), Fraction(str(t))) for r, t in config.polar]


def _export(label: str, points=None) -> str:
    return coq_gathering_of_points(label, points if points is not None else _points(label),
                                   source_of(_stored(label)), STATEMENTS[label].claim)


def _accepted(text: str, name: str = "Gathering_refutation.v") -> bool:
    ok, messages, _ = coqc_accepts(text, name, COQC)
    return ok


# ------------------------------------------------------------------ no coqc needed

@pytest.mark.parametrize("label", sorted(GATHERING_STATEMENTS))
def test_each_gathering_statement_is_cited_and_stored_as_its_export(label):
    s = STATEMENTS[label]
    assert s.grade.startswith("refuted")
    coq = [e.path for e in s.evidence if e.kind == "coq"]
    assert coq == [f"proofs/coq/refutations/{coq_file_name(label)}"]
    text = _stored(label)
    assert text == coq_export(s, ROOT, text) == _export(label)
    # the source case is cited as evidence too, and both libraries are inlined
    assert any(e.kind == "case" and e.path == source_of(text) for e in s.evidence)
    assert library_text().rstrip() in text and gathering_library_text().rstrip() in text
    assert "Refuted under the reading:" in text and "Admitted" not in text
    assert "Axiom" not in text


def test_outside_the_scope_is_an_error():
    with pytest.raises(CoqExportError, match="no Coq statement"):
        coq_gathering_of_points("Pasym-Pord", [("1", "0")])
    with pytest.raises(CoqExportError, match="not rational"):
        coq_gathering_of_points("lem-vl-move", [("1", "sqrt(2)")])


def test_the_export_depends_on_the_points():
    points = _points("gather-no-obstacle")
    moved = [(r, t + Fraction(1, 5)) for r, t in points]
    assert _export("gather-no-obstacle", moved) != _export("gather-no-obstacle")


# ------------------------------------------------------------------ coqc

@needs_coqc
def test_the_gathering_library_compiles_on_its_own(tmp_path):
    text = library_text() + "\n" + gathering_library_text()
    (tmp_path / "Gathering.v").write_text(text)
    run = subprocess.run([COQC, "-q", "Gathering.v"], capture_output=True, text=True,
                         cwd=tmp_path, timeout=300)
    assert run.returncode == 0 and (tmp_path / "Gathering.vo").is_file(), run.stderr


@needs_coqc
@pytest.mark.parametrize("label", sorted(GATHERING_STATEMENTS))
def test_coqc_accepts_the_export(label):
    ok, messages, _ = coqc_accepts(_stored(label), coq_file_name(label), COQC)
    assert ok and messages == "Closed under the global context", messages


def _with_point(points: list, index: int, r2, turn) -> list:
    out = list(points)
    out[index] = (Fraction(r2), Fraction(turn))
    return out


@needs_coqc
def test_a_tampered_obstacle_start_is_rejected():
    """Robot 1 pushed out to exactly 2 from C (touching is no overlap): the leader robot 0
    then reaches C freely; robot 1 put within 2 of robot 0 (not separated); robot 1 put
    at C (C occupied): each rejected.  Turned by 2/7 and mirrored: still accepted."""
    label = "gather-no-obstacle"
    points = _points(label)
    assert _accepted(_export(label, [(r, Fraction(2, 7) - t) for r, t in points]))
    for r2, turn in (("4", "1/2"), ("81/25", "1/20"), ("0", "0")):
        tampered = _export(label, _with_point(points, 1, r2, turn))
        assert not _accepted(tampered), (r2, turn)


@needs_coqc
def test_a_tampered_snapshot_is_rejected():
    """lem-vl-move: the Look at the start of the move (lam = 0: G_t still symmetric), G_1
    turned so that its mirror is G_t's (apex at turn 1/4: calG' in O_S, GatheringPattern
    stops), G_1 made equilateral (three mirrors: ElectLeader's first branch not taken),
    and G_1 a single robot (the former witness: no degree of symmetry one, so the theorem
    says nothing about ElectLeader's leader): each rejected; turned by 2/7 and mirrored:
    still accepted."""
    label = "lem-vl-move"
    text = _stored(label)
    at_start = text.replace("Definition lam : Q := (Qmake 1 2).",
                            "Definition lam : Q := (Qmake 0 1).")
    assert at_start != text and not _accepted(at_start)
    points = _points(label)
    outer = [(r, t) for r, t in points if r == 400]
    inner = [t for r, t in points if r == 9]
    assert len(outer) == 4 and len(inner) == 3
    apex = Fraction(1, 24)
    assert apex in inner
    for triangle in ([Fraction(1, 4) + d for d in (0, Fraction(1, 5), Fraction(-1, 5))],
                     [apex + d for d in (0, Fraction(1, 3), Fraction(-1, 3))],
                     [apex]):
        tampered = outer + [(Fraction(9), t % 1) for t in triangle]
        assert not _accepted(_export(label, tampered)), triangle
    assert _accepted(_export(label, [(r, Fraction(2, 7) - t) for r, t in points]))


@needs_coqc
def test_another_epsilon_and_instant_is_refuted_too():
    """lem-vl-move's snapshot is not tuned to one epsilon or one instant: a tenth of the
    epsilon, a third of the way, is refuted as well."""
    text = _stored("lem-vl-move")
    other = text.replace("Definition eps : Q := (Qmake 1 100).",
                         "Definition eps : Q := (Qmake 1 1000).")
    other = other.replace("Definition lam : Q := (Qmake 1 2).",
                          "Definition lam : Q := (Qmake 1 3).")
    assert other.count("(Qmake 1 1000)") == 1 and other.count("(Qmake 1 3).") == 1
    assert _accepted(other)


@needs_coqc
def test_a_flipped_claim_is_rejected():
    text = _stored("lem-vl-move")
    flipped = re.sub(r"\(G_t P\) = true\)\.\nProof\.", "(G_t P) = false).\nProof.", text)
    assert flipped != text and not _accepted(flipped)


@needs_coqc
def test_certify_writes_the_stored_file(tmp_path):
    out = tmp_path / "lem_vl_move.v"
    source = source_of(_stored("lem-vl-move"))
    run = subprocess.run([sys.executable, "-m", "exactsym", "certify", "--refutes",
                          "lem-vl-move", source, "--coq", str(out)], cwd=ROOT,
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    # certify quotes no ledger claim; otherwise the same file
    stored = re.sub(r"\n   The ledger \(proofs/statements.toml\): .*", "", _stored("lem-vl-move"))
    assert out.read_text() == stored
