"""Exact plane geometry for the gathering simulator: points, paths, collision predicates.

Points are pairs of :class:`~exactsym.exact.multiquadratic.MQ` (multiquadratic field
elements); no angle, ``atan2`` or ``arcsin`` is ever computed: angular comparisons use
signs of cross and dot products.  Paths are sequences of :class:`Segment` and
:class:`Arc` pieces (circular arcs about a centre, each at most a quarter turn, so that
"is this direction inside the arc" is two cross-product signs).

Predicates (CGAL style: they return bools or small ints and are exact):

* :func:`segment_min_dist2_less` -- does a disc moving along a segment come closer than
  ``d`` to a fixed point (the closest point of a segment is the clamped projection);
* :func:`arc_min_dist2_less` -- the same along an arc (the closest point of a circle arc
  to ``q`` is the radial projection of ``q`` when its direction is inside the arc, else
  an end point);
* :func:`linear_motions_min_dist2_less` -- two discs moving along segments at once over
  the same time interval (the squared distance is a quadratic in time: its vertex).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..exact.algebraic.interface import (float_and_error, is_field_number, motion_number,
                                         products_are_large,
                                         two_products)
from ..exact.algebraic.norms import negative_instant
from ..exact.algebraic.polynomials import padd, pmul, pscale, trim
from ..exact.multiquadratic import MQ, mq, sqrt_rational
from ..geometry import sec
from ..geometry.predicates import circumcentre

Point = tuple  # (MQ, MQ)

ZERO = MQ()
ONE = MQ.rational(1)


def point(x, y) -> Point:
    return (mq(x), mq(y))


def add(p, q):
    return (p[0] + q[0], p[1] + q[1])


def sub(p, q):
    return (p[0] - q[0], p[1] - q[1])


def scale(p, s):
    return (p[0] * s, p[1] * s)


def dot(u, v):
    return two_products(u[0], v[0], u[1], v[1], 1)


def cross(u, v):
    return two_products(u[0], v[1], u[1], v[0], -1)


def dist2(p, q):
    if products_are_large(p[0], q[0], p[1], q[1]) or is_field_number(p[0]):
        key = (p, q)
        try:
            out = _DIST2.get(key)
        except ValueError:      # equal hashes of numbers of two K(alpha): never compared
            out, key = None, None
        if out is not None:
            return out
        d = sub(p, q)
        out = dot(d, d)
        if len(_DIST2) >= _DIST2_MAX:
            _DIST2.clear()
        if key is not None:
            _DIST2[key] = out
        return out
    d = sub(p, q)
    return dot(d, d)


#: dist2 of the same two points (a decision measures a robot's distance to the centre in
#: the recogniser, in R's distances and in the centre rule): remembered by value, bounded;
#: only for MQ coordinates with several terms (their hashes are remembered, and a key
#: met again is usually the same object, found without comparing; small ones cost less
#: than the look-up) and for numbers of K(alpha) (an algebraic start: a product there is
#: d^2 MQ products and a reduction)
_DIST2: dict = {}
_DIST2_MAX = 1 << 12


def rotate(u, c, s):
    """``u`` rotated by the rotation with cosine ``c`` and sine ``s``."""
    return (u[0] * c - u[1] * s, u[0] * s + u[1] * c)


def quarter(u, sense: int):
    """``u`` turned a quarter turn counter-clockwise (``sense = 1``) or clockwise."""
    return (-u[1], u[0]) if sense > 0 else (u[1], -u[0])


def radial_point(centre, p, radius: int):
    """The point at distance ``radius`` from ``centre`` on the ray towards ``p``:
    ``centre + radius * (p - centre) / |p - centre|``.  ``|p - centre|^2`` must be
    rational (it is for every robot that has not yet slid along an arc)."""
    v = sub(p, centre)
    r2 = dot(v, v)
    if not r2.is_rational():
        # p lies on a circle whose radius is known only through its square in a larger
        # field: robot.radial_point takes that root (multiquadratic, or a run's tower)
        raise ValueError("radial_point needs a rational squared distance")
    inv = sqrt_rational(1 / r2.to_fmpq())   # 1/|v|, a single radical
    return add(centre, scale(v, inv * radius))


def angle_key(u, v):
    """A key ordering the counter-clockwise angle from ``u`` to ``v`` in [0, 2 pi) when
    all compared pairs have the same ``|u| |v|``: ``(half, t)``, ``t`` increasing with
    the angle inside each half turn."""
    c, s = dot(u, v), cross(u, v)
    if s.sign() > 0 or (s.sign() == 0 and c.sign() > 0):
        return (0, -c)
    return (1, c)


def angle_less(k1, k2) -> bool:
    """Compare two :func:`angle_key` values exactly."""
    if k1[0] != k2[0]:
        return k1[0] < k2[0]
    return k1[1] < k2[1]


@dataclass(frozen=True)
class Segment:
    start: Point
    end: Point

    @property
    def final(self):
        return self.end

    def at(self, f):
        """The point at rational fraction ``f`` of the way."""
        return add(self.start, scale(sub(self.end, self.start), f))

    def split(self, f):
        mid = self.at(f)
        return Segment(self.start, mid), Segment(mid, self.end)


@dataclass(frozen=True)
class Arc:
    """From ``start`` to ``end`` about ``centre``, counter-clockwise when ``sense = 1``;
    at most a quarter turn (:func:`arc_path` splits longer ones)."""
    centre: Point
    start: Point
    end: Point
    sense: int

    @property
    def final(self):
        return self.end

    def contains_direction(self, w) -> bool:
        """Is the ray from the centre along ``w`` inside the (closed) arc?"""
        a, b = sub(self.start, self.centre), sub(self.end, self.centre)
        if self.sense > 0:
            return cross(a, w).sign() >= 0 and cross(w, b).sign() >= 0 and dot(a, w).sign() + \
                dot(b, w).sign() > -2
        return cross(w, a).sign() >= 0 and cross(b, w).sign() >= 0 and dot(a, w).sign() + \
            dot(b, w).sign() > -2

    def at(self, f):
        """The point of the arc reached by the rational rotation whose half-angle tangent is
        ``f`` times that of the whole arc (``0 <= f <= 1``, stays in the same field)."""
        a = sub(self.start, self.centre)
        t = self._tan_half * f
        t2 = t * t
        inv = 1 / (1 + t2)          # one inverse for both (the same values as dividing)
        return add(self.centre, rotate(a, (1 - t2) * inv, (2 * t) * inv))

    @cached_property
    def _tan_half(self):
        """tan of half the whole arc's angle (the arc is at most a quarter turn); kept on
        the arc, whose points never change: a motion's instants are all on one arc."""
        a, b = sub(self.start, self.centre), sub(self.end, self.centre)
        r2 = dot(a, a)
        cos_t, sin_t = dot(a, b) / r2, cross(a, b) / r2
        return sin_t / (1 + cos_t)

    def split(self, f):
        mid = self.at(f)
        return Arc(self.centre, self.start, mid, self.sense), Arc(self.centre, mid, self.end,
                                                                  self.sense)


