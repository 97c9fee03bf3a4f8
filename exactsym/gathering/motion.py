"""A moving robot as a rational curve, and the polynomials of its relations.

A robot moving along a piece (segment or arc) over the parameter ``f`` in [0, 1] is at
``p(f) = N(f) / D(f)`` (:class:`Motion`): a segment linearly (``D = 1``); an arc by the
rational rotation whose half-angle tangent is ``f`` times that of the whole arc (what
``Arc.at`` does), ``D = 1 + T^2 f^2``.  A relation between the mover and fixed points (a
distance, a side of a line) is then a polynomial in ``f`` with exact coefficients
(:mod:`~exactsym.exact.algebraic.polynomials`) whose roots are the critical instants
(:mod:`.instants`, :mod:`.joint_instants`).  Which relations can have a root at all is
told by :func:`may_be_at` and :func:`may_come_within`: Arb balls with a proof, the exact
numbers when a ball cannot tell.
"""

from __future__ import annotations

from dataclasses import dataclass

from flint import arb, ctx

from ..exact.algebraic.polynomials import padd, pmul, pscale, psub, trim
from ..exact.algebraic.roots import roots_in_unit
from ..exact.multiquadratic import MQ
from . import geometry as g

__all__ = ["Motion", "motion_of", "rel", "dist2_poly", "cross_poly", "dot_poly",
           "point_param", "may_leave", "may_be_at", "may_come_within", "reach_decided"]

ONE = MQ.rational(1)


@dataclass(frozen=True)
class Motion:
    nx: tuple
    ny: tuple
    d: tuple


def motion_of(piece) -> Motion:
    if isinstance(piece, g.Segment):
        s, e = piece.start, piece.end
        return Motion(trim((s[0], e[0] - s[0])), trim((s[1], e[1] - s[1])), (ONE,))
    c = piece.centre
    a = g.sub(piece.start, c)
    b = g.sub(piece.end, c)
    r2 = g.dot(a, a)
    cos_t, sin_t = g.dot(a, b) / r2, g.cross(a, b) / r2
    T = sin_t / (1 + cos_t)
    T2 = T * T
    # c (1 + T^2 f^2) + (1 - T^2 f^2) a + 2 T f J a,  J a = (-a_y, a_x)
    nx = trim((c[0] + a[0], -2 * T * a[1], T2 * (c[0] - a[0])))
    ny = trim((c[1] + a[1], 2 * T * a[0], T2 * (c[1] - a[1])))
    return Motion(nx, ny, (ONE, MQ(), T2))


def rel(m: Motion, x):
    """``(N - x D)``: D times the vector from ``x`` to the mover."""
    return psub(m.nx, pscale(m.d, x[0])), psub(m.ny, pscale(m.d, x[1]))


def dist2_poly(m: Motion, x, r2) -> tuple:
    """``D^2 (|p - x|^2 - r2)``."""
    u, v = rel(m, x)
    return psub(padd(pmul(u, u), pmul(v, v)), pscale(pmul(m.d, m.d), r2))


def cross_poly(m: Motion, x, w) -> tuple:
    """``D cross(p - x, w)``: zero where the mover is on the line through x along w."""
    u, v = rel(m, x)
    return psub(pscale(u, w[1]), pscale(v, w[0]))


def dot_poly(m: Motion, x, w) -> tuple:
    u, v = rel(m, x)
    return padd(pscale(u, w[0]), pscale(v, w[1]))


def point_param(piece, q):
    """The parameter ``f`` in (0, 1) with ``piece.at(f) == q``, or None."""
    if isinstance(piece, g.Segment):
        d, v = g.sub(piece.end, piece.start), g.sub(q, piece.start)
        if g.dot(d, d).is_zero() or not g.cross(d, v).is_zero():
            return None
        f = g.dot(d, v) / g.dot(d, d)
    else:
        a, v = g.sub(piece.start, piece.centre), g.sub(q, piece.centre)
        if g.dot(a, a) != g.dot(v, v) or not piece.contains_direction(v):
            return None
        b = g.sub(piece.end, piece.centre)
        r2 = g.dot(a, a)
        T = (g.cross(a, b) / r2) / (1 + g.dot(a, b) / r2)
        u = g.cross(a, v) / (r2 + g.dot(a, v))      # tan of half the angle a -> v
        f = u / T
    if f.sign() > 0 and (f - 1).sign() < 0:
        return f
    return None


