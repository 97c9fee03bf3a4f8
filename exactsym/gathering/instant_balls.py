"""Arb balls of a motion's relations, to skip those that have no root inside the piece.

The critical instants (:mod:`.instants`) build one polynomial per relation (the mover on
the circle on a diameter, a right angle, the circle through three hull robots, ...) and
isolate its roots in (0, 1); most relations have none there.  A joint step's in-circle
determinants (:mod:`.joint_instants`, four robots on one circle) likewise
(:func:`incircle_clear`).  Building them exactly is
products of coefficients of up to 256 terms and thousands of bits; a ball of each
coefficient, from the balls of the motion and of the points, costs a few Arb operations.

Soundness: every kernel number's ``enclosure`` is a rigorous ball, and interval arithmetic
keeps the exact value inside every ball it computes.  So when
:func:`~exactsym.exact.algebraic.sturm.balls_clear_unit` proves that no polynomial with
coefficients in the balls has a root in [0, 1], the exact relation has none in (0, 1), and
leaving it out changes nothing (:func:`~exactsym.exact.algebraic.roots.roots_of` reads
only roots); likewise a robot proved strictly outside a circle (a ball of ``|c - p|^2 -
r^2`` above 0) is what the exact test ``encloses`` would find.  A ball that cannot decide
sends the case to the exact code, unchanged.
"""

from __future__ import annotations

from flint import arb, ctx

from ..exact.algebraic.sturm import balls_clear_unit

PREC = 128


def point_ball(p) -> tuple:
    return (p[0].enclosure(PREC), p[1].enclosure(PREC))


def _poly_ball(p) -> list:
    return [c.enclosure(PREC) for c in p]


class MotionBall:
    """The balls of a :class:`.instants.Motion`'s coefficients (``N_x``, ``N_y``, ``D``)."""

    def __init__(self, m):
        self.nx, self.ny, self.d = _poly_ball(m.nx), _poly_ball(m.ny), _poly_ball(m.d)

    def _rel(self, x):
        """The balls of ``N - x D`` (:func:`.instants._rel`)."""
        n = max(len(self.nx), len(self.ny), len(self.d))
        u = [_at(self.nx, k) - x[0] * _at(self.d, k) for k in range(n)]
        v = [_at(self.ny, k) - x[1] * _at(self.d, k) for k in range(n)]
        return u, v

    def dot_clear(self, x, w) -> bool:
        """Does ``dot_poly(m, x, w)`` surely have no root in (0, 1)?  (balls of x, w)"""
        with ctx.workprec(PREC):
            u, v = self._rel(x)
            return balls_clear_unit([a * w[0] + b * w[1] for a, b in zip(u, v)], PREC)

    def dist2_clear(self, x, r2) -> bool:
        """Does ``dist2_poly(m, x, r2)`` surely have no root in (0, 1)?"""
        with ctx.workprec(PREC):
            u, v = self._rel(x)
            uu, vv, dd = _mul(u, u), _mul(v, v), _mul(self.d, self.d)
            n = max(len(uu), len(dd))
            return balls_clear_unit([_at(uu, k) + _at(vv, k) - _at(dd, k) * r2
                                     for k in range(n)], PREC)


def dist2_ball(a, b):
    dx, dy = a[0] - b[0], a[1] - b[1]
    return dx * dx + dy * dy


def surely_outside(centre, r2, balls) -> bool:
    """Is one of the points (balls) proved strictly outside the circle (centre, r2)?"""
    with ctx.workprec(PREC):
        return any(dist2_ball(centre, p) - r2 > 0 for p in balls)


def circle3_ball(a, b, c):
    """Balls of the circle through three points (balls), or None when the balls do not
    prove them not collinear."""
    with ctx.workprec(PREC):
        abx, aby, acx, acy = b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]
        d = (abx * acy - aby * acx) * 2
        if d.contains(0):
            return None
        b2, c2 = abx * abx + aby * aby, acx * acx + acy * acy
        ux, uy = (b2 * acy - c2 * aby) / d, (c2 * abx - b2 * acx) / d
        return (a[0] + ux, a[1] + uy), ux * ux + uy * uy


def incircle_clear(balls) -> bool:
    """Does the in-circle determinant of four moving points
    (:func:`.joint_relations.incircle_poly`; ``balls``: their :class:`MotionBall` objects)
    surely have no root in (0, 1)?  The same rows and expansion, on balls."""
    with ctx.workprec(PREC):
        rows = [(_mul(b.nx, b.d), _mul(b.ny, b.d), _add(_mul(b.nx, b.nx), _mul(b.ny, b.ny)),
                 _mul(b.d, b.d)) for b in balls]
        return balls_clear_unit(_det(rows), PREC)


def _det(rows) -> list:
    if len(rows) == 1:
        return rows[0][0]
    out: list = []
    for j in range(len(rows)):
        term = _mul(rows[0][j], _det([r[:j] + r[j + 1:] for r in rows[1:]]))
        out = _add(out, term) if j % 2 == 0 else _add(out, [-c for c in term])
    return out


def _add(p, q) -> list:
    return [_at(p, k) + _at(q, k) for k in range(max(len(p), len(q)))]


def _at(p, k):
    return p[k] if k < len(p) else arb(0)


def _mul(p, q) -> list:
    out = [arb(0)] * (len(p) + len(q) - 1) if p and q else []
    for i, a in enumerate(p):
        for j, b in enumerate(q):
            out[i + j] = out[i + j] + a * b
    return out
