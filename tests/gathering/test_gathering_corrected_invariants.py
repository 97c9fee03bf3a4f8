"""The corrected variant's invariants of issue 31 (``proofs/gathering-corrected.md``):
no path grazes a robot (two robots come to touch only at an arrival, so C cannot move
mid-way), and no move ends in a symmetric configuration while robots are left to move.
Each test failed before: the grazing configurations violated I6 (C moved), the n = 9
trap and the mirror tie stalled."""

from __future__ import annotations

from fractions import Fraction as F
from pathlib import Path

import pytest
from flint import fmpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactsym.exact.multiquadratic import MQ
from exactsym.gathering import geometry as g
from exactsym.gathering.cases import run_settings, settings_of
from exactsym.gathering.corrected import decide_corrected
from exactsym.gathering.corrected_choice import keeps_a_leader
from exactsym.gathering.invariants import ALL
from exactsym.gathering.paper_bridge import configuration_of, read_case
from exactsym.gathering.pattern import generate
from exactsym.gathering.robot import Readings
from exactsym.gathering.schedulers import run
from exactsym.truth.symmetry import symmetry_group

ROOT = Path(__file__).resolve().parents[2]
SEC_ROBOTS = [(16, 12), (-12, 16), (0, -20)]          # radius 20, the origin inside


def _mq(points):
    return tuple((MQ.coerce(x), MQ.coerce(y)) for x, y in points)


def _min_dist2_segment(a, b, q):
    """The exact minimum squared distance from ``q`` to the segment ``ab``."""
    ab, aq = g.sub(b, a), g.sub(q, a)
    den, t = g.dot(ab, ab), g.dot(aq, ab)
    if den.is_zero() or t.sign() <= 0:
        return g.dist2(a, q)
    if (t - den).sign() >= 0:
        return g.dist2(b, q)
    return g.dot(aq, aq) - t * t / den


def _clearance_ok(pieces, pts, mover, allowed):
    """Independent of the code under test: every robot but the mover farther than 2
    from every point of the path, except robots of ``allowed`` at the final point only
    (arcs: the nearest point of a circle to q is its radial projection, sampled at the
    arc's ends and at every exact point ``at(k/64)`` -- an arc of the variant never
    comes near a robot except where a segment could, a coarse but exact check)."""
    for k, piece in enumerate(pieces):
        for j, q in enumerate(pts):
            if j == mover:
                continue
            if isinstance(piece, g.Segment):
                m = _min_dist2_segment(piece.start, piece.end, q)
                if (m - 4).sign() < 0:
                    return False
                if m == 4:
                    end_touch = k == len(pieces) - 1 and g.dist2(piece.end, q) == 4
                    if not (end_touch and j in allowed):
                        return False
                    # touching at the end only: the squared distance falls to the end
                    if g.dot(g.sub(piece.end, q), g.sub(piece.end, piece.start)).sign() > 0:
                        return False
            else:
                for s in range(65):
                    if (g.dist2(piece.at(MQ.rational(F(s, 64))), q) - 4).sign() <= 0:
                        return False
    return True


@st.composite
def grazing(draw):
    """Robot A on the x axis at distance a from C = (0, 0) (the SEC centre), the nearest
    robot; robot B at distance exactly 2 from A's segment to C (the foot at (t, 0), t near
    a, so that B is farther from C than A); three robots on the SEC of radius 20; all of
    it turned by a Pythagorean rotation and maybe reflected."""
    a = F(draw(st.integers(40, 80)), 10)
    t = a - F(draw(st.integers(1, 4)), 20)
    assume_far = t * t + 4 > a * a
    side = draw(st.sampled_from([1, -1]))
    pts = [(a, F(0)), (t, F(2 * side))] + [(F(x), F(y)) for x, y in SEC_ROBOTS]
    u = F(draw(st.integers(-3, 3)), 4)
    c, s = (1 - u * u) / (1 + u * u), 2 * u / (1 + u * u)
    refl = draw(st.booleans())
    out = [((c * x - s * y), (s * x + c * y)) for x, y in pts]
    if refl:
        out = [(x, -y) for x, y in out]
    return out, assume_far


@settings(max_examples=6, deadline=None)
@given(grazing())
def test_a_path_to_c_that_would_graze_is_not_taken(case):
    """The first Look: the nearest robot's straight segment to C touches B; the variant
    takes a path that keeps B strictly farther than 2, and the run gathers with every
    invariant on (before: the segment, and I6 at the graze)."""
    points, b_farther = case
    if not b_farther:
        return
    pts = _mq(points)
    d = decide_corrected(pts)
    assert d.status == "move" and d.moves[0].robot == 0
    assert _clearance_ok(d.moves[0].path, pts, 0, frozenset())
    assert len(d.moves[0].path) > 1                  # not the grazing segment
    res = run(points, "centralised", 0, Readings(), max_events=600, algorithm="corrected")
    assert res.outcome == "gathered", res.detail


def test_every_planned_path_keeps_clear_along_runs():
    """Along runs of the case files of the variant (and their mirror images), every
    path a Look plans is clear: no robot within 2 except the pattern's robots, or robots
    at distance 2 of C, at the final point."""
    seen = 0
    for name in ("corrected-graze-keeps-centre", "corrected-obstacle-beside-path"):
        points, _n, _e, _s = read_case(ROOT / f"cases/gathering/{name}.toml")
        for pts0 in (points, [(x, -y) for x, y in points]):
            res = run(pts0, "centralised", 0, Readings(), max_events=600,
                      algorithm="corrected")
            assert res.outcome == "gathered", res.detail
            pts = list(_mq(pts0))
            for step in res.log:
                if step.kind == "advance":
                    pts[step.robot] = step.pieces[0].final
                    continue
                if not step.pieces:
                    continue
                d = decide_corrected(tuple(pts))
                C = d.centre
                allowed = set(d.pattern.robots) | {j for j, q in enumerate(pts)
                                                   if g.dist2(q, C) == 4}
                assert _clearance_ok(step.pieces, pts, step.robot, allowed)
                seen += 1
    assert seen >= 16