def arc_path(centre, start, end, sense: int) -> list:
    """Arc pieces of at most a quarter turn from ``start`` to ``end`` (same circle)."""
    pieces = []
    cur = start
    b = sub(end, centre)
    for _ in range(4):
        a = sub(cur, centre)
        key = angle_key(a, b) if sense > 0 else angle_key(b, a)
        if key[0] == 0 and dot(a, b).sign() >= 0:      # at most a quarter turn left
            break
        nxt = add(centre, quarter(a, sense))
        pieces.append(Arc(centre, cur, nxt, sense))
        cur = nxt
    if cur != end:
        pieces.append(Arc(centre, cur, end, sense))
    return pieces


def segment_min_dist2_less(a, b, q, d2) -> bool:
    """Does some point of segment ``ab`` lie at squared distance ``< d2`` from ``q``?"""
    ab = sub(b, a)
    aq = sub(q, a)
    t_num = dot(aq, ab)
    den = dot(ab, ab)
    if den.is_zero() or t_num.sign() <= 0:
        return (dist2(a, q) - d2).sign() < 0
    if (t_num - den).sign() >= 0:
        return (dist2(b, q) - d2).sign() < 0
    # perpendicular foot inside: |aq|^2 - (aq.ab)^2/|ab|^2 < d2
    return (dot(aq, aq) * den - t_num * t_num - d2 * den).sign() < 0


