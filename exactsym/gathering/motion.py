"""A moving robot as a rational curve, and the polynomials of its relations.

A robot moving along a piece (segment or arc) over the parameter ``f`` in [0, 1] is at
``p(f) = N(f) / D(f)`` (:class:`Motion`): a segment linearly (``D = 1``); an arc by the
rational rotation whose half-angle tangent is ``f`` times that of the whole arc (what
``Arc.at`` does), ``D = 1 + T^2 f^2``.  A relation between the mover and fixed points (a
distance, a side of a line) is then a polynomial in ``f`` with exact coefficients
(:mod:`~exactsym.exact.algebraic.polynomials`) whose roots are the critical instants
(:mod:`.instants`, :mod:`.joint_instants`).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..exact.algebraic.polynomials import padd, pmul, pscale, psub, trim
from ..exact.algebraic.roots import roots_in_unit
from ..exact.multiquadratic import MQ
from . import geometry as g

__all__ = ["Motion", "motion_of", "rel", "dist2_poly", "cross_poly", "dot_poly",
           "point_param", "may_leave", "reach"]

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


def reach(piece, x) -> tuple:
    """Floats ``(lo, hi)`` with ``lo <= |p - x| <= hi`` for every point p of the piece,
    widened by a margin far above the floats' error (1e-6 relative, 1e-6 absolute): they
    only choose which polynomials to build (a layer, a tie or a contact outside the range
    has no root), never decide an instant."""
    def f(v):
        return float(v)
    if isinstance(piece, g.Segment):
        a, b = piece.start, piece.end
        ax, ay, bx, by, qx, qy = (f(a[0]), f(a[1]), f(b[0]), f(b[1]), f(x[0]), f(x[1]))
        dx, dy = bx - ax, by - ay
        den = dx * dx + dy * dy
        t = 0.0 if den == 0 else min(1.0, max(0.0, ((qx - ax) * dx + (qy - ay) * dy) / den))
        lo = ((ax + t * dx - qx) ** 2 + (ay + t * dy - qy) ** 2) ** 0.5
        hi = max(((ax - qx) ** 2 + (ay - qy) ** 2) ** 0.5, ((bx - qx) ** 2 + (by - qy) ** 2) ** 0.5)
    else:
        d = f(g.dist2(piece.centre, x)) ** 0.5
        r = f(g.dist2(piece.start, piece.centre)) ** 0.5
        lo, hi = abs(d - r), d + r
    return lo * (1 - 1e-6) - 1e-6, hi * (1 + 1e-6) + 1e-6