def test_keeps_a_leader_exact_values():
    """The ground truth's verdict on completed moves: the robot at C, the hexagon and
    two robots point-symmetric about C is symmetric; one of them moved is not."""
    hexagon = list(generate(7))
    a, b = (MQ.rational(20), MQ.rational(0)), (MQ.rational(-20), MQ.rational(0))
    pts = hexagon[:6] + [(MQ.rational(5), MQ.rational(9)), a, b]
    assert keeps_a_leader(pts, 6, hexagon[6]) is False
    assert keeps_a_leader(pts, 8, (MQ.rational(-16), MQ.rational(12))) is True
    assert keeps_a_leader(pts, 6, (MQ.rational(5), MQ.rational(8))) is True


def _arrival_states(points, res):
    """(positions, R not empty) after every advance of the run that ends a piece."""
    pts = list(_mq(points))
    for step in res.log:
        if step.kind == "advance":
            pts[step.robot] = step.pieces[0].final
            yield tuple(pts)


@pytest.mark.parametrize("frame", ["plain", "mirror", "turned"])
def test_the_n9_trap_is_avoided(frame):
    """Two diametrically opposite robots fix the SEC (n = 9): the run gathers (before:
    stalled with the last two point-symmetric about C), in the mirror image and turned
    by a Pythagorean angle too; every configuration after an advance in which robots
    are left to move has a leader by the ground truth."""
    points, _n, expect, _s = read_case(ROOT / "cases/gathering/corrected-n9-symmetric-trap.toml")
    if frame == "mirror":
        points = [(x, -y) for x, y in points]
    elif frame == "turned":
        points = [(fmpq(3, 5) * x - fmpq(4, 5) * y, fmpq(4, 5) * x + fmpq(3, 5) * y)
                  for x, y in points]
    s = settings_of(expect)
    res = run_settings(points, s)
    assert res.outcome == "gathered", res.detail
    assert res.checks["I9"] > 0 and res.checks["I6"] > 0
    asym = 0
    for pts in _arrival_states(points, res):
        d = decide_corrected(pts)
        if d.status == "terminated":
            continue
        assert symmetry_group(configuration_of(list(pts))).orderable, d.detail
        asym += d.status == "move" and d.moves[0].role == "asym"
    assert asym >= 1                         # the step aside was made


def test_the_step_aside_is_planned_again_from_every_point_of_its_way():
    """I3 by construction: at 1/3 and 2/3 of the step aside (and at its start) the
    decision names the same robot, role and target."""
    points, _n, _e, _s = read_case(ROOT / "cases/gathering/corrected-n9-symmetric-trap.toml")
    res = run(points, "centralised", 0, Readings(), max_events=600, algorithm="corrected")
    pts = list(_mq(points))
    for step in res.log:
        if step.kind == "advance":
            pts[step.robot] = step.pieces[0].final
            continue
        d = decide_corrected(tuple(pts))
        if d.status == "move" and d.moves[0].role == "asym":
            break
    else:
        pytest.fail("no step aside in the run")
    m, path = d.moves[0].robot, d.moves[0].path
    for f in (F(1, 3), F(2, 3)):
        mid = list(pts)
        mid[m] = path[0].at(MQ.rational(f))
        again = decide_corrected(tuple(mid))
        assert [(x.robot, x.role) for x in again.moves] == [(m, "asym")]
        assert again.moves[0].path[-1].final == path[-1].final
    # at the end it ties with the farthest robots and is left out
    end = list(pts)
    end[m] = path[-1].final
    after = decide_corrected(tuple(end))
    assert after.status == "move" and after.moves[0].robot != m


@pytest.mark.parametrize("scheduler", ["async", "fsync"])
def test_the_mirror_tie_is_avoided(scheduler):
    """Five robots on one circle, four at the compass points: used to stall with the
    pattern and the last robot mirror-symmetric; gathers now."""
    points, _n, expect, _s = read_case(ROOT / "cases/gathering/corrected-mirror-tie-avoided.toml")
    s = settings_of(expect)
    s.update(scheduler=scheduler, invariants=list(ALL))
    res = run_settings(points, s)
    assert res.outcome == "gathered", res.detail


def test_the_literal_definition_moves_as_lone_accept_with_a_layer_start():
    """lone=reject (Def. 1 read literally): with a robot at C the next arrival puts one
    robot alone in layer 1, no literal pattern; the variant makes the same move as under
    lone=accept (before: not-possible, on a start with a leader), marked ``layer-start``,
    and reports the literal pattern (robot 0 alone)."""
    pts = _mq([(0, 0), (7, 1), (-12, 16), (16, 12), (0, -20)])
    literal = decide_corrected(pts, Readings(lone="reject"))
    accepted = decide_corrected(pts, Readings())
    assert accepted.status == "move" and accepted.moves[0].robot == 1
    assert g.dist2(accepted.moves[0].path[-1].final, pts[0]) == 4
    assert literal.status == "move" and literal.moves[0].robot == 1
    assert literal.moves[0].role == "layer-start" and accepted.moves[0].role == "leader"
    assert literal.moves[0].path == accepted.moves[0].path
    assert set(literal.pattern.robots) == {0}
