"""One mover dragging R's SEC centre (exactsym.gathering.instants with
moving_centre.about_moving_sec, shared with joint steps): while the mover supports the
SEC of R, the rays and ties of R's robots about that moving centre are critical
instants.  Found at its exact instant, missed without the family, a (test) algorithm
that stays exactly there caught by I3 there; and the superset property: between two
consecutive instants no ray or tie about R's true SEC centre changes sign."""

from fractions import Fraction as F

import pytest
from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import geometry as g
from exactsym.gathering import moving_centre
from exactsym.gathering.instants import critical_roots, look_points
from exactsym.gathering.invariants import Checker, Violation
from exactsym.gathering.pattern import recognise
from exactsym.gathering.robot import Decision, Move, Readings
from exactsym.gathering.world import IDENTITY, Frame, World

P = g.point
Q = MQ.rational
ORIGIN = P(0, 0)

#: robots 0, 1 in the pattern (C = (0, 0)); R = {2, 3, 4, 5}.  Robot 5 moves alone out
#: along the x-axis from (25, 0) to (35, 0): with robots 2 (10, 10) and 3 (10, -10) it
#: supports R's SEC, whose centre (h, 0), h = (x^2 - 200) / (2x - 20), moves.  Robot 4
#: stands at (12, 15/2), on the line through (18, 0) and robot 2: h = 18 at
#: x = 18 + 2 sqrt(41), time -7/10 + sqrt(41)/5 (about 0.58).  About the SEC centre of
#: the others of R, (10, 0), robot 5 crosses no line through a robot of R.
PTS = [(0, 0), (2, 0), (10, 10), (10, -10), (12, F(15, 2)), (25, 0)]
PIECE = g.Segment(P(25, 0), P(35, 0))
R_SET = frozenset({2, 3, 4, 5})
EVENT = Q(F(-7, 10)) + sqrt_rational(41) / 5
RAY = ("ray", "robots 2 and 4 on one line through the centre of R's SEC (supports 2, 3, 5)")


def _world(pts=PTS, piece=PIECE, r_set=R_SET):
    w = World(pts, Readings())
    w.robots[5].r_set = frozenset(r_set)
    return w


def _on_ray_2_4(pts):
    c = g.smallest_enclosing_circle([pts[k] for k in sorted(R_SET)])[0]
    return g.cross(g.sub(pts[2], c), g.sub(pts[4], c)).is_zero()


def _stub(stays):
    """A test algorithm (not the paper's): robot 5 goes to (35, 0) unless ``stays``."""
    def decide(snapshot, readings=Readings(), unit=fmpq(1)):
        pts = list(snapshot)
        pat = recognise(pts, ORIGIN)
        if stays(pts):
            return Decision("stay", (), ORIGIN, pat, None, "the test's event")
        return Decision("move", (Move(5, (g.Segment(pts[5], P(35, 0)),), "leader"),),
                        ORIGIN, pat, 5, "to the target")
    return decide


def _tags_at(w, t):
    return [tag for r in critical_roots(PIECE, w, 5, ORIGIN) if r.exact == t
            for tag in r.tags]


def test_the_ray_about_the_moving_centre_is_an_exact_instant():
    pts = [PIECE.at(EVENT) if k == 5 else P(*p) for k, p in enumerate(PTS)]
    assert _on_ray_2_4(pts)
    assert g.smallest_enclosing_circle([pts[k] for k in sorted(R_SET)])[0] == P(18, 0)
    assert RAY in _tags_at(_world(), EVENT)
    points, sided = look_points(PIECE, _world(), 5, ORIGIN)
    assert [lp.exact for lp in points if lp.f == EVENT] == [True] and sided == 0


def test_I3_catches_a_stub_that_stays_exactly_there(monkeypatch):
    w = World(PTS, Readings(), checker=Checker(enabled=frozenset({"I3"})))
    w.decide = _stub(_on_ray_2_4)
    w.look(5, IDENTITY)
    assert w.robots[5].r_set == R_SET and w.robots[5].path == [PIECE]
    with pytest.raises(Violation) as err:
        w.advance(5)
    v = err.value
    assert (v.invariant, v.robots) == ("I3", (5,))
    assert "robots 2 and 4 on one line through the centre of R's SEC" in v.witness
    assert "sqrt(41)" in v.witness
    # without the moving centre (before: rays about (10, 0) only) the event is missed
    monkeypatch.setattr(moving_centre, "about_moving_sec", lambda *a, **k: ([], []))
    assert RAY not in _tags_at(_world(), EVENT)
    w = World(PTS, Readings(), checker=Checker(enabled=frozenset({"I3"})))
    w.decide = _stub(_on_ray_2_4)
    w.look(5, IDENTITY)
    w.advance(5)
    assert w.robots[5].pos == P(35, 0)


