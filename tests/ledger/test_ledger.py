"""The statement ledger (proofs/statements.toml, exactsym.ledger) and label validation."""

from __future__ import annotations

import importlib.util
import json
import tomllib
import os
import sys
from pathlib import Path

import pytest

from exactsym.report.cases import case_files, label_counts, run_cases
from exactsym.cli.main import main as exactsym_main
from exactsym.errors import InputError
from exactsym.labels import ALGORITHMS, LABELS, STATEMENTS, nearest_label
from exactsym.ledger import LedgerError, load_ledger
from exactsym.ledger.audit_doc import render
from exactsym.ledger.cli import AUDIT, LEDGER, main as ledger_main
from exactsym.ledger.evidence import check_evidence, load_sweep
from exactsym.ledger.graph import cycles, support
from exactsym.ledger.model import Evidence, Ledger, Statement, parse_ledger

ROOT = Path(__file__).resolve().parents[2]
PROOFS = ROOT / "proofs"


def _proofs_module(name):
    sys.path.insert(0, str(PROOFS))
    spec = importlib.util.spec_from_file_location(f"test_proofs_{name}", PROOFS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# ---------------------------------------------------------------- labels
def test_labels_are_the_readme_numbering():
    assert len(STATEMENTS) == len(set(STATEMENTS)) == 65
    assert len(ALGORITHMS) == 12
    assert {"obs-type-4", "obs1-Gprime-equiG", "Gprime-equiG", "type-0", "hull-symmetric",
            "gather-no-obstacle", "Find_Asymmetry_Pair"} <= LABELS
    assert "obs-type 4" not in LABELS


@pytest.mark.parametrize("typo, nearest", [("lem-sym-notrod", "lem-sym-notord"),
                                           ("obs-type 4", "obs-type-4"),
                                           ("makeasym", "MakeAsym"),
                                           ("Gprime-equivG", "Gprime-equiG")])
def test_nearest_label(typo, nearest):
    assert nearest_label(typo) == nearest


def test_unknown_label_in_a_case_file_exits_2_naming_the_nearest(tmp_path, capsys):
    f = tmp_path / "c.toml"
    f.write_text('format = 1\nlemmas = ["lem-asym-ord", "lem-sym-notrod"]\n'
                 'points = [[0, 0], [1, 0]]\n')
    assert exactsym_main(["check", str(f)]) == 2
    err = capsys.readouterr().err
    assert "c.toml:2:" in err and "'lem-sym-notrod'" in err and "'lem-sym-notord'" in err


def test_cases_lemma_unknown_label_exits_2(capsys):
    assert exactsym_main(["cases", str(ROOT / "cases"), "--lemma", "Psym-Gsim"]) == 2
    assert "'Psym-Gsym'" in capsys.readouterr().err
    with pytest.raises(InputError):
        run_cases(ROOT / "cases", "Psym-Gsim")


def test_cases_labels_counts(capsys):
    counts = label_counts(ROOT / "cases")
    assert list(counts) == list(STATEMENTS + ALGORITHMS)
    tagged = [p for p in case_files(ROOT / "cases") if p.suffix == ".toml"
              and "Psym-Gsym" in tomllib.loads(p.read_text()).get("lemmas", [])]
    assert counts["Psym-Gsym"] == len(tagged) > 0
    assert exactsym_main(["cases", str(ROOT / "cases"), "--labels"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert f"{counts['Psym-Gsym']:4d}  Psym-Gsym" in lines and len(lines) == len(LABELS)


# ---------------------------------------------------------------- validation
def _toml(v) -> str:
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k} = {_toml(x)}" for k, x in v.items()) + "}"
    if isinstance(v, list):
        return "[" + ", ".join(_toml(x) for x in v) + "]"
    return json.dumps(v)


def _minimal_ledger(**override) -> str:
    """A ledger text with one definition entry per label, ``override`` replacing fields of
    the entry of ``override['label']``."""
    out = ["format = 1"]
    for label in STATEMENTS + ALGORITHMS:
        kind = "algorithm" if label in ALGORITHMS else "definition"
        grade = "open" if kind == "algorithm" else "definition"
        fields = {"label": label, "kind": kind, "lines": [1, 2], "claim": "c", "uses": [],
                  "hypotheses": [], "readings": [], "grade": grade, "finding": "f",
                  "evidence": [], "checked_by": "none yet"}
        if override.get("label") == label:
            fields.update(override)
        out.append("[[statement]]")
        out += [f"{k} = {_toml(v)}" for k, v in fields.items()]
    return "\n".join(out) + "\n"


def test_minimal_ledger_is_valid():
    ledger = parse_ledger(_minimal_ledger())
    assert len(ledger.statements) == len(LABELS)


@pytest.mark.parametrize("override, words", [
    ({"label": "lem-los-gij", "kind": "lemma", "grade": "open",
      "uses": ["obs-gdc"]}, ["'obs-gdc'", "'obs-gcd'"]),
    ({"label": "MakeAsym", "grade": "wrong"}, ["grade 'wrong'"]),
    ({"label": "lem-los-gij", "kind": "lemma", "grade": "refuted-under-reading",
      "evidence": [{"proof": "p.md"}]}, ["fails_under"]),
    ({"label": "lem-los-gij", "kind": "lemma", "grade": "proved",
      "evidence": [{"case": "x.toml", "verdict": "expect"}]}, ["proof or a script"]),
    ({"label": "lem-los-gij", "kind": "lemma", "grade": "refuted",
      "evidence": [{"case": "x.toml", "verdict": "maybe"}]}, ["verdict"]),
    ({"label": "lem-los-gij", "kind": "lemma", "grade": "definition"}, ["'definition'"]),
])
def test_invalid_ledgers_are_rejected(override, words):
    with pytest.raises(LedgerError) as err:
        parse_ledger(_minimal_ledger(**override))
    for w in words:
        assert w in str(err.value)


def test_unknown_and_missing_labels(tmp_path):
    text = _minimal_ledger().replace('label = "obs-gcd"', 'label = "obs-gdc"')
    with pytest.raises(LedgerError, match="nearest known label: 'obs-gcd'"):
        parse_ledger(text)
    start = text.index('[[statement]]\nlabel = "obs-gdc"')
    end = text.index("[[statement]]", start + 1)
    with pytest.raises(LedgerError, match="no entry for label.*obs-gcd"):
        parse_ledger(text[:start] + text[end:])
    # the command exits 2 and names the nearest label
    (tmp_path / "proofs").mkdir()
    (tmp_path / "docs").mkdir()
    (tmp_path / "proofs" / "statements.toml").write_text(text)
    assert ledger_main(["--root", str(tmp_path), "--no-write"]) == 2


# ---------------------------------------------------------------- propagation
def _toy(grades: dict, uses: dict) -> Ledger:
    return Ledger("toy", tuple(
        Statement(label=l, kind="lemma", lines=(1, 1), claim="", uses=tuple(uses.get(l, ())),
                  calls=(), hypotheses=(), readings=(), grade=g, fails_under=(),
                  rescued_by=None, finding="", evidence=(), checked_by="")
        for l, g in grades.items()))


def test_propagation_on_a_toy_graph():
    grades = {"T": "open", "A": "proved", "B": "refuted", "C": "refuted-under-reading",
              "D": "proved", "E": "holds-on-cases", "F": "definition", "G": "proved"}
    uses = {"T": ["A", "E"], "A": ["B", "F"], "B": ["C"], "E": ["D"], "G": ["F", "D"],
            "C": ["T"]}                                  # a cycle T -> A -> B -> C -> T
    toy = _toy(grades, uses)
    sup = support(toy)
    assert sup["T"].rests_on_refuted == ("B",)
    assert sup["T"].rests_on_reading == ("C",)
    assert set(sup["T"].unproved) == {"B", "C", "E"}    # a statement never rests on itself
    assert sup["A"].rests_on_refuted == ("B",)
    assert sup["E"].rests_on_refuted == () and sup["E"].rests_only_on_proved
    assert sup["G"].rests_only_on_proved and sup["F"].rests_only_on_proved
    assert sup["D"].unproved == ()
    assert sup["B"].rests_on_refuted == ()                   # not on itself, even in a cycle
    assert sup["B"].rests_on_reading == ("C",)
    assert not sup["A"].rests_only_on_proved
    assert cycles(toy) == [["A", "B", "C", "T"]]


# ---------------------------------------------------------------- the real ledger
@pytest.fixture(scope="module")
def ledger():
    return load_ledger(ROOT / LEDGER)


def test_every_label_has_one_grade(ledger):
    assert sorted(s.label for s in ledger.statements) == sorted(LABELS)


def test_docs_audit_is_generated_from_the_ledger(ledger):
    from exactsym.ledger.cli import sweep_texts
    expected = render(ledger, support(ledger), sweep_texts(ledger, ROOT))
    actual = (ROOT / AUDIT).read_text(encoding="utf-8")
    assert actual == expected, "docs/audit.md is stale: run python -m exactsym.ledger"


def test_rests_on_refuted_in_the_real_ledger(ledger):
    sup = support(ledger)
    assert "lem-type4" in sup["lem-3-pair-sym"].rests_on_refuted     # refuted (issue 32)
    assert "lem-3-pair-sym" in sup["theorem-sym-pair-symG"].rests_on_reading
    assert "obs-exh-poly" in sup["lem-3-pair-sym"].rests_on_refuted
    assert "lem-los-gij" in sup["Gprime-equiG"].rests_on_refuted
    assert sup["lemma-sym-ord"].rests_only_on_proved


def test_check_reruns_every_piece_of_evidence(ledger):
    # the stored gathering reading matrices: every one is checked for shape and for the
    # grade it implies; re-run here only those that took at most 3 s when written (the
    # others take up to minutes: `exactsym ledger --check` re-runs them all)
    assert check_evidence(ledger, ROOT, matrix_seconds=3) == []


def test_check_reports_a_wrong_verdict(ledger):
    s = ledger.by_label()["lem-los-gij"]
    wrong = Evidence("case", "cases/family/gcd-9-15-merge.toml", "audit-false")
    bad = Ledger("x", (Statement(**{**s.__dict__, "evidence": (wrong,)}),))
    problems = check_evidence(bad, ROOT)
    assert len(problems) == 1 and "does not find lem-los-gij false" in problems[0].message


def test_ledger_json(capsys):
    assert ledger_main(["--json", "--no-write", "--root", str(ROOT)]) == 0
    data = json.loads(capsys.readouterr().out)
    by = {s["label"]: s for s in data["statements"]}
    assert set(by) == set(LABELS)
    assert set(by["Gprime-equiG"]) == {"label", "kind", "grade", "readings", "uses",
                                       "evidence", "rests_on_refuted"}
    assert by["Gprime-equiG"]["grade"] == "refuted"
    assert "lem-los-gij" in by["Gprime-equiG"]["rests_on_refuted"]


def test_sweep_summary_format(tmp_path, ledger):
    f = tmp_path / "s.json"
    f.write_text(json.dumps({"format": 1, "label": "lem-los-gij", "family": "roots:24:<=8",
                             "configurations": 10, "failures": 0, "smallest_case": None}))
    assert load_sweep(f)["configurations"] == 10
    f.write_text(json.dumps({"format": 1, "label": "lem-los-gij", "family": "x",
                             "configurations": True, "failures": 0, "smallest_case": None}))
    with pytest.raises(ValueError):
        load_sweep(f)


# ---------------------------------------------------------------- proofs/
def test_check_symmetry_odd_exhaustive_small():
    cso = _proofs_module("check_symmetry_odd")
    assert cso.check(12, 11)["polygons"] == sum(
        __import__("math").comb(11, k - 1) for k in range(1, 12, 2))
    # the literal loop's count differs from the mirrors exactly on the D1 pentagon's shape
    assert cso.deg_sym_fixed_loop((0, 1, 3, 9, 11), 12) == len(cso.mirrors((0, 1, 3, 9, 11), 12))


def test_straight_sym_readings():
    ssr = _proofs_module("straight_sym_readings")
    r = ssr.check(12, 12)
    assert r["or_reading_failures"] > 0
    # the isosceles triangle (apex 0, base 3/8 and 5/8 on the 24-gon grid): 'or' says the
    # leg bisectors are mirrors
    tri = tuple(2 * x for x in (0, 9, 15))
    assert ssr.palindrome(ssr.string_at(9, tri, 48))          # leg midpoint 0..9 at 9/2
    assert not ssr.palindrome(ssr.string_at(9 + 24, tri, 48))


def test_witnesses_under_every_reading():
    w = _proofs_module("witnesses").check()
    ref = w["refutations"]
    for label in ("Psym-Gsym", "cor-Pasym-Pord", "Pasym-Pord", "lem-los-gij",
                  "Gprime-equiG", "obs-gcd"):
        assert len(ref[label]) == 8, label
    assert set(w["readings"]) - set(ref["lem-sym-notord"]) == {
        "same-kind, literal, singleton straight"}
    assert ref["Psym-Gsym"]["same-kind, literal, singleton straight"] == ["two_gon_on_mirror"]
    f = w["facts"]
    assert f["merge_within_hypotheses"] == {"n": 28, "sec_centre_is_C": True,
                                            "in_O_S": False, "orderable": True}
    assert f["two_gon_on_mirror"]["in_O_S"] and not f["two_gon_on_mirror"]["orderable"]


def test_readings_are_metamorphic_under_rotation_and_reflection():
    """Turning every robot by the same rational turn, or reflecting (turn -> -turn),
    changes none of the verdicts of proofs/readings.py."""
    from fractions import Fraction as Q
    R = _proofs_module("readings")
    wit = _proofs_module("witnesses")
    for name in wit.WITNESSES:
        pts = wit._points(name)
        for move in (lambda t: t + Q(1, 7), lambda t: -t):
            other = [(r, R.norm(move(t))) for r, t in pts]
            assert R.in_O_S(other) == R.in_O_S(pts)
            assert R.orderable_about_centre(other) == R.orderable_about_centre(pts)
            for reading in R.READINGS:
                assert R.family_symmetric(R.levels(other), reading) == \
                    R.family_symmetric(R.levels(pts), reading)


def test_same_kind_reading_breaks_three_pairs():
    """lem-3-pair-sym / theorem-sym-pair-symG: pairwise symmetric, no common line, under
    exactly the four same-kind readings (issue 32)."""
    r = _proofs_module("three_pairs_same_kind").check()
    assert len(r["fails_under"]) == 4 and all(n.startswith("same-kind") for n in r["fails_under"])
    assert all(n.startswith("mixed") for n in r["holds_under"])


def test_straight_sym_needs_lines_through_centre():
    """The equilateral triangle's chord between the circle points at turns 1/6 and 1/2:
    both strings palindromes, no mirror (the third change lemma-straight-sym needs)."""
    ssr = _proofs_module("straight_sym_readings")
    assert ssr.chord_witness() == ((4, 12, 4), (4, 12, 4))
    assert ssr.check(12, 4)["chord_not_through_C"] == ((4, 12, 4), (4, 12, 4))


def test_literal_pattern_has_gaps():
    """Def. 1 read literally: no pattern of n = 2, 8, 20, 38, 63 robots; the capacities
    agree with exactsym's generator."""
    from exactsym.gathering.pattern import capacity
    pl = _proofs_module("pattern_lone_layer")
    assert pl.no_literal_pattern(70) == [2, 8, 20, 38, 63]
    assert [pl.capacity(L) for L in range(1, 7)] == [capacity(L) for L in range(1, 7)]


def test_chord_strings_make_no_false_vertex_equality():
    assert _proofs_module("chord_strings").check(10, 6)["asymmetric_polygons"] > 0


def test_extract_refs_on_a_snippet():
    er = _proofs_module("extract_refs")
    text = "\n".join([
        "\\begin{lemma}", "\\label{lem-a}", "Claim.", "\\end{lemma}",
        "\\emph{Proof:} By lemma \\ref{lem-b} and Fig. \\ref{skew}.", "\\qed",
        "\\begin{obs}", "\\label{obs-type 4}", "Text.", "\\end{obs}",
        "\\begin{lemma}", "\\label{lem-b}", "B.", "\\end{lemma}", "Text \\ref{lem-a}.",
        "{\\it Correctness of Foo(G):} Follows from theorem \\ref{lem-a}.", "\\qed"])
    got = {s["label"]: s["refs"] for s in er.statements(text)}
    assert got == {"lem-a": ["lem-b"], "obs-type-4": [], "lem-b": [], "Foo": ["lem-a"]}


@pytest.mark.skipif(not os.environ.get("EXACTSYM_PAPER"),
                    reason="set EXACTSYM_PAPER to the paper's LaTeX source")
def test_uses_contain_every_extracted_ref(ledger):
    er = _proofs_module("extract_refs")
    text = Path(os.environ["EXACTSYM_PAPER"]).read_text(encoding="utf-8")
    by = ledger.by_label()
    for s in er.statements(text):
        assert set(s["refs"]) <= set(by[s["label"]].uses), s["label"]


# ---------------------------------------------------------------- refutation certificates
def _refutation(label, case):
    from exactsym.geometry.configuration import load
    from exactsym.certificates.refutation import make_refutation
    return json.loads(json.dumps(make_refutation(load(ROOT / case), label)))


def test_refutation_certificates_verify_and_reject_tampering():
    from exactsym import checker
    from exactsym.certificates.certificate import CertificateError
    obj = _refutation("Pasym-Pord", "cases/discrepancies/family-chiral-c3-ring.toml")
    ok, why = checker.verify_refutation(obj)
    assert ok and "order 3" in why
    assert checker.verify_refutation({**obj, "label": "lem-sym-notord"})[0] is False
    bad = json.loads(json.dumps(obj))
    bad["certificate"]["claim"]["orderable"] = True
    assert checker.verify_refutation(bad)[0] is False
    # one level is part of lem-asym-ord's premise: two rings of the C3 family do not refute it
    with pytest.raises(CertificateError, match="not one polygon"):
        _refutation("lem-asym-ord", "cases/discrepancies/family-c3-two-triangles.toml")
    with pytest.raises(CertificateError, match="in O_S"):
        _refutation("Pasym-Pord", "cases/family/regular-d3-not-orderable.toml")
    with pytest.raises(CertificateError, match="nearest known label: 'Pasym-Pord'"):
        _refutation("Pasym-Pard", "cases/discrepancies/family-chiral-c3-ring.toml")


def test_shipped_refutation_certificates_match_their_cases(ledger):
    from exactsym import checker
    for s in ledger.statements:
        for e in s.evidence:
            if e.kind == "certificate":
                obj = json.loads((ROOT / e.path).read_text())
                assert checker.verify_refutation(obj)[0] and obj["label"] == s.label


def test_checked_by_names_an_existing_function(ledger):
    """A renamed module makes this fail until the ledger's checked_by follows it."""
    import importlib
    for s in ledger.statements:
        if s.checked_by == "none yet":
            continue
        module, _, attr = s.checked_by.rpartition(".")
        assert callable(getattr(importlib.import_module(module), attr)), s.label


def test_witnesses_are_the_case_files():
    """proofs/witnesses.py checks the same points as the case file it names."""
    import tomllib
    from fractions import Fraction as Q
    wit = _proofs_module("witnesses")
    for name, (case, _) in wit.WITNESSES.items():
        with open(ROOT / case, "rb") as fh:
            points = tomllib.load(fh)["points"]
        in_case = {(Q(p["r"]), Q(p["turn"]) % 1) for p in points}
        assert {(Q(r), Q(t) % 1) for r, t in wit._points(name)} == in_case, name
