"""Exact plane geometry: predicates return enums or ints, constructions return exact points.

Points are pairs ``(x, y)`` of exact numbers of :mod:`exactsym.exact` (``fmpq`` or
``FieldElement`` of one field).  Nothing here rounds, except the float filters at the
end, whose proven error bounds only split values into certainly ordered groups.
"""

from __future__ import annotations

import math
from enum import IntEnum
from functools import cmp_to_key

import numpy as np

from ..exact import sign

Point = tuple


class Turn(IntEnum):
    """Orientation of an ordered triple: the sign of the cross product."""
    RIGHT = -1      # clockwise
    COLLINEAR = 0
    LEFT = 1        # counter-clockwise


def cross(o: Point, a: Point, b: Point):
    """``(a - o) x (b - o)``."""
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def orientation(p: Point, q: Point, r: Point) -> Turn:
    return Turn(sign(cross(p, q, r)))


def squared_distance(p: Point, q: Point):
    dx, dy = p[0] - q[0], p[1] - q[1]
    return dx * dx + dy * dy


def compare_distance(c: Point, p: Point, q: Point) -> int:
    """Sign of ``|cp|^2 - |cq|^2``: -1 when p is nearer to c than q."""
    return sign(squared_distance(c, p) - squared_distance(c, q))


def midpoint(p: Point, q: Point) -> Point:
    return ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)


def circumcentre(a: Point, b: Point, c: Point) -> Point:
    """Centre of the circle through three non-collinear points (raises ValueError otherwise)."""
    bx, by = b[0] - a[0], b[1] - a[1]
    cx, cy = c[0] - a[0], c[1] - a[1]
    d = 2 * (bx * cy - by * cx)
    if d == 0:
        raise ValueError("collinear points have no circumcentre")
    b2, c2 = bx * bx + by * by, cx * cx + cy * cy
    return (a[0] + (cy * b2 - by * c2) / d, a[1] + (bx * c2 - cx * b2) / d)


def circumcentre_homogeneous(a: Point, b: Point, c: Point) -> tuple:
    """``(X, Y, D)`` with ``D > 0``: the circumcentre is ``(X/D, Y/D)``; nothing is divided
    (raises ValueError for collinear points)."""
    bx, by = b[0] - a[0], b[1] - a[1]
    cx, cy = c[0] - a[0], c[1] - a[1]
    d = 2 * (bx * cy - by * cx)
    s = sign(d)
    if s == 0:
        raise ValueError("collinear points have no circumcentre")
    b2, c2 = bx * bx + by * by, cx * cx + cy * cy
    x, y = a[0] * d + (cy * b2 - by * c2), a[1] * d + (bx * c2 - cx * b2)
    return (x, y, d) if s > 0 else (-x, -y, -d)


def orientation_homogeneous(p: Point, q: Point, o: tuple) -> Turn:
    """``orientation(p, q, (X/D, Y/D))`` for ``o = (X, Y, D)``, ``D > 0``, without dividing."""
    x, y, d = o
    return Turn(sign((q[0] - p[0]) * (y - d * p[1]) - (q[1] - p[1]) * (x - d * p[0])))


def half_plane(d: Point) -> int:
    """0 for directions with angle in [0, pi), 1 for [pi, 2 pi); ``d`` must not be zero."""
    sy = sign(d[1])
    return 0 if sy > 0 or (sy == 0 and sign(d[0]) > 0) else 1


def compare_directions(d1: Point, d2: Point) -> int:
    """Compare the angles in [0, 2 pi) of two non-zero vectors: -1, 0 or 1."""
    h1, h2 = half_plane(d1), half_plane(d2)
    if h1 != h2:
        return -1 if h1 < h2 else 1
    return -sign(d1[0] * d2[1] - d1[1] * d2[0])


def angular_sort(centre: Point, points: list[Point], indices: list[int]) -> list[int]:
    """``indices`` sorted counter-clockwise about ``centre``, starting at angle 0 (the +x ray).

    Points at the centre itself come first.
    """
    def direction(i):
        return (points[i][0] - centre[0], points[i][1] - centre[1])

    def cmp(i, j):
        di, dj = direction(i), direction(j)
        zi, zj = di[0] == 0 and di[1] == 0, dj[0] == 0 and dj[1] == 0
        if zi or zj:
            return (zj - zi)
        return compare_directions(di, dj)

    return sorted(indices, key=cmp_to_key(cmp))