@pytest.mark.parametrize("frame", [Frame(F(3, 5), F(4, 5), False, F(7), F(-3)),
                                   Frame(F(-5, 13), F(12, 13), True, F(1, 2), F(9))])
def test_the_instant_survives_an_exact_congruence(frame):
    pts = [frame.to_world(P(*p)) for p in PTS]
    piece = frame.piece_to_world(PIECE)
    w = World(pts, Readings())
    w.robots[5].r_set = R_SET
    roots = critical_roots(piece, w, 5, frame.to_world(ORIGIN))
    assert any(r.exact == EVENT and RAY in r.tags for r in roots)


def test_a_mover_inside_the_others_sec_gets_no_moving_centre(monkeypatch):
    """Robot 4 moving inside R's SEC (held by robots 2, 3, 5 standing still): the centre
    stays put and the moving-centre family is not built."""
    calls = []
    real = moving_centre.about_moving_sec
    monkeypatch.setattr(moving_centre, "about_moving_sec",
                        lambda *a, **k: calls.append(1) or real(*a, **k))
    w = World(PTS, Readings())
    w.robots[4].r_set = R_SET
    critical_roots(g.Segment(P(12, F(15, 2)), P(12, 3)), w, 4, ORIGIN)
    assert not calls
    critical_roots(PIECE, _world(), 5, ORIGIN)
    assert calls


# -- the superset property ---------------------------------------------------------------
def _signs(pts):
    """Signs of every ray and tie of two robots of R about R's SEC centre (None: two
    robots at one point)."""
    at = {k: pts[k] for k in sorted(R_SET)}
    if len(set(at.values())) < len(at):
        return None
    c = g.smallest_enclosing_circle(list(at.values()))[0]
    out = []
    ks = sorted(at)
    for x, a in enumerate(ks):
        for b in ks[x + 1:]:
            out.append(g.cross(g.sub(at[a], c), g.sub(at[b], c)).sign())
            out.append((g.dist2(at[a], c) - g.dist2(at[b], c)).sign())
    return out


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(-12, 12), st.integers(-12, 12)), min_size=4,
                max_size=4, unique=True),
       st.tuples(st.integers(-8, 8), st.integers(-8, 8)),
       st.sampled_from([None, F(1, 2), F(-1, 3), F(2, 5)]))
def test_no_ray_or_tie_about_Rs_sec_centre_changes_inside_a_stretch(r_pts, vel, turn):
    """R = robots 2-5 (robots 0, 1 in the pattern, far away); robot 5 alone moves, along
    a segment or an arc about a random point of R (it may drag R's SEC, or leave and
    re-enter it).  Between two consecutive critical instants the sign of every ray and
    every tie of two robots of R about the true SEC centre of R is the same at both
    ends of the stretch."""
    pts = [(0, 60), (2, 60)] + r_pts
    start = P(*r_pts[3])
    if turn is None:
        piece = g.Segment(start, P(r_pts[3][0] + 3 * vel[0], r_pts[3][1] + 3 * vel[1]))
    else:
        centre = P(*r_pts[0])
        if centre == start:
            return
        cs, sn = (1 - turn * turn) / (1 + turn * turn), 2 * turn / (1 + turn * turn)
        end = g.add(centre, g.rotate(g.sub(start, centre), Q(cs), Q(sn)))
        piece = g.Arc(centre, start, end, 1 if turn > 0 else -1)
    if piece.start == piece.end:
        return
    w = World(pts, Readings())
    w.robots[5].r_set = R_SET

    def signs(t):
        return _signs([piece.at(t) if k == 5 else P(*p) for k, p in enumerate(pts)])

    cuts = [F(0)] + [F(int(x.p), int(x.q)) for r in critical_roots(piece, w, 5, P(0, 60))
                     for x in (r.lo, r.hi)] + [F(1)]
    ends = [(a if a > 0 else b / 4, b if b < 1 else (3 + a) / 4)
            for a, b in zip(cuts[::2], cuts[1::2])]
    for a, b in ends:
        sa, sb = signs(Q(a)), signs(Q(b))
        if sa is not None and sb is not None:
            assert sa == sb, (a, b)
