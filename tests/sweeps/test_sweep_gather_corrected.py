"""``exactsym sweep gather:... --what gather-corrected``: the corrected variant per start;
a not-possible run is no failure exactly when the ground truth finds the start
symmetric (``docs/gathering-corrected.md``, "What it cannot gather")."""

from __future__ import annotations

import json

from exactsym.sweeps import analysis_bridge as bridge
from exactsym.sweeps.engine import SweepOptions, run_sweep
from exactsym.sweeps.families import parse_family


def _points(pairs):
    return tuple(("xy", x, y) for x, y in pairs)


def test_a_symmetric_start_is_not_possible_and_no_failure():
    """A square of radius 20 and two robots on a mirror line (group D2): the variant
    answers not-possible, which the sweep records with the group and does not count."""
    rec = bridge.analyse("gather-corrected", _points(
        [("20", "0"), ("0", "20"), ("-20", "0"), ("0", "-20"), ("5", "0"), ("-5", "0")]))
    assert rec["gather"]["outcome"] == "not-possible" and rec["gather"]["group"] == "D2"
    assert rec["failed"] == []
    # the paper's algorithm on the same start is judged as before (not gathered: failed)
    paper = bridge.analyse("gather", _points(
        [("20", "0"), ("0", "20"), ("-20", "0"), ("0", "-20"), ("5", "0"), ("-5", "0")]))
    assert "group" not in paper["gather"]


def test_an_asymmetric_start_gathers():
    """The grazing start of issue 31 (cases/gathering/corrected-graze-keeps-centre.toml),
    mirrored: gathered under the sweep's ASYNC run, no failure."""
    rec = bridge.analyse("gather-corrected", _points(
        [("5", "0"), ("24/5", "-2"), ("16", "-12"), ("-12", "-16"), ("0", "20")]))
    assert rec["gather"] == {"outcome": "gathered", "gathered": True,
                             "steps": rec["gather"]["steps"], "group": "C1"}
    assert rec["failed"] == []


def test_the_sweep_runs_the_variant(tmp_path):
    out = tmp_path / "gc.jsonl"
    run = run_sweep(parse_family("gather:400:random:5:7:2"), "gather-corrected", out,
                    options=SweepOptions(serial=True))
    assert run.complete
    records = [r for r in map(json.loads, out.read_text().splitlines()) if "status" in r]
    assert len(records) == 2 and all(r["status"] == "ok" for r in records)
    for r in records:
        ok = r["gather"]["outcome"] == "gathered" or (
            r["gather"]["outcome"] == "not-possible" and r["gather"]["group"] != "C1")
        assert (r["failed"] == []) == ok