def arc_min_dist2_less(arc: Arc, q, d2) -> bool:
    """Does some point of ``arc`` lie at squared distance ``< d2`` from ``q``?"""
    if (dist2(arc.start, q) - d2).sign() < 0 or (dist2(arc.end, q) - d2).sign() < 0:
        return True
    w = sub(q, arc.centre)
    if w[0].is_zero() and w[1].is_zero():
        return False                                  # all points equally far: ends decide
    if not arc.contains_direction(w):
        return False
    # nearest point: radial projection; distance (rho - |w|)^2 < d2  with rho^2 = r2
    r2 = dist2(arc.start, arc.centre)
    w2 = dot(w, w)
    # (rho - |w|)^2 < d2  <=>  r2 + w2 - d2 < 2 rho |w|  (and the lhs may be negative)
    lhs = r2 + w2 - d2
    if lhs.sign() < 0:
        return True
    return (lhs * lhs - 4 * r2 * w2).sign() < 0


def piece_hits(piece, q, d2=4) -> bool:
    d2 = mq(d2)
    if _certainly_far(piece, q, d2):
        return False
    if isinstance(piece, Segment):
        return segment_min_dist2_less(piece.start, piece.end, q, d2)
    return arc_min_dist2_less(piece, q, d2)


def linear_motions_min_dist2_less(a0, a1, b0, b1, d2) -> bool:
    """Two discs move at constant speed over the same time interval [0, 1], from ``a0``
    to ``a1`` and from ``b0`` to ``b1``: is their squared distance ever ``< d2``?
    ``|D0 + t (D1 - D0)|^2`` is a quadratic in t: check the ends and the vertex."""
    d0, d1 = sub(a0, b0), sub(a1, b1)
    return segment_min_dist2_less(d0, d1, (ZERO, ZERO), mq(d2))


def piece_endpoints_max_dist2(piece, c):
    """The largest squared distance from ``c`` over the piece when ``c`` is the arc's
    centre (arcs keep it constant) or for a segment (a convex function: an end point)."""
    a, b = dist2(piece.start, c), dist2(piece.end, c)
    return a if a >= b else b


def fmt_point(p) -> str:
    return f"({p[0].text()}, {p[1].text()})"


# -- the smallest enclosing circle: the one of exactsym.geometry.sec ------------------
def circumcircle(a, b, c):
    """``(centre, radius^2)`` of the circle through three points that are not collinear."""
    centre = circumcentre(a, b, c)
    return centre, dist2(centre, a)


def smallest_enclosing_circle(points) -> tuple:
    """``(centre, radius^2)`` of the SEC of the points (distinct; MQ, tower or K(alpha)
    coordinates): :func:`exactsym.geometry.sec.smallest_enclosing_circle`, the checker's
    own, so that the simulator and the paper layer it calls agree on one implementation;
    a rational centre or radius comes back as an MQ."""
    circle = sec.smallest_enclosing_circle(list(points))
    x, y = circle.centre
    return (motion_number(x), motion_number(y)), motion_number(circle.radius_squared)


# -- two discs moving at once (simultaneous motion, I1 in continuous time) -------------
# A piece traversed over the common time tau in [0, 1] is a rational curve
# (X(tau), Y(tau)) / W(tau) with multiquadratic coefficients: a segment linearly
# (W = 1); an arc by the rational rotation of half-angle tangent k*tau, k the tangent of
# the whole arc's half angle (what ``Arc.at`` does), W = 1 + k^2 tau^2.  Polynomials are
# coefficient lists, lowest degree first (:mod:`~exactsym.exact.algebraic.polynomials`).


