"""A reading under which the printed FormGPattern has no instruction gives the leader no
move (what else is planned is still made): the run ends in a proved stall or cycle (the
algorithm's failure), never "undecided" (the kernel's limit)."""

from pathlib import Path

from exactsym.gathering.cases import run_settings, settings_of
from exactsym.gathering.paper_bridge import read_case
from exactsym.gathering.robot import Readings

CASE = Path(__file__).resolve().parents[2] / "cases/gathering/obstacle-beyond-destination.toml"


def test_a_reading_with_no_rule_stalls():
    points, _name, expect, _src = read_case(CASE)
    settings = settings_of(expect)
    settings["readings"] = Readings(A3="all", A4="within2").as_dict()
    # robot 1 is within 2 of C and nobody is at C: "C is occupied by other robot" under
    # A4=within2, and FormGPattern has no layer to extend: the leader has no instruction
    from exactsym.gathering.robot import decide
    from exactsym.gathering.geometry import point
    d = decide(tuple(point(x, y) for x, y in points), Readings(A3="all", A4="within2"))
    assert "the leader stays: C is occupied (A4)" in d.detail
    # what is planned besides (Make_SymToAsym's epsilon move) is still made: only it moves
    assert {m.role for m in d.moves} <= {"Make_SymToAsym", "leader+epsilon"}
    res = run_settings(points, settings)
    assert res.outcome == "stalled"          # the algorithm's failure, never "undecided"
    mirrored = [(-x, y) for x, y in points]
    assert run_settings(mirrored, settings).outcome == "stalled"


def test_the_mover_does_not_occupy_c_against_itself():
    """L1605: "If C is not occupied by *other* robot".  The leader 3/2 from C and nobody
    else within 2 of C: under every reading of A4 its path ends with the segment to C (it
    used to count itself as the occupant, plan nothing, and at a fresh Look half way fail
    I3)."""
    from fractions import Fraction as F

    from exactsym.gathering.geometry import Segment, point
    from exactsym.gathering.robot import decide
    pts = tuple(point(x, y) for x, y in ((F(3, 2), 0), (-4, 1), (8, 6), (-6, 8), (0, -10)))
    for a4 in ("covers", "within2", "exact"):
        d = decide(pts, Readings(A3="all", A4=a4))
        assert d.leader == 0, a4
        last = d.move_of(0).path[-1]
        assert isinstance(last, Segment) and last.end == point(0, 0), a4
        assert "C is occupied" not in d.detail, a4