class PseudoAngle:
    """The diamond angle of a non-zero vector (``symmetry.pseudo_angle``) kept as
    ``quadrant + num/den`` with ``den > 0``: nothing is divided, so no field inverse is
    computed (issue 9: 64 inverses in Q(zeta_4620) took 25 s for a 32-point set).

    The quadrants' ranges [0, 1), [1, 2], (2, 3), [3, 4) are disjoint, so values compare by
    quadrant, then by the sign of ``num1*den2 - num2*den1``.  ``ball(prec)`` is an Arb
    enclosure, a filter for sorting and grouping; it decides nothing."""

    __slots__ = ("quadrant", "num", "den")

    def __init__(self, x, y):
        if y >= 0:
            if x > 0:
                self.quadrant, self.num, self.den = 0, y, x + y
            else:
                self.quadrant, self.num, self.den = 1, -x, y - x
        elif x < 0:
            self.quadrant, self.num, self.den = 2, -y, -(x + y)
        else:
            self.quadrant, self.num, self.den = 3, x, x - y

    def _cmp(self, other) -> int:
        if isinstance(other, PseudoAngle):
            if self.quadrant != other.quadrant:
                return -1 if self.quadrant < other.quadrant else 1
            return sign(self.num * other.den - other.num * self.den)
        return sign(self.num + (self.quadrant - other) * self.den)     # a rational value

    def __eq__(self, other):
        return self._cmp(other) == 0

    def __ne__(self, other):
        return self._cmp(other) != 0

    def __lt__(self, other):
        return self._cmp(other) < 0

    def __le__(self, other):
        return self._cmp(other) <= 0

    def __gt__(self, other):
        return self._cmp(other) > 0

    def __ge__(self, other):
        return self._cmp(other) >= 0

    __hash__ = None     # equal values may have different (num, den): group with intern_by_value

    def ball(self, prec: int = 64):
        from flint import ctx
        with ctx.workprec(prec):
            return self.quadrant + enclosure_of(self.num, prec) / enclosure_of(self.den, prec)


def enclosure_of(x, prec: int):
    """An Arb ball around the exact number ``x`` (a kernel number at ``prec`` bits, or a
    rational, exactly)."""
    from flint import arb
    if hasattr(x, "enclosure"):
        return x.enclosure(prec)
    return arb(x)


def sorted_by_value(indices: list, values) -> list:
    """``indices`` sorted by ``values[i]`` (exact comparisons), stable.  A sort on the
    midpoints of Arb balls proposes the order; every adjacent pair is then checked exactly
    and any disorder falls back to the exact comparison sort."""
    mids = {i: values[i].ball().mid() for i in indices}
    proposal = sorted(indices, key=lambda i: mids[i])
    if all(values[a] <= values[b] for a, b in zip(proposal, proposal[1:])):
        return proposal
    return sorted(indices, key=cmp_to_key(lambda a, b: values[a]._cmp(values[b])))


def intern_by_value(values) -> list[int]:
    """Small integers, equal iff the values are exactly equal, for values without a hash
    (:class:`PseudoAngle`).  Arb balls pick the candidates: values whose balls are disjoint
    differ; only overlapping ones are compared exactly (a sweep over the balls sorted by
    midpoint, scanning back as far as the widest radius allows)."""
    balls = [v.ball() for v in values]
    order = sorted(range(len(values)), key=lambda i: balls[i].mid())
    ids = [0] * len(values)
    reps: list[int] = []                       # one index per class, in midpoint order
    widest = 0.0
    count = 0
    for i in order:
        b = balls[i]
        widest = max(widest, float(b.rad()))
        low = float(b.mid()) - float(b.rad()) - widest
        match = None
        for r in reversed(reps):
            if float(balls[r].mid()) < low - abs(low) * 2.0 ** -50:
                break                          # this ball and all before it end below b
            if balls[r].overlaps(b) and values[r] == values[i]:
                match = r
                break
        if match is None:
            ids[i] = count
            count += 1
            reps.append(i)
        else:
            ids[i] = ids[match]
    return ids


# ---------------------------------------------------------------- float filters (NumPy)
#
# Proven error bounds (docs/numbers.md, "Filtered predicates over arrays"): a float filter
# only splits values into groups such that every exact value of a group is less than every
# exact value of the next group; ties and near-ties stay in one group and are decided
# exactly by the caller.

FILTER_EPS = 2.0 ** -50           # >= 4 units in the last place of a double
_TINY = 1e-290                    # covers underflow in products of subnormal magnitudes


def float_coordinates(points):
    """``(fx, fy)``: the correctly rounded floats of the coordinates of rational points
    (``float(fmpq)``), as arrays; None when one is not a finite double.  Computed once per
    configuration (``Levels.floats``) and shared by the SEC, the levels and the rays."""
    try:
        fx = np.fromiter((float(p[0]) for p in points), dtype=float, count=len(points))
        fy = np.fromiter((float(p[1]) for p in points), dtype=float, count=len(points))
    except (OverflowError, ValueError):
        return None
    if not (np.isfinite(fx).all() and np.isfinite(fy).all()):
        return None
    return fx, fy


def float_differences(points, origin, floats=None):
    """``(dx, dy, ex, ey)``: float arrays with ``|dx - (x - ox)| <= ex`` (likewise y) for
    rational points and origin (``float(fmpq)`` is within a relative 2^-52 of its value).
    ``floats``: the points' :func:`float_coordinates`, when already computed.
    None when a value is not a finite double."""
    if floats is None:
        floats = float_coordinates(points)
        if floats is None:
            return None
    fx, fy = floats
    try:
        ox, oy = float(origin[0]), float(origin[1])
    except (OverflowError, ValueError):
        return None
    if not (math.isfinite(ox) and math.isfinite(oy)):
        return None
    dx, dy = fx - ox, fy - oy
    ex = FILTER_EPS * (np.abs(fx) + abs(ox) + np.abs(dx)) + _TINY
    ey = FILTER_EPS * (np.abs(fy) + abs(oy) + np.abs(dy)) + _TINY
    return dx, dy, ex, ey


