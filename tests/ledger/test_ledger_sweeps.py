"""Sweep summaries as ledger evidence (exactsym.ledger.sweeps): validation, what a sweep
can say about each grade, the smallest counterexample re-run by --check, import."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from exactsym.ledger import load_ledger
from exactsym.ledger.analysis_bridge import CaseAnalysis
from exactsym.ledger.cli import LEDGER, main as ledger_main
from exactsym.ledger.evidence import check_evidence
from exactsym.ledger.model import Evidence, Ledger, Statement
from exactsym.ledger.sweeps import (SweepError, consistency, import_sweep, load_sweep,
                                    sweep_item)

ROOT = Path(__file__).resolve().parents[2]
CASE = "cases/discrepancies/family-chiral-c3-ring.toml"


@pytest.fixture(scope="module")
def ledger():
    return load_ledger(ROOT / LEDGER)


def _item(label, failures, applicable=10, case=None, robots=6, total=10):
    verdict = "fails" if failures else ("vacuous" if applicable == 0 else "holds")
    return {"statement": label, "verdict": verdict, "configurations": total,
            "applicable": applicable, "failures": failures, "outside": 0,
            "smallest": {"robots": robots, "case": case, "key": "k"} if failures else None,
            "text": f"{verdict} on something"}


def _summary(tmp_path, *items, name="s.json", total=10):
    data = {"format": 1, "source": "exactsym sweep", "family": "roots:12:<=6",
            "what": "audit", "results": None, "configurations": total, "errors": 0,
            "evidence": list(items)}
    f = tmp_path / name
    f.write_text(json.dumps(data))
    return f


def _with(statement: Statement, *evidence, grade=None) -> Statement:
    return Statement(**{**statement.__dict__, "evidence": tuple(evidence),
                        "grade": grade or statement.grade})


def test_load_validates_counts_and_verdicts(tmp_path):
    ok = load_sweep(_summary(tmp_path, _item("Pasym-Pord", 2, case=CASE)))
    assert sweep_item(ok, "Pasym-Pord")["failures"] == 2
    bad = _item("Pasym-Pord", 0)
    bad["verdict"] = "fails"                              # the counts say holds
    with pytest.raises(SweepError, match="counts say 'holds'"):
        load_sweep(_summary(tmp_path, bad))
    with pytest.raises(SweepError, match="more failures"):
        load_sweep(_summary(tmp_path, _item("Pasym-Pord", 5, applicable=3, case=CASE)))
    with pytest.raises(SweepError, match="count"):
        load_sweep(_summary(tmp_path, _item("Pasym-Pord", True, case=CASE)))
    old = tmp_path / "old.json"                           # the one-label format
    old.write_text(json.dumps({"format": 1, "label": "lem-los-gij", "family": "f",
                               "configurations": 10, "failures": 0, "smallest_case": None}))
    assert sweep_item(load_sweep(old), "lem-los-gij")["verdict"] == "holds"


def test_what_a_sweep_can_say_about_each_grade(tmp_path, ledger):
    by = ledger.by_label()
    s = by["lemma-sym-ord"]                               # proved
    holds = load_sweep(_summary(tmp_path, _item("lemma-sym-ord", 0)))
    fails = load_sweep(_summary(tmp_path, _item("lemma-sym-ord", 1, case=CASE)))
    vacuous = load_sweep(_summary(tmp_path, _item("lemma-sym-ord", 0, applicable=0)))
    assert consistency(s, "x", holds, ROOT) == []
    assert "must change" in consistency(s, "x", fails, ROOT)[0]
    assert "does not test" in consistency(s, "x", vacuous, ROOT)[0]
    assert "does not report" in consistency(by["Psym-Gsym"], "x", holds, ROOT)[0]
    # a holding sweep beside 'refuted': only with another witness of the refutation
    p = by["Pasym-Pord"]
    holds_p = load_sweep(_summary(tmp_path, _item("Pasym-Pord", 0)))
    assert consistency(p, "x", holds_p, ROOT) == []        # it has a certificate
    alone = _with(p, Evidence("sweep", "x"))
    assert "another witness" in consistency(alone, "x", holds_p, ROOT)[0]
    # a failing sweep backs 'refuted' through a case file of the tree only
    fails_p = load_sweep(_summary(tmp_path, _item("Pasym-Pord", 1, case=CASE)))
    assert consistency(alone, "x", fails_p, ROOT) == []
    nowhere = load_sweep(_summary(tmp_path, _item("Pasym-Pord", 1, case="/abs/c.toml")))
    assert "not a case file of the tree" in consistency(alone, "x", nowhere, ROOT)[0]


def test_check_reruns_the_smallest_counterexample(tmp_path, ledger):
    p = ledger.by_label()["Pasym-Pord"]
    (tmp_path / "proofs").mkdir()
    _summary(tmp_path / "proofs", _item("Pasym-Pord", 3, case=CASE, robots=6))
    ev = Evidence("sweep", "proofs/s.json")
    (tmp_path / "cases" / "discrepancies").mkdir(parents=True)
    (tmp_path / CASE).write_text((ROOT / CASE).read_text())
    one = Ledger("x", (_with(p, ev),))

    def analysed(false, n):
        return lambda path: CaseAnalysis(str(path), None, (), frozenset(false), n)

    assert check_evidence(one, tmp_path, analysed({"Pasym-Pord"}, 6)) == []
    [m] = check_evidence(one, tmp_path, analysed({"Pasym-Pord"}, 7))
    assert "7 robots, the sweep says 6" in m.message
    [m] = check_evidence(one, tmp_path, analysed(set(), 6))
    assert "does not find Pasym-Pord false" in m.message
    proved = Ledger("x", (_with(p, ev, grade="holds-on-cases"),))
    [m] = check_evidence(proved, tmp_path, analysed({"Pasym-Pord"}, 6))
    assert "must change" in m.message


def test_import_copies_the_cited_cases_and_drops_machine_paths(tmp_path):
    run = tmp_path / "run"
    (run / "r-cases").mkdir(parents=True)
    (run / "r-cases" / "sweep-Pasym-Pord.toml").write_text("format = 1\n")
    item = _item("Pasym-Pord", 1, case=str(run / "r-cases" / "sweep-Pasym-Pord.toml"))
    item["text"] = f"fails on 1 of 10; smallest counterexample: 6 robots ({item['smallest']['case']})"
    other = _item("Psym-Gsym", 1, case=str(run / "r-cases" / "missing.toml"))
    other["text"] = f"fails ({other['smallest']['case']})"
    src = _summary(run, item, other, name="r.evidence.json")
    root = tmp_path / "tree"
    out, written = import_sweep(src, root, "r12", labels=("Pasym-Pord",))
    data = load_sweep(out)
    assert out == root / "proofs" / "sweeps" / "r12.json" and data["results"] is None
    case = sweep_item(data, "Pasym-Pord")["smallest"]["case"]
    assert case == "cases/sweeps/r12/sweep-Pasym-Pord.toml" and (root / case).is_file()
    assert written == [root / case]
    assert sweep_item(data, "Psym-Gsym")["smallest"]["case"] is None
    assert str(tmp_path) not in out.read_text()


def test_command_says_what_each_sweep_finds(tmp_path, capsys):
    f = _summary(tmp_path, _item("lemma-sym-ord", 1, case=CASE), _item("Pasym-Pord", 0))
    assert ledger_main(["--sweep", str(f), "--root", str(ROOT)]) == 1
    out = capsys.readouterr()
    assert "BAD lemma-sym-ord (proved)" in out.out and "ok  Pasym-Pord (refuted)" in out.out
    assert "lemma-sym-ord" in out.err


def test_every_cited_sweep_is_consistent_with_its_grade(ledger):
    cited = [(s, e) for s in ledger.statements for e in s.evidence if e.kind == "sweep"]
    assert cited, "the ledger cites no sweep"
    for s, e in cited:
        data = load_sweep(ROOT / e.path)
        assert consistency(s, e.path, data, ROOT) == [], (s.label, e.path)
        assert data["results"] is None and "/tmp" not in (ROOT / e.path).read_text()
