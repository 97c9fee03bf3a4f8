"""gathering_pattern (Def. 1) and the exact geometry of the gathering simulator."""

from fractions import Fraction as F
from math import acos, floor, pi

import pytest
from hypothesis import given, settings, strategies as st

from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import geometry as g
from exactsym.gathering.pattern import (capacity, definition_defects, generate,
                                        layer_rotation, recognise, rotation_power_coefficients)

small = st.fractions(min_value=-20, max_value=20, max_denominator=7)


def pythagorean(t: F):
    return (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)


def test_capacities():
    assert [capacity(L) for L in range(1, 6)] == [6, 12, 18, 25, 31]
    assert capacity(0) == 1


@pytest.mark.parametrize("L", range(2, 40))
def test_capacity_against_a_float_oracle(L):
    theta = acos(1 - 1 / (2 * L * L))
    k = floor(2 * pi / theta)
    assert abs(2 * pi / theta - round(2 * pi / theta)) > 1e-9   # the oracle is not near a tie (L = 1: exactly 6, above)
    assert capacity(L) == k


def test_rotation_recurrence_matches_powers():
    for L in (1, 2, 5):
        c, s = layer_rotation(L)
        pc, ps = MQ.rational(1), MQ()
        for k in range(1, 8):
            pc, ps = pc * c - ps * s, pc * s + ps * c
            a, b = rotation_power_coefficients(L, k)
            assert pc == MQ.rational(a) and ps == sqrt_rational(4 * L * L - 1) * b


@settings(max_examples=40, deadline=None)
@given(st.integers(1, 40), small, small, st.integers(-9, 9), st.booleans())
def test_generated_pattern_is_recognised_and_valid(n, cx, cy, t, mirror):
    pts = generate(n, (cx, cy), first=(cx + 1 + abs(t), cy + t))
    if mirror:          # a reflection maps a pattern to a pattern
        pts = [(p[0], 2 * MQ.rational(cy) - p[1]) for p in pts]
    centre = pts[0]
    pat = recognise(pts, centre)
    assert pat.robots == frozenset(range(n))
    assert definition_defects(pts, pat) == []
    # layer sizes: full inner layers, the rest in the last
    sizes = [len(layer) for layer in pat.layers]
    assert all(s == capacity(L) for L, s in enumerate(sizes[:-1], start=1))
    assert sum(sizes) + 1 == n


@settings(max_examples=15, deadline=None)
@given(st.integers(2, 45))
def test_pattern_distances(n):
    pts = generate(n)
    pat = recognise(pts, pts[0])
    for i in range(n):
        for j in range(i + 1, n):
            assert (g.dist2(pts[i], pts[j]) - 4).sign() >= 0
    for layer in pat.layers:          # consecutive robots of a chain touch
        for a, b in zip(layer, layer[1:]):
            assert g.dist2(pts[a], pts[b]) == 4
    for r in (pat.layers[0] if pat.layers else ()):   # layer 1 touches the centre robot
        assert g.dist2(pts[r], pts[0]) == 4


def test_recogniser_defect_switches():
    pts = generate(8)           # 1 + 6 + a lone robot in layer 2
    pat = recognise(pts, pts[0])
    assert len(pat.robots) == 8 and len(pat.layers[1]) == 1
    strict = recognise(pts, pts[0], lone="reject")
    assert len(strict.robots) == 7 and strict.defects
    assert definition_defects(pts, pat, lone="reject")
    # two chains of equal length in the last layer: neither is taken
    c = (MQ(), MQ())
    two = [c, (MQ.rational(2), MQ()), (MQ.rational(-2), MQ())]
    pat2 = recognise(two, c)
    assert pat2.robots == frozenset({0}) and "tie" in pat2.defects[0]
    # no robot at the centre: empty pattern
    assert recognise(pts[1:], pts[0]).robots == frozenset()


def test_recognise_in_a_scaled_frame():
    pts = [(p[0] * 3, p[1] * 3) for p in generate(12)]
    assert recognise(pts, pts[0], unit=3).robots == frozenset(range(12))
    assert recognise(pts, pts[0]).robots == frozenset({0})


# -- geometry -------------------------------------------------------------------------
points = st.tuples(small, small)


