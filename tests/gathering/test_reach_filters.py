"""The reach filters of :mod:`exactsym.gathering.motion` and the segment filter of
:mod:`exactsym.gathering.geometry`: balls with a proof, the exact numbers when a ball
cannot tell (issue 30, point 6)."""

from fractions import Fraction

from hypothesis import given, settings, strategies as st

from exactsym.exact.multiquadratic import MQ
from exactsym.gathering import geometry as g
from exactsym.gathering import motion
from exactsym.gathering.motion import may_be_at, may_come_within, reach_decided


def q(x):
    return MQ.coerce(Fraction(x))


def pt(x, y):
    return (q(x), q(y))


def test_cancellation_the_fixed_margin_got_wrong():
    # y0 = 10^12 sqrt 2 - 1414213562373 ~ 0.0950488; its double is 0.0952148, off by
    # 1.7e-4: the old float reach (1e-6 margin) started the range at 0.09521 and left
    # out a tie at 0.0951, which the mover does reach
    y0 = MQ.rational(10 ** 12) * MQ.sqrt(2) - MQ.rational(1414213562373)
    piece = g.Segment((MQ(), y0), pt(0, 10))
    r2 = q(Fraction(951, 10000)) ** 2
    assert float(y0) > 0.0952 and (y0 - q(Fraction(951, 10000))).sign() < 0
    assert reach_decided(piece, pt(0, 0), r2, within=False) == (True, "ball")
    # just below the true start of the range: not reached
    r2_below = q(Fraction(950, 10000)) ** 2
    assert not may_be_at(piece, pt(0, 0), r2_below)


def test_a_straddling_ball_falls_back_to_exact():
    # the foot of the perpendicular is exactly the segment's start, through numbers
    # whose balls do not cancel: the ball of t meets 0 and the exact sign settles it
    s2 = MQ.sqrt(2)
    piece = g.Segment((MQ(), s2), (q(4), s2))
    assert reach_decided(piece, pt(0, 0), q(2), within=False) == (True, "exact")
    assert reach_decided(piece, pt(0, 0), q(2), within=True) == (True, "exact")
    assert reach_decided(piece, pt(0, 0), q(2) - q(Fraction(1, 10 ** 30)),
                         within=True)[0] is False


def test_arc_ranges_without_square_roots():
    arc = g.Arc(pt(0, 0), pt(3, 0), pt(0, 3), 1)
    x = pt(10, 0)
    assert may_be_at(arc, x, q(49)) and may_be_at(arc, x, q(169))   # 7 and 13
    assert not may_be_at(arc, x, q(36)) and not may_be_at(arc, x, q(170))
    assert may_come_within(arc, x, q(49)) and not may_come_within(arc, x, q(48))
    # from inside the circle: the nearest point is 2 away
    assert may_come_within(arc, pt(1, 0), q(4)) and not may_come_within(arc, pt(1, 0), q(3))


@settings(max_examples=150, deadline=None)
@given(st.lists(st.fractions(min_value=-20, max_value=20, max_denominator=50),
                min_size=6, max_size=6),
       st.fractions(min_value=0, max_value=400, max_denominator=20), st.booleans())
def test_segment_reach_agrees_with_exact_range(c, r2, tiny):
    """The filtered answer is the exact one: lo2 <= r2 (<= hi2) on the exact range."""
    ax, ay, bx, by, xx, xy = c
    if tiny:                                     # chords far below the old 1e-6
        bx, by = ax + Fraction(1, 10 ** 9), ay - Fraction(1, 10 ** 8)
    a, b, x = (ax, ay), (bx, by), (xx, xy)
    d = (bx - ax, by - ay)
    v = (xx - ax, xy - ay)
    dd, t = d[0] ** 2 + d[1] ** 2, v[0] * d[0] + v[1] * d[1]
    sa = v[0] ** 2 + v[1] ** 2
    sb = (xx - bx) ** 2 + (xy - by) ** 2
    if dd == 0 or t <= 0:
        lo = sa
    elif t >= dd:
        lo = sb
    else:
        lo = (v[0] * d[1] - v[1] * d[0]) ** 2 / dd
    piece = g.Segment(pt(*a), pt(*b))
    assert may_come_within(piece, pt(*x), q(r2)) == (lo <= r2)
    assert may_be_at(piece, pt(*x), q(r2)) == (lo <= r2 <= max(sa, sb))
    # the double filter of piece_hits is a lower bound: never "far" when within 2
    assert g.piece_hits(piece, pt(*x)) == (lo < 4)


def test_no_module_state():
    """The filters keep no counters or caches between calls."""
    assert not [k for k, v in vars(motion).items()
                if isinstance(v, (dict, list, set)) and not k.startswith("__")]
