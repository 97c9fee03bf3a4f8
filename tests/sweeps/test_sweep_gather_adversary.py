"""``gather:EVENTS+STATES:FAMILY --what gather-corrected``: the searching adversary per
start (issue 31), its tables, resume, algebraic starts, and the ledger's claim on it."""

from __future__ import annotations

import copy
import gzip
import json
from fractions import Fraction
from pathlib import Path

import pytest

from exactsym.ledger.gather_sweep import (GatherSweepError, grade_problems,
                                          load_gather_sweep)
from exactsym.ledger.model import LedgerError, parse_ledger
from exactsym.sweeps import analysis_bridge as bridge
from exactsym.sweeps.engine import SweepOptions, run_sweep
from exactsym.sweeps.families import SURD_RADII, family_items, family_size, parse_family
from exactsym.sweeps.gather_table import events_by_n, failures, median_events, merge, tally

ROOT = Path(__file__).resolve().parents[2]


def _points(pairs):
    return tuple(("xy", x, y) for x, y in pairs)


# ---------------------------------------------------------------- families
def test_the_adversary_budget_is_read_from_the_family():
    fam = parse_family("gather:3000+300:random:5..12:s:40")
    assert (fam.budget, fam.states, fam.inner.kind, family_size(fam)) == (3000, 300, "random", 40)
    assert parse_family("gather:400:random:5:7:2").states == 0
    with pytest.raises(ValueError, match="STATES"):
        parse_family("gather:3000+x:random:5:7:2")


def test_an_algebraic_family_draws_surd_radii_on_rays_of_its_turns():
    items = list(family_items(parse_family("algebraic:5..7:12:t:9")))
    assert [i.n for i in items] == [5, 6, 7] * 3
    for item in items:
        assert item.points[0][2] == "0"                  # turned: first robot at turn 0
        for kind, r, turn in item.points:
            assert kind == "polar" and r in SURD_RADII
            assert (Fraction(turn) * 12).denominator == 1 and 0 <= Fraction(turn) < 1
        assert len(set(item.points)) == item.n
    # the same seed, the same draws; another seed, others
    assert items == list(family_items(parse_family("algebraic:5..7:12:t:9")))
    assert items != list(family_items(parse_family("algebraic:5..7:12:u:9")))