def _segment_oracle(a, b, q, d2):
    """min over t in [0,1] of |a + t(b-a) - q|^2 in Fractions."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    ex, ey = a[0] - q[0], a[1] - q[1]
    A, B = dx * dx + dy * dy, 2 * (dx * ex + dy * ey)
    cands = [F(0), F(1)] + ([-B / (2 * A)] if A else [])
    best = min((ex + t * dx) ** 2 + (ey + t * dy) ** 2 for t in cands if 0 <= t <= 1)
    return best < d2


@settings(max_examples=200, deadline=None)
@given(points, points, points, st.sampled_from([F(4), F(1), F(9, 4)]))
def test_segment_predicate_against_oracle(a, b, q, d2):
    P = lambda p: g.point(*p)      # noqa: E731
    assert g.segment_min_dist2_less(P(a), P(b), P(q), MQ.rational(d2)) == \
        _segment_oracle(a, b, q, d2)


def test_segment_touching_is_not_a_collision():
    P = g.point
    assert not g.segment_min_dist2_less(P(0, 0), P(10, 0), P(5, 2), MQ.rational(4))
    assert g.segment_min_dist2_less(P(0, 0), P(10, 0), P(5, F(199, 100)), MQ.rational(4))
    # an irrational end point: the radial arrival at distance exactly 2
    c, p = P(0, 0), P(7, 3)
    q = g.radial_point(c, p, 2)
    assert g.dist2(q, c) == 4
    assert not g.piece_hits(g.Segment(p, q), c)


@settings(max_examples=60, deadline=None)
@given(st.fractions(min_value=-3, max_value=3, max_denominator=5),
       st.fractions(min_value=F(1, 2), max_value=6, max_denominator=4), st.booleans())
def test_arc_predicate(t, rho, inside):
    """An arc of radius 2*rho about 0 from the +x axis, a quarter turn at most; a point on
    the arc's middle ray at distance 2*rho +- 3/2 (hit), or on the opposite ray (hit only
    if the circle is small)."""
    c = g.point(0, 0)
    start = g.point(2 * rho, 0)
    cs, sn = pythagorean(F(1, 3))       # about 37 degrees
    end = g.point(2 * rho * cs, 2 * rho * sn)
    for sense, arc in ((1, g.Arc(c, start, end, 1)), (-1, g.Arc(c, end, start, -1))):
        mc, ms = pythagorean(F(1, 7))    # inside the arc
        r = 2 * rho + (F(-3, 2) if inside and rho > 1 else F(3, 2))
        q = g.point(r * mc, r * ms)
        assert g.arc_min_dist2_less(arc, q, MQ.rational(4))
        far = g.point(-(2 * rho + 1) * mc, -(2 * rho + 1) * ms)
        assert not g.arc_min_dist2_less(arc, far, MQ.rational(4))


def test_arc_path_splits_and_at():
    c = g.point(0, 0)
    pieces = g.arc_path(c, g.point(2, 0), g.point(-2, 0), 1)     # half a turn
    assert len(pieces) == 2 and pieces[-1].end == g.point(-2, 0)
    mid = pieces[0].at(MQ.rational(F(1, 2)))
    assert g.dist2(mid, c) == 4 and mid[0].sign() > 0 and mid[1].sign() > 0
    cw = g.arc_path(c, g.point(2, 0), g.point(0, 2), -1)         # three quarters clockwise
    assert len(cw) == 3


def test_linear_motions():
    P = g.point
    # head-on along the x axis: they meet
    assert g.linear_motions_min_dist2_less(P(0, 0), P(10, 0), P(10, 0), P(0, 0), 4)
    # parallel, 3 apart: never closer than 3
    assert not g.linear_motions_min_dist2_less(P(0, 0), P(10, 0), P(0, 3), P(10, 3), 4)
    # crossing paths at different times: the quadratic's vertex decides
    assert not g.linear_motions_min_dist2_less(P(-10, 0), P(0, 0), P(20, -10), P(20, 0), 4)


@settings(max_examples=40, deadline=None)
@given(st.lists(points, min_size=2, max_size=9, unique=True))
def test_sec_matches_the_kernel(pts):
    from exactsym.geometry.configuration import Configuration
    from exactsym.geometry.sec import smallest_enclosing_circle
    mq_pts = [g.point(*p) for p in pts]
    centre, r2 = g.smallest_enclosing_circle(mq_pts)
    circle = smallest_enclosing_circle(Configuration.from_points(pts).points)
    assert centre == (MQ.rational(circle.centre[0]), MQ.rational(circle.centre[1]))
    assert r2 == MQ.rational(circle.radius_squared)


def test_sec_claim_witness_more_than_three_on_the_circle():
    """Spec section 6: five robots on the circle of radius 20 at about 0, 10, 20, 30 and 180
    degrees (rational points); an epsilon rotation of the 180-degree robot towards the
    others changes the SEC although |G_t| = 5 > 3 (MakeAsym's correctness sentence)."""
    def P(t, r=20):
        cs, sn = pythagorean(F(t))
        return g.point(r * cs, r * sn)
    pts = [P(0), P(F(1, 11)), P(F(1, 6)), P(F(4, 15)), g.point(-20, 0)]
    c0, r0 = g.smallest_enclosing_circle(pts)
    assert c0 == g.point(0, 0) and r0 == 400
    cs, sn = pythagorean(F(-1, 100))                 # clockwise: towards 170 degrees
    moved = pts[:4] + [g.rotate(pts[4], MQ.rational(cs), MQ.rational(sn))]
    c1, r1 = g.smallest_enclosing_circle(moved)
    assert c1 != c0 and (r1 - r0).sign() < 0


def test_literal_definition_fails_exactly_with_a_lone_last_robot():
    """Def. 1's 'touches at least 1 robot of its layer' fails for complete patterns whose
    last layer holds one robot: n = 2, 8, 20, 38, 63, ... (1 + full layers + 1)."""
    lone_ns, total = [], 1
    for L in range(1, 6):
        lone_ns.append(total + 1)
        total += capacity(L)
    assert lone_ns[:4] == [2, 8, 20, 38]
    for n in range(2, 70):
        pts = generate(n)
        pat = recognise(pts, pts[0])
        assert bool(definition_defects(pts, pat, lone="reject")) == (n in lone_ns)
