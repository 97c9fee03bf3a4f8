"""A reading under which the printed FormGPattern has no instruction moves nobody: the run
is a proved stall (the algorithm's failure), never "undecided" (the kernel's limit)."""

from pathlib import Path

from exactsym.gathering.cases import run_settings, settings_of
from exactsym.gathering.paper_bridge import read_case
from exactsym.gathering.robot import Readings

CASE = Path(__file__).resolve().parents[2] / "cases/gathering/obstacle-beyond-destination.toml"


def test_a_reading_with_no_rule_stalls():
    points, _name, expect, _src = read_case(CASE)
    settings = settings_of(expect)
    settings["readings"] = Readings(A3="all", A4="within2").as_dict()
    res = run_settings(points, settings)
    # robots 0 and 1 are within 2 of C, nobody is at C: "C is occupied" under A4=within2,
    # and FormGPattern has no layer to extend
    assert res.outcome == "stalled"
    assert "no layer to extend" in res.detail
    # the mirror image stalls alike
    mirrored = [(-x, y) for x, y in points]
    assert run_settings(mirrored, settings).outcome == "stalled"