def piece_motion(piece):
    """``(X, Y, W)``: the piece as a rational curve of the common time ``tau`` in
    [0, 1] (the point at ``tau`` is ``piece.at(tau)``)."""
    if isinstance(piece, Segment):
        d = sub(piece.end, piece.start)
        return [piece.start[0], d[0]], [piece.start[1], d[1]], [ONE]
    a, b = sub(piece.start, piece.centre), sub(piece.end, piece.centre)
    r2 = dot(a, a)
    cos_t, sin_t = dot(a, b) / r2, cross(a, b) / r2
    k = sin_t / (1 + cos_t)
    k2 = k * k
    c = piece.centre
    w = [ONE, ZERO, k2]
    x = [c[0] + a[0], -(a[1] * k) * 2, (c[0] - a[0]) * k2]
    y = [c[1] + a[1], (a[0] * k) * 2, (c[1] - a[1]) * k2]
    return x, y, w


def joint_gap_polynomial(piece1, piece2, d2=4):
    """``f(tau) = |P1 - P2|^2 W1^2 W2^2 - d2 W1^2 W2^2``: negative exactly at the
    instants where the two moving centres are closer than ``sqrt(d2)``."""
    x1, y1, w1 = piece_motion(piece1)
    x2, y2, w2 = piece_motion(piece2)
    dx = padd(pmul(x1, w2), pscale(pmul(x2, w1), -ONE))
    dy = padd(pmul(y1, w2), pscale(pmul(y2, w1), -ONE))
    ww = pmul(w1, w2)
    return trim(padd(padd(pmul(dx, dx), pmul(dy, dy)), pscale(pmul(ww, ww), -mq(d2))))


def _piece_disc(piece):
    """A disc holding the piece: the one on its chord as diameter (a segment; an arc of
    at most a half turn sees its chord at an angle of at least 90 degrees)."""
    m = ((piece.start[0] + piece.end[0]) / 2, (piece.start[1] + piece.end[1]) / 2)
    return m, dist2(piece.start, piece.end) / 4


def _far_apart(piece1, piece2, d2) -> bool:
    """A filter: the two pieces' discs are certainly more than ``sqrt(d2)`` apart
    (Arb balls; False when they cannot tell, and the exact test runs)."""
    (m1, h1), (m2, h2) = _piece_disc(piece1), _piece_disc(piece2)
    # enclosure: MQ's Arb ball, or a tower number's (a nested radical)
    gap = dist2(m1, m2).enclosure().sqrt() - h1.enclosure().sqrt() - h2.enclosure().sqrt()
    return bool(gap * gap > mq(d2).enclosure()) and bool(gap > 0)


def joint_motion_overlap(piece1, piece2, d2=4):
    """Two discs move at once over the common time [0, 1], along ``piece1`` and
    ``piece2`` (segments or arcs, each at its own speed): a rational instant at which
    their centres are closer than ``sqrt(d2)``, or None if there is none.  Exact."""
    if _far_apart(piece1, piece2, d2):
        return None
    if isinstance(piece1, Segment) and isinstance(piece2, Segment):
        d0, d1 = sub(piece1.start, piece2.start), sub(piece1.end, piece2.end)
        if not segment_min_dist2_less(d0, d1, (ZERO, ZERO), mq(d2)):
            return None
    return negative_instant(joint_gap_polynomial(piece1, piece2, d2))


# -- certified float filters over all robots at once (NumPy) ---------------------------
# A coordinate c_1 sqrt(m_1) + ... + c_k sqrt(m_k) evaluated in doubles is within
# (k + 6) 2^-52 S of its value, S the sum of the terms' magnitudes (the bound of
# ``multiquadratic._float_sign``).  The filters below only ever say "certainly not":
# their slack is that bound doubled plus 10^-12 of every magnitude involved (each
# further double operation errs by 2^-53 relatively, a few of them per test); NaN or
# infinity (overflow) compares False and sends the pair to the exact test.

def approx_points(pts):
    """``(X, Y, E)``: NumPy arrays of the centres' doubles and a bound on the error of
    each coordinate."""
    xs, ys, es = [], [], []
    for p in pts:
        try:
            (x, ex), (y, ey) = float_and_error(p[0]), float_and_error(p[1])
        except OverflowError:
            x = y = ex = ey = float("nan")
        xs.append(x)
        ys.append(y)
        es.append(max(ex, ey))
    return np.array(xs), np.array(ys), np.array(es)