def test_an_algebraic_start_is_read_exactly_and_scaled_as_a_case_writes_it():
    """The simulator's start from square-root radii at turns j/12: irrational exact numbers,
    separated by the least integer scale; the scaled text, read back by ``gather``'s own
    reader, gives the same numbers (exact differences zero)."""
    from exactsym.gathering.paper_bridge import read_case
    from exactsym.sweeps.casefile import case_text
    item = next(i for i in family_items(parse_family("algebraic:6:12:t:20"))
                if any("sqrt" in p[1] for p in i.points))
    config = bridge.configuration(item.points)
    start, scale = bridge._separated(bridge._start(item.points, config))
    assert not all(c.is_rational() for p in start for c in p)
    # every two robots more than 2 apart, and not so at scale - 1
    d2 = [(a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 for i, a in enumerate(start)
          for b in start[:i]]
    assert all((d - 4).sign() > 0 for d in d2)
    if scale > 1:
        k = Fraction(scale - 1, scale) ** 2
        assert any((d * k - 4).sign() <= 0 for d in d2)
    tmp = ROOT / "tests" / "sweeps" / "_scaled_start.toml"
    try:
        tmp.write_text(case_text(bridge.scaled_points(item.points, scale)), encoding="utf-8")
        read, *_ = read_case(tmp)
    finally:
        tmp.unlink()
    assert all((a - b).is_zero() for p, q in zip(start, read) for a, b in zip(p, q))


# ---------------------------------------------------------------- one start
def test_a_symmetric_start_is_no_leader_and_no_failure():
    """A square and two robots on a mirror line (D2, no leader): not possible, counted
    as no leader; the record says the search ran within its budget."""
    rec = bridge.analyse("gather-corrected", _points(
        [("20", "0"), ("0", "20"), ("-20", "0"), ("0", "-20"), ("5", "0"), ("-5", "0")]),
        (3000, 20))
    g = rec["gather"]
    assert (g["class"], g["leader"], rec["failed"]) == ("no-leader", False, [])
    assert rec["truth"] == {"group": "D2", "orderable": False}
    assert g["search"]["states"] <= 20 and g["search"]["stopped"] in ("budget", "exhausted")


@pytest.mark.parametrize("mirror", [False, True])
def test_each_class_fails_exactly_when_it_counts_against_the_claim(mirror):
    """The grazing start of issue 31 and its mirror image: whatever the algorithm does,
    the class, the label and the truth's leader agree (a start with a leader that is not
    gathered is a failure), and the mirror image gets the same class (no chirality)."""
    pts = [("5", "0"), ("24/5", "-2"), ("16", "-12"), ("-12", "-16"), ("0", "20")]
    if mirror:
        pts = [(x, str(-Fraction(y))) for x, y in pts]
    rec = bridge.analyse("gather-corrected", _points(pts), (3000, 30))
    g = rec["gather"]
    assert g["leader"] is True and rec["truth"]["group"] == "C1"
    expect = {"gathered": [], "violated": [g["label"]], "stalled": ["gather-stalled"],
              "undecided": ["gather-undecided"],
              "not-possible-with-leader": ["gather-not-possible-with-leader"],
              "other": ["gathering-within-budget"]}[g["class"]]
    assert rec["failed"] == expect
    other = bridge.analyse("gather-corrected", _points(
        [(x, str(-Fraction(y))) for x, y in pts]), (3000, 30))
    assert other["gather"]["class"] == g["class"]


# ---------------------------------------------------------------- tables
def _write(path: Path, family: str, records: list) -> None:
    head = {"sweep": {"enumeration": 1, "family": family, "format": 1,
                      "what": "gather-corrected"}}
    with gzip.open(path, "wt", encoding="utf-8") as fh:
        for r in [head] + records:
            fh.write(json.dumps(r) + "\n")


def _rec(index: int, n: int, kind: str, events: int = 0, label=None, search="budget"):
    return {"index": index, "key": f"k{index}", "n": n, "denominator": 1, "size": 0,
            "status": "ok", "failed": [], "applicable": None,
            "gather": {"class": kind, "events": events, "label": label,
                       "search": {"stopped": search}}}


def test_the_tally_counts_each_configuration_once_with_exact_events(tmp_path):
    path = tmp_path / "t.jsonl.gz"
    _write(path, "gather:1+1:random:5..6:x:7", [
        _rec(0, 5, "gathered", 80), _rec(1, 5, "gathered", 120), _rec(2, 6, "gathered", 200),
        _rec(3, 6, "no-leader", 9), _rec(4, 5, "stalled", 31, search="error"),
        _rec(5, 6, "violated", 4, label="gather-no-overlap"),
        _rec(1, 5, "gathered", 999),                       # index 1 again: not counted
        {"index": 6, "key": "k6", "n": 5, "denominator": 1, "size": 0, "status": "error",
         "error": "boom", "failed": [], "applicable": None}])
    t = tally(path)
    assert {k: t[k] for k in ("configurations", "gathered", "no-leader", "stalled",
                              "violated", "errors", "search_errors")} == \
        {"configurations": 6, "gathered": 3, "no-leader": 1, "stalled": 1, "violated": 1,
         "errors": 1, "search_errors": 1}
    assert t["labels"] == {"gather-no-overlap": 1}
    assert t["events"] == {"5": [80, 120], "6": [200]}
    assert median_events(t) == 120 and failures(t) == 3
    assert events_by_n(t) == [{"n": 5, "gathered": 2, "median": 100, "max": 120},
                              {"n": 6, "gathered": 1, "median": 200, "max": 200}]
    both = merge([t, t])
    assert both["configurations"] == 12 and both["events"]["5"] == [80, 80, 120, 120]


def test_a_resumed_sweep_equals_an_uninterrupted_one(tmp_path):
    """Stopped after one start and resumed: the same records as one run (the adversary's
    search has no time bound: a record is a function of the start and the budget)."""
    family = parse_family("gather:3000+10:random:5:r:2")
    whole, part = tmp_path / "whole.jsonl.gz", tmp_path / "part.jsonl.gz"
    run_sweep(family, "gather-corrected", whole, options=SweepOptions(serial=True))
    first = run_sweep(family, "gather-corrected", part,
                      options=SweepOptions(serial=True, stop_after=1, batch_size=1))
    assert first.new == 1 and not first.complete
    again = run_sweep(family, "gather-corrected", part, resume=True,
                      options=SweepOptions(serial=True))
    assert (again.new, again.skipped, again.complete) == (1, 1, True)

    def records(p):
        with gzip.open(p, "rt", encoding="utf-8") as fh:
            return sorted((json.loads(x) for x in fh if '"index"' in x),
                          key=lambda r: r["index"])
    assert records(part) == records(whole)
    assert all(r["status"] == "ok" and r["gather"]["class"] for r in records(whole))


# ---------------------------------------------------------------- the ledger's claim
def _summary(**changes) -> dict:
    t = {"configurations": 10, "gathered": 8, "no-leader": 2, "not-possible-with-leader": 0,
         "violated": 0, "stalled": 0, "undecided": 0, "other": 0, "errors": 0,
         "search_errors": 0, "labels": {}, "events": {}}
    data = {"format": 1, "planned": 10, "ran": 10,
            "chunks": [{"chunk": "c", "ran": 10, "tally": t}],
            "total": {"tally": copy.deepcopy(t), "failures": 0}}
    for key, value in changes.items():
        data["total"]["tally"][key] = value
    return data


def _fix(data: dict) -> dict:
    t = data["total"]["tally"]
    data["total"]["failures"] = sum(t[c] for c in ("violated", "stalled", "undecided",
                                                   "not-possible-with-leader", "other")) \
        + t["errors"]
    data["chunks"][0]["tally"] = copy.deepcopy(t)
    return data


@pytest.mark.parametrize("changes, ran, grade, ok", [
    ({}, 10, "holds-on-cases", True),
    ({}, 10, "open", True),
    ({}, 10, "refuted", False),
    ({}, 10, "proved", False),
    ({}, 12, "holds-on-cases", False),            # part of the plan: open only
    ({}, 12, "open", True),
    ({"gathered": 7, "stalled": 1}, 10, "refuted", True),
    ({"gathered": 7, "stalled": 1}, 10, "holds-on-cases", False),
    ({"gathered": 7, "undecided": 1}, 10, "refuted", False),   # refutes nothing
    ({"gathered": 7, "undecided": 1}, 10, "open", True),
    ({"gathered": 7, "not-possible-with-leader": 1}, 10, "refuted", True),
])
def test_the_claims_grade_follows_from_the_sweep(tmp_path, changes, ran, grade, ok):
    data = _fix(_summary(**changes))
    data["planned"] = ran                      # `ran` above: the plan's size
    path = tmp_path / "s.json"
    path.write_text(json.dumps(data))
    assert (grade_problems(grade, load_gather_sweep(path)) == []) is ok


@pytest.mark.parametrize("break_it, why", [
    (lambda d: d["total"]["tally"].update(gathered=9), "add up"),
    (lambda d: d["total"].update(failures=3), "failures"),
    (lambda d: d.update(ran=11, planned=11), "what ran"),
    (lambda d: d.update(planned=5), "planned"),
])
def test_a_malformed_gathering_summary_is_refused(tmp_path, break_it, why):
    data = _fix(_summary())
    break_it(data)
    path = tmp_path / "s.json"
    path.write_text(json.dumps(data))
    with pytest.raises(GatherSweepError, match=why):
        load_gather_sweep(path)


def test_a_claim_is_validated():
    text = (ROOT / "proofs" / "statements.toml").read_text(encoding="utf-8")
    bad = text + '''
[[claim]]
id = "GatheringPattern"
about = ["GatheringPattern"]
claim = "x"
grade = "open"
finding = "y"
evidence = [{gather_sweep = "proofs/sweeps/gather_corrected.json"}]
checked_by = "z"
'''
    with pytest.raises(LedgerError, match="not a label of the paper"):
        parse_ledger(bad)
    with pytest.raises(LedgerError, match="grade must be one of"):
        parse_ledger(bad.replace('id = "GatheringPattern"', 'id = "new-claim"')
                     .replace('grade = "open"', 'grade = "definition"'))
