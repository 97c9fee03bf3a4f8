"""The gaps of :mod:`exactsym.truth.symmetry` in number fields, made lazily (``_LazyGap``: a
ball from the coordinates' balls, exact parts only when read) and compared through their
remembered balls (``_Angle._cmp``), against the exact pseudo-angles they replace, on near
ties: equal gaps (one pair of rays turned by a rational turn), perpendicular and opposite
rays (a zero dot or cross product: the balls cannot pick the quadrant), gaps 10^-30 apart.
"""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from flint import fmpq

from exactsym.exact import sign
from exactsym.exact.cyclotomic import cos_turn, cyclotomic_field, sin_turn
from exactsym.geometry.predicates import PseudoAngle
from exactsym.truth.symmetry import _Angle, _LazyGap

M = 120
FIELD = cyclotomic_field(M)
TINY = fmpq(1, 10 ** 30)

turns = st.integers(0, M - 1).map(lambda k: fmpq(k, M))


def _unit(t):
    return (cos_turn(FIELD, t), sin_turn(FIELD, t))


def _turned(v, t):
    c, s = _unit(t)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])


@st.composite
def vectors(draw):
    """r (cos, sin) of a turn in 1/M, r in {1, 2, 3/2}, sometimes moved by 10^-30."""
    r = draw(st.sampled_from([fmpq(1), fmpq(2), fmpq(3, 2)]))
    c, s = _unit(draw(turns))
    v = (r * c, r * s)
    if draw(st.booleans()):
        v = (v[0] + draw(st.sampled_from([-1, 0, 1])) * TINY, v[1])
    return v


def _exact(u, v) -> PseudoAngle:
    (ux, uy), (vx, vy) = u, v
    return PseudoAngle(ux * vx + uy * vy, ux * vy - uy * vx)


def _sign_exact(a: PseudoAngle, b: PseudoAngle) -> int:
    if a.quadrant != b.quadrant:
        return -1 if a.quadrant < b.quadrant else 1
    return sign(a.num * b.den - b.num * a.den)


@st.composite
def gap_pairs(draw):
    """Two gaps (u, v), (u', v'), often with (u', v') the first pair turned (equal gaps),
    or one of its vectors turned by a quarter or a half (zero dot or cross product)."""
    u, v = draw(vectors()), draw(vectors())
    kind = draw(st.sampled_from(["free", "turned", "quarter", "half", "near"]))
    if kind == "turned":
        t = draw(turns)
        u2, v2 = _turned(u, t), _turned(v, t)
    elif kind in ("quarter", "half"):
        u2 = draw(vectors())
        v2 = _turned(u2, fmpq(1, 4) if kind == "quarter" else fmpq(1, 2))
    elif kind == "near":
        t = draw(turns)
        u2, v2 = _turned(u, t), _turned(v, t)
        v2 = (v2[0] + TINY, v2[1])
    else:
        u2, v2 = draw(vectors()), draw(vectors())
    return (u, v), (u2, v2)


@settings(max_examples=150, deadline=None)
@given(gap_pairs())
def test_lazy_gaps_compare_as_the_exact_ones(pairs):
    (u, v), (u2, v2) = pairs
    e1, e2 = _exact(u, v), _exact(u2, v2)
    lazy1, lazy2 = _LazyGap(u, v), _LazyGap(u2, v2)
    want = _sign_exact(e1, e2)
    assert lazy1._cmp(lazy2) == want
    assert (lazy1 == lazy2) == (want == 0)
    assert (lazy1 < lazy2) == (want < 0)
    # the ball holds the exact value
    for lazy, exact in ((lazy1, e1), (lazy2, e2)):
        assert lazy.ball().overlaps(exact.ball(128))
    # read, the exact parts are those of the eager gap (three products, Gauss)
    eager = _Angle(*_gauss(u, v))
    assert (lazy1.quadrant, lazy1.num, lazy1.den) == (eager.quadrant, eager.num, eager.den)
    assert _sign_exact(eager, e1) == 0


def _gauss(u, v):
    (ux, uy), (vx, vy) = u, v
    k = vx * (ux - uy)
    return k + uy * (vx + vy), k + ux * (vy - vx)


@settings(max_examples=60, deadline=None)
@given(vectors(), st.sampled_from([fmpq(0), fmpq(1, 4), fmpq(1, 2), fmpq(3, 4)]))
def test_lazy_gaps_on_axes_and_against_rationals(u, t):
    """Rays a quarter or a half apart: the balls leave the quadrant open, the exact parts
    decide; a half turn equals the pseudo-angle 2 (symmetry._is_half_turn)."""
    v = _turned(u, t)
    lazy = _LazyGap(u, v)
    exact = _exact(u, v)
    assert lazy._cmp(2) == exact._cmp(2)
    assert (lazy == 2) == (t == fmpq(1, 2))
    assert lazy._cmp(_LazyGap(v, u)) == _sign_exact(exact, _exact(v, u))


@settings(max_examples=30, deadline=None)
@given(vectors(), vectors())
def test_a_ray_to_itself(u, v):
    """One ray: the gap from u to the same vector object is exactly 0 (its ball is the
    point 0, no product made), compares as the exact gap and reads back exact parts."""
    lazy, exact = _LazyGap(u, u), _exact(u, u)
    assert lazy.ball() == 0 and exact == 0
    other = _LazyGap(u, v)
    assert lazy._cmp(other) == _sign_exact(exact, _exact(u, v))
    assert lazy._cmp(_LazyGap(v, v)) == 0
    assert (lazy.quadrant, sign(lazy.num)) == (0, 0)