def maybe_touching_pairs(pts, unit) -> list:
    """A superset of the pairs ``(i, j)``, ``i < j``, of centres exactly ``2 unit``
    apart: the pairs the doubles cannot separate from ``4 unit^2``."""
    X, Y, E = approx_points(pts)
    four = 4.0 * float(unit) ** 2
    dx, dy = X[:, None] - X[None, :], Y[:, None] - Y[None, :]
    d2 = dx * dx + dy * dy
    err = E[:, None] + E[None, :]
    err = err + 1e-15 * (np.abs(dx) + np.abs(dy))
    slack = 2 * (2 * err * (np.abs(dx) + np.abs(dy)) + 2 * err * err) + \
        1e-12 * (d2 + four) + 1e-300
    maybe = ~(np.abs(d2 - four) > slack)
    return [(int(i), int(j)) for i, j in zip(*np.nonzero(np.triu(maybe, 1)))]


def touching_pairs(pts, unit) -> list:
    """The pairs ``(i, j)``, ``i < j``, of centres exactly ``2 unit`` apart: the
    doubles' candidates (:func:`maybe_touching_pairs`), decided exactly."""
    four = 4 * unit * unit
    return [(i, j) for i, j in maybe_touching_pairs(pts, unit)
            if dist2(pts[i], pts[j]) == four]


def farthest_candidates(approx, centre, among) -> list:
    """The robots of ``among`` that may be the farthest from ``centre`` (a point): every
    robot left out is certainly nearer than one kept (the doubles' error bounds)."""
    X, Y, E = approx
    idx = np.array(list(among), dtype=int)
    if len(idx) == 0:
        return []
    try:
        (cx, ex), (cy, ey) = float_and_error(centre[0]), float_and_error(centre[1])
    except OverflowError:
        return list(among)
    d = np.hypot(X[idx] - cx, Y[idx] - cy)
    slack = 2 * (2 * E[idx] + ex + ey) + 1e-12 * (d + abs(cx) + abs(cy) + np.abs(X[idx]) +
                                                  np.abs(Y[idx])) + 1e-300
    lower, upper = d - slack, d + slack
    best = np.max(lower)
    keep = ~(upper < best)          # NaN: kept
    return [int(k) for k in idx[keep]]


def robots_near_piece(piece, approx, d) -> list:
    """Indices of the robots that may come within ``d`` (a float) of ``piece``: every
    robot left out is certainly farther than ``d`` from every point of it, by the lower
    bound of :func:`_piece_lower_bound` computed for all robots at once."""
    X, Y, E = approx
    try:
        geo = _piece_frame(piece)
    except OverflowError:
        return list(range(len(X)))
    far = _piece_lower_bound(geo, X, Y, E, np) > d
    return [int(k) for k in np.nonzero(~far)[0]]


def _piece_frame(piece):
    """Doubles describing a piece for the filters, with the error bound ``sigma`` of
    its points' coordinates: ``(kind, mx, my, h, ux, uy, cx, cy, r, sigma)``.

    A segment's direction ``u`` is kept only when the chord is long beside the errors:
    ``h > 4 sigma + 2^-40 (|mx| + |my| + h)``.  Then the double chord ``w`` differs from
    the exact ``e`` by at most ``sigma`` plus its roundings (``2^-52`` of each
    magnitude), less than ``|e| / 4``, so ``|w/|w| - e/|e|| <= 2 |w - e| / |e| <=
    2 sigma / h`` up to those roundings, which the ``turn`` slack of
    :func:`_piece_lower_bound` (``4 dist sigma / h``) and its ``1e-9`` relative term
    cover.  Otherwise ``u = 0`` and only the disc on the chord bounds the distance.
    Either way the result is a valid lower bound: the choice decides nothing, it only
    makes the bound tighter (the fixed ``h > 1e-6`` it replaces ignored ``sigma``)."""
    (sx, es), (sy, fs) = float_and_error(piece.start[0]), float_and_error(piece.start[1])
    (tx, et), (ty, ft) = float_and_error(piece.end[0]), float_and_error(piece.end[1])
    sigma = es + fs + et + ft
    mx, my = (sx + tx) / 2, (sy + ty) / 2
    h = ((sx - tx) ** 2 + (sy - ty) ** 2) ** 0.5 / 2
    if isinstance(piece, Segment):
        long_chord = h > 4 * sigma + 2.0 ** -40 * (abs(mx) + abs(my) + h)
        ux, uy = ((tx - sx) / (2 * h), (ty - sy) / (2 * h)) if long_chord else (0.0, 0.0)
        return ("segment", mx, my, h, ux, uy, 0.0, 0.0, 0.0, sigma)
    (cx, ec), (cy, fc) = float_and_error(piece.centre[0]), float_and_error(piece.centre[1])
    r = ((sx - cx) ** 2 + (sy - cy) ** 2) ** 0.5
    return ("arc", mx, my, h, 0.0, 0.0, cx, cy, r, sigma + ec + fc)