def float_squared_norms(dx, dy, ex, ey):
    """``(r2, err)``: floats within ``err`` of ``x^2 + y^2`` for the exact ``x, y`` within
    ``ex, ey`` of ``dx, dy``; None when a value is not finite.  ``|x^2 - dx^2| =
    |x - dx| |x + dx| <= ex (2 |dx| + ex)``; the two products and the sum add at most
    ``3u r2`` (``FILTER_EPS >= 4u``); 1.01 covers the rounding of the bound itself."""
    with np.errstate(all="ignore"):
        r2 = dx * dx + dy * dy
        err = (ex * (2 * np.abs(dx) + ex) + ey * (2 * np.abs(dy) + ey)) * 1.01 \
            + FILTER_EPS * r2 + _TINY
    if not (np.isfinite(r2).all() and np.isfinite(err).all()):
        return None
    return r2, err


def float_pseudo_angles(vx, vy, ex, ey):
    """``(keys, errs, sure)``: for vectors known within ``ex, ey`` (componentwise), floats
    ``keys`` within ``errs`` of the exact diamond angle (:class:`PseudoAngle`) where ``sure``;
    elsewhere (a sign of a component, hence the quadrant, not certified) the caller must
    supply exact keys.  Bound: with ``s = |x| + |y|`` and ``E = max(ex, ey)``, the ratio
    ``a / s`` (a one of |x|, |y|) moves by at most ``E / s'`` (s' the float sum, > 2E)."""
    with np.errstate(all="ignore"):
        ax, ay = np.abs(vx), np.abs(vy)
        s = ax + ay
        big = np.maximum(ex, ey)
        sure = (ax > ex) & (ay > ey) & (s > 2 * big) & np.isfinite(s)
        upper = vy > 0
        quadrant = np.where(upper, np.where(vx > 0, 0.0, 1.0), np.where(vx < 0, 2.0, 3.0))
        numer = np.where(upper == (vx > 0), ay, ax)
        keys = quadrant + numer / s
        errs = big / s * 1.01 + 2.0 ** -46
    return keys, errs, sure


def certified_groups(keys, errs):
    """``(order, starts)``: ``order`` sorts ``keys``; the groups ``order[starts[g]:
    starts[g+1]]`` are such that every exact value (within ``errs`` of its key) of one
    group is strictly less than every exact value of any later group."""
    order = np.argsort(keys, kind="stable")
    k, e = keys[order], errs[order]
    hi = np.maximum.accumulate(k + e)
    lo = np.minimum.accumulate((k - e)[::-1])[::-1]
    cut = hi[:-1] < lo[1:]
    return order, np.flatnonzero(np.concatenate(([True], cut)))


def angular_ranks(points, centre, diffs=None) -> list[int] | None:
    """``rank[i]``: the position of point i when all points are sorted counter-clockwise
    about ``centre`` from the +x ray (as :func:`angular_sort`; the point at the centre
    ranks -1), for rational points and centre.  Floats with proven bounds
    (:func:`float_pseudo_angles`) order whatever they can; points whose quadrant is
    uncertain, and groups the bounds cannot split, are ordered by the exact rational
    pseudo-angle.  Points of one direction get distinct ranks in an arbitrary order (no
    two of them share a level).  ``diffs``: the :func:`float_differences` of the points
    from ``centre``, when already computed.  None when the floats overflow."""
    if diffs is None:
        diffs = float_differences(points, centre)
    if diffs is None:
        return None
    dx, dy, ex, ey = diffs
    keys, errs, sure = float_pseudo_angles(dx, dy, ex, ey)
    cx, cy = centre
    exact: dict = {}

    def exact_key(i):
        key = exact.get(i)
        if key is None:
            a = PseudoAngle(points[i][0] - cx, points[i][1] - cy)
            key = exact[i] = a.quadrant + a.num / a.den
        return key

    rank = [0] * len(points)
    at_centre = None
    for i in np.flatnonzero(~sure).tolist():
        if points[i][0] == cx and points[i][1] == cy:
            at_centre = i
            keys[i], errs[i] = -1.0, 0.5
            continue
        keys[i], errs[i] = float(exact_key(i)), 2.0 ** -46
    order, starts = certified_groups(keys, errs)
    flat = order.tolist()
    if len(starts) < len(flat):
        bounds = starts.tolist() + [len(flat)]
        for g in range(len(bounds) - 1):
            a, b = bounds[g], bounds[g + 1]
            if b - a > 1:
                flat[a:b] = sorted(flat[a:b], key=exact_key)
    for position, i in enumerate(flat):
        rank[i] = position
    if at_centre is not None:
        rank[at_centre] = -1
    return rank