def may_leave(m: Motion, c, r2) -> bool:
    """Can the mover be strictly outside the circle (c, r2) at some time in [0, 1]?"""
    e = dist2_poly(m, c, r2)
    if not e:
        return False
    return sum(e, MQ()).sign() > 0 or e[0].sign() > 0 or bool(roots_in_unit(e))


#: Working precision of the reach filters' balls (bits).
REACH_PREC = 128


def may_be_at(piece, x, r2) -> bool:
    """Can the mover be exactly at squared distance ``r2`` from ``x`` at some instant of
    ``piece``?  A superset test (False only when it surely is not): a relation left out
    on False has no root inside the piece.  :func:`reach_decided` says how."""
    return reach_decided(piece, x, r2, within=False)[0]


def may_come_within(piece, x, r2) -> bool:
    """Can the mover come to squared distance at most ``r2`` from ``x`` on ``piece``?"""
    return reach_decided(piece, x, r2, within=True)[0]


class _Straddle(Exception):
    """A ball that cannot settle a comparison: the exact numbers must."""


def reach_decided(piece, x, r2, within: bool) -> tuple:
    """``(answer, "ball" | "exact")``: :func:`may_come_within` (``within``) or
    :func:`may_be_at`, and which arithmetic settled it.

    Segment ``a -> b``: the squared distance to ``x`` is a convex quadratic in the
    parameter, so over the segment it fills ``[lo2, hi2]``, ``hi2 = max(|a-x|^2,
    |b-x|^2)``, ``lo2`` at the clamped foot of the perpendicular: ``|a-x|^2`` when
    ``t = dot(x-a, b-a) <= 0``, ``|b-x|^2`` when ``t >= |b-a|^2``, else ``cross(x-a,
    b-a)^2 / |b-a|^2``.  Arc about ``c``, radius ``r``: its points lie on the circle,
    whose distances to ``x`` (``d = |c - x|``) fill ``[|d - r|, d + r]`` (a superset of
    the arc's); with ``D = d^2``, ``R = r^2``, ``s = D + R - r2``: ``sqrt(r2)`` lies in it
    iff ``|s| <= 2 sqrt(D R)`` iff ``s^2 <= 4 D R`` (the triangle inequality), and
    ``|d - r| <= sqrt(r2)`` iff ``s <= 0`` or ``s^2 <= 4 D R``: no square root.

    The filter: the same formulas on Arb balls of the coordinates (``enclosure``, 128
    bits); interval arithmetic keeps every exact value inside its ball, so a comparison
    whose gap ball lies on one side of 0 is the exact comparison's answer.  A gap ball
    that meets 0 (an equality, or too close to tell) raises, and the whole test is done
    again on the exact numbers.  (The float reach this replaces widened by a fixed 1e-6:
    no proof covered numbers of large magnitude or a distance within 1e-6 of a layer.)"""
    try:
        with ctx.workprec(REACH_PREC):
            ball = lambda p: (p[0].enclosure(REACH_PREC), p[1].enclosure(REACH_PREC))
            return _reach(piece, ball, ball(x), r2.enclosure(REACH_PREC), within,
                          _ball_le, arb(0)), "ball"
    except _Straddle:
        return _reach(piece, lambda p: p, x, r2, within, _exact_le, MQ()), "exact"


def _reach(piece, conv, x, r2, within, le, zero) -> bool:
    if isinstance(piece, g.Segment):
        a, b = conv(piece.start), conv(piece.end)
        sa, sb = _d2(a, x), _d2(b, x)
        d, v = _sub(b, a), _sub(x, a)
        dd, t = _dot(d, d), _dot(v, d)
        if le(dd, zero):                        # a zero-length piece: one point
            lo = sa
        elif le(t, zero):
            lo = sa
        elif le(dd, t):
            lo = sb
        else:
            c = _cross(v, d)
            lo = c * c / dd
        return le(lo, r2) and (within or le(r2, sa) or le(r2, sb))
    c = conv(piece.centre)
    D, R = _d2(c, x), _d2(conv(piece.start), c)
    s = D + R - r2
    if within and le(s, zero):
        return True
    return le(s * s, 4 * D * R)


def _ball_le(u, v) -> bool:
    gap = v - u
    if gap >= 0:
        return True
    if gap < 0:
        return False
    raise _Straddle


def _exact_le(u, v) -> bool:
    return (v - u).sign() >= 0


def _sub(p, q):
    return (p[0] - q[0], p[1] - q[1])


def _dot(p, q):
    return p[0] * q[0] + p[1] * q[1]


def _cross(p, q):
    return p[0] * q[1] - p[1] * q[0]


def _d2(p, q):
    w = _sub(p, q)
    return _dot(w, w)