def _piece_lower_bound(geo, qx, qy, eq, lib):
    """A lower bound on the distance from the point(s) ``(qx, qy)`` (coordinate error
    ``eq``) to the piece: the largest of the distance to the disc on the chord as
    diameter (the piece lies in it), for a segment the distance to it through its
    direction (exact for an exact direction), for an arc the distance to its circle;
    minus a slack covering the errors of every double involved (twice the coordinate
    bounds, 10^-9 of every magnitude: the direction's normalisation and a few
    roundings err far less).  ``lib``: :mod:`math` or NumPy."""
    kind, mx, my, h, ux, uy, cx, cy, r, sigma = geo
    dx, dy = qx - mx, qy - my
    dist = lib.hypot(dx, dy)
    disc = dist - h
    turn = 0.0
    if kind == "segment":
        if ux == 0.0 and uy == 0.0:
            best = disc
        else:
            along = abs(dx * ux + dy * uy) - h
            perp = dx * uy - dy * ux
            pos = (along + abs(along)) / 2                  # max(along, 0), NumPy or not
            best = lib.hypot(pos, perp)
            turn = 4 * dist * sigma / h        # the direction's error, from its ends'
        scale = abs(mx) + abs(my) + h
    else:
        ring = abs(lib.hypot(qx - cx, qy - cy) - r)
        best = (ring + disc + abs(ring - disc)) / 2         # max(ring, disc)
        scale = abs(cx) + abs(cy) + r + abs(mx) + abs(my) + h
    slack = 4 * (eq + sigma) + turn + 1e-9 * (scale + abs(qx) + abs(qy) + 1.0)
    return best - slack


def _certainly_far(piece, q, d2) -> bool:
    """A filter for :func:`piece_hits`: ``q`` is certainly farther than ``sqrt(d2)``
    from every point of the piece (:func:`_piece_lower_bound` in doubles); False when
    the doubles cannot tell (or overflow)."""
    try:
        geo = _piece_frame(piece)
        (qx, eq), (qy, gq) = float_and_error(q[0]), float_and_error(q[1])
        r2, er = float_and_error(d2)
    except OverflowError:
        return False
    r = max(r2 + er, 0.0) ** 0.5 * (1 + 1e-12)
    return _piece_lower_bound(geo, qx, qy, eq + gq, math) > r


def maybe_on_layers(approx, centre, unit) -> list:
    """Indices of the robots that may lie exactly at C or at a distance ``2 L unit`` from
    ``centre`` for an integer L >= 1 (every robot left out certainly does not): the
    robots a pattern about ``centre`` can contain."""
    X, Y, E = approx
    try:
        (cx, ex), (cy, ey) = float_and_error(centre[0]), float_and_error(centre[1])
    except OverflowError:
        return list(range(len(X)))
    two = 2.0 * float(unit)
    d = np.hypot(X - cx, Y - cy)
    slack = 2 * (2 * E + ex + ey) + 1e-12 * (d + abs(cx) + abs(cy) + np.abs(X) + np.abs(Y))
    level = d / two
    off = np.abs(level - np.round(level)) * two
    keep = ~(off > slack + 1e-300)
    return [int(k) for k in np.nonzero(keep)[0]]
