"""The smallest enclosing circle (SEC), exactly.

Welzl's algorithm in its iterative move-to-front form (expected linear time on a
randomly permuted input; the permutation is seeded, and the SEC is unique, so
the result does not depend on it).  A float run first proposes the support
points; the exact circle through them is then verified against every point
(float filter with a proven error bound, exact test when the filter cannot
decide) and accepted only if it is also minimal (``sec_is_minimal``).  When the
proposal fails, the exact algorithm runs from scratch.  Floats never decide.
"""

from __future__ import annotations

import math
import random
from collections.abc import Sequence

import numpy as np
from flint import arb, ctx

from ..exact import fmpq, sign
from ..exact.number import (all_plain_rational, costly_inverse, enclosure, is_plain_rational,
                            reduced, shares_inverse)
from .predicates import (Point, Turn, circumcentre_homogeneous, midpoint,
                       orientation_homogeneous, squared_distance)

_SEED = 20100707


def _reduced(v):
    """A coordinate of the centre as the rational it is when it is one in the sparse
    Q(zeta_N) (:meth:`~.exact.sparse_cyclotomic.SparseCyclotomic.reduced`): the centre
    (1/3, 1/5) of a C7 set translated by it was held as quotients of 28 and 4 cosines, and
    every direction p - C, gap and line of the 98 robots multiplied them (7.5 s of a
    check)."""
    return reduced(v)


class Circle:
    """A circle with its centre kept homogeneous: ``homogeneous = (X, Y, D)``, ``D > 0``, the
    centre being ``(X/D, Y/D)``.  Predicates use the homogeneous form, so no field inverse is
    computed (issue 9: a circumcentre in Q(sqrt 2, ..., sqrt 23) made every later number
    dense); ``centre`` and ``radius_squared`` divide once, on first use.  ``support``: indices
    of the points on the circle that determine it."""

    __slots__ = ("homogeneous", "support", "_through", "_centre", "_radius_squared")

    def __init__(self, centre: Point, radius_squared, support: tuple[int, ...],
                 homogeneous: tuple | None = None, through: Point | None = None):
        self.support = support
        if homogeneous is None:
            one = centre[0] * 0 + 1
            homogeneous = (centre[0], centre[1], one)
        self.homogeneous = homogeneous
        self._through = through             # a point on the circle (when radius is lazy)
        self._centre = centre
        self._radius_squared = radius_squared

    @property
    def centre(self) -> Point:
        if self._centre is None:
            x, y, d = self.homogeneous
            if shares_inverse(d) and not d.is_rational():
                # one field inverse, not two; over a sparse base both coordinates then
                # share its denominator (sums of the directions p - C do not
                # cross-multiply two equal ones)
                inverse = 1 / d
                self._centre = (x * inverse, y * inverse)
            else:
                self._centre = (_reduced(x / d), _reduced(y / d))
        return self._centre

    @property
    def radius_squared(self):
        if self._radius_squared is None:
            self._radius_squared = squared_distance(self.centre, self._through)
        return self._radius_squared

    def scaled_power(self, p: Point):
        """``D^2 (|p - centre|^2 - radius^2)``: its sign says outside (+), on (0), inside (-)."""
        x, y, d = self.homogeneous
        dx, dy = d * p[0] - x, d * p[1] - y
        if self._through is not None and self._radius_squared is None:
            tx, ty = d * self._through[0] - x, d * self._through[1] - y
            return dx * dx + dy * dy - (tx * tx + ty * ty)
        return dx * dx + dy * dy - d * d * self.radius_squared

    def scaled_radius_squared(self):
        """``D^2 radius^2``, without a division (from the point on the circle when the
        radius is lazy)."""
        x, y, d = self.homogeneous
        if self._through is not None and self._radius_squared is None:
            tx, ty = d * self._through[0] - x, d * self._through[1] - y
            return tx * tx + ty * ty
        return d * d * self.radius_squared

    def same_circle(self, other: "Circle", coerce=None) -> bool:
        """Whether the two circles have the same centre and radius, by cross-multiplying
        their homogeneous forms (no field inverse: in Q(zeta_3988) one cost seconds);
        ``coerce`` writes this circle's numbers in the other's number system first."""
        c = coerce or (lambda v: v)
        x, y, d = (c(v) for v in self.homogeneous)
        ox, oy, od = other.homogeneous
        same = x * od == ox * d and y * od == oy * d and \
            c(self.scaled_radius_squared()) * (od * od) == other.scaled_radius_squared() * (d * d)
        if same and self._centre is not None and other._centre is None:
            # the same exact numbers: the other circle need not divide again (MakeAsym's
            # moved configurations keep the SEC; one division in Q(zeta_3988) cost 2-5 s)
            other._centre = (c(self._centre[0]), c(self._centre[1]))
        return same

    def contains(self, p: Point) -> bool:
        return sign(self.scaled_power(p)) <= 0

    def __eq__(self, other):
        return isinstance(other, Circle) and self.support == other.support and \
            self.centre == other.centre and self.radius_squared == other.radius_squared

    __hash__ = None

    def __repr__(self):
        return f"Circle(homogeneous={self.homogeneous!r}, support={self.support!r})"


class LazyCentre(Sequence):
    """The centre ``(x, y)`` of a :class:`Circle`, read as a pair; the exact division
    ``(X/D, Y/D)`` is made when a coordinate is first read (issue 9: in a
    multiquadratic field of degree 512 it cost 0.1 s, more than the rest of the truth)."""

    __slots__ = ("circle",)

    def __init__(self, circle: Circle):
        self.circle = circle

    def __len__(self) -> int:
        return 2

    def __getitem__(self, k):
        return self.circle.centre[k]

    def __iter__(self):
        return iter(self.circle.centre)

    def __eq__(self, other):
        if isinstance(other, LazyCentre):
            other = other.circle.centre
        return tuple(self.circle.centre) == other

    def __hash__(self):
        return hash(tuple(self.circle.centre))

    def __repr__(self) -> str:
        return repr(tuple(self.circle.centre))

    def __reduce__(self):
        return (tuple, (tuple(self.circle.centre),))


def _circle(points, support: tuple[int, ...]) -> Circle:
    if len(support) == 1:
        p = points[support[0]]
        return Circle(p, p[0] * 0, support)
    if len(support) == 2:
        a, b = (points[i] for i in support)
        c = midpoint(a, b)
        if all_plain_rational(c):
            return Circle(c, squared_distance(c, a), support)
        return Circle(c, None, support, through=a)      # radius computed when read
    a, b, c = (points[i] for i in support)
    x, y, d = circumcentre_homogeneous(a, b, c)
    if is_plain_rational(d):                 # rationals: dividing is cheap, do it now
        centre = (x / d, y / d)
        return Circle(centre, squared_distance(centre, a), support)
    return Circle(None, None, support, (x, y, d), a)


def _welzl(points, order, contains, circle_of):
    """Iterative move-to-front Welzl on ``order``; ``contains(circle, i)`` and
    ``circle_of(support)`` decide and construct (exactly or in floats)."""
    circle = circle_of((order[0],))
    for a in range(1, len(order)):
        i = order[a]
        if contains(circle, i):
            continue
        circle = circle_of((i,))
        for b in range(a):
            j = order[b]
            if contains(circle, j):
                continue
            circle = circle_of((i, j))
            for c in range(b):
                k = order[c]
                if not contains(circle, k):
                    circle = circle_of((i, j, k))
    return circle


def _float_support(points, order, fx, fy) -> tuple[int, ...]:
    """The support of the SEC of the float points, by the same move-to-front Welzl as
    :func:`_welzl` (same order, same circles), with each "first point outside the current
    circle" found by a NumPy scan over growing chunks instead of one test per point.  It
    only proposes: the caller verifies the circle exactly."""
    xs = np.asarray(fx, dtype=float)[order]
    ys = np.asarray(fy, dtype=float)[order]

    def circle_of(i, j=None, k=None):
        if j is None:
            return (xs[i], ys[i], 0.0, (i,))
        if k is None:
            cx, cy = (xs[i] + xs[j]) / 2, (ys[i] + ys[j]) / 2
            return (cx, cy, (xs[i] - cx) ** 2 + (ys[i] - cy) ** 2, (i, j))
        bx, by, qx, qy = xs[j] - xs[i], ys[j] - ys[i], xs[k] - xs[i], ys[k] - ys[i]
        d = 2 * (bx * qy - by * qx)
        if d == 0:
            return (xs[i], ys[i], float("inf"), (i, j, k))   # a proposal only: verified exactly
        b2, q2 = bx * bx + by * by, qx * qx + qy * qy
        cx, cy = xs[i] + (qy * b2 - by * q2) / d, ys[i] + (bx * q2 - qx * b2) / d
        return (cx, cy, (xs[i] - cx) ** 2 + (ys[i] - cy) ** 2, (i, j, k))

    def next_outside(circle, start, stop):
        """The first position in [start, stop) whose point is outside ``circle``, or stop."""
        cx, cy, r2, _ = circle
        bound = r2 * (1 + 1e-12) + 1e-300
        chunk = 64
        while start < stop:
            end = min(stop, start + chunk)
            out = (xs[start:end] - cx) ** 2 + (ys[start:end] - cy) ** 2 > bound
            hit = int(out.argmax())
            if out[hit]:
                return start + hit
            start, chunk = end, chunk * 4
        return stop

    n = len(order)
    with np.errstate(all="ignore"):
        circle = circle_of(0)
        a = next_outside(circle, 1, n)
        while a < n:
            circle = circle_of(a)
            b = next_outside(circle, 0, a)
            while b < a:
                circle = circle_of(a, b)
                c = next_outside(circle, 0, b)
                while c < b:
                    circle = circle_of(a, b, c)
                    c = next_outside(circle, c + 1, b)
                b = next_outside(circle, b + 1, a)
            a = next_outside(circle, a + 1, n)
    return tuple(order[p] for p in circle[3])


def sec_is_minimal(points, circle: Circle) -> bool:
    """A circle through its support is the SEC of points it contains iff the support
    is a diameter pair, or a triangle with the centre inside or on it (non-obtuse)."""
    s = circle.support
    if len(s) == 1:
        return True
    if len(s) == 2:
        return True
    a, b, c = (points[i] for i in s)
    o = circle.homogeneous
    turns = {orientation_homogeneous(a, b, o), orientation_homogeneous(b, c, o),
             orientation_homogeneous(c, a, o)}
    return not (Turn.LEFT in turns and Turn.RIGHT in turns)


def _exact_contains_all(points, circle: Circle, fx, fy, errors=None) -> bool:
    """Every point inside or on ``circle``.  A float test with a proven error bound clears
    the points well inside: the centre and squared radius are Arb balls (so a centre kept
    as X/D is enclosed without dividing exactly), each float coordinate is within a
    relative 2^-50 of its exact value (fmpq: correctly rounded; algebraic: the midpoint of
    a 53-bit ball, whose radius is added), and the comparison keeps a relative 2^-40 slack
    plus the balls' radii (``errors[i]``, when given, bounds the error of both floats of
    point i, and replaces the relative bound).  The rest are decided exactly,
    division-free, but for the support points, which are on the circle by construction.
    A point the filter sees well outside makes the caller fall back to exact Welzl."""
    x, y, d = circle.homogeneous
    if is_plain_rational(d) and d == 1 and circle._radius_squared is not None \
            and is_plain_rational(x) and is_plain_rational(y):
        # rational centre: float() of an fmpq is correctly rounded, no ball needed
        return _float_filtered(points, circle, fx, fy, float(x), float(y),
                               float(circle._radius_squared), 0.0, 0.0, errors)
    with ctx.workprec(64):
        bd = _ball(d)
        bx, by = _ball(x) / bd, _ball(y) / bd
        if circle._radius_squared is not None:
            br2 = _ball(circle._radius_squared)
        else:
            t = circle._through
            br2 = (_ball(t[0]) - bx) ** 2 + (_ball(t[1]) - by) ** 2
    fcx, fcy, fr2 = float(bx.mid()), float(by.mid()), float(br2.mid())
    # the radii rounded up: float() of a radius rounds to nearest, possibly down
    rad = (float(bx.rad()) + float(by.rad())) * (1 + 2.0 ** -50)
    rad2 = float(br2.rad()) * (1 + 2.0 ** -50)
    return _float_filtered(points, circle, fx, fy, fcx, fcy, fr2, rad, rad2, errors)


def _float_filtered(points, circle, fx, fy, fcx, fcy, fr2, rad, rad2, errors=None) -> bool:
    """The test of :func:`_exact_contains_all` with the centre and radius as floats within
    ``rad`` and ``rad2`` of their exact values, vectorised over all points: the points the
    slack cannot settle (and any overflow, which makes the bound NaN or infinite) are
    decided exactly."""
    if not all(math.isfinite(v) for v in (fcx, fcy, fr2, rad, rad2)):
        raise OverflowError("not representable as floats")
    px, py = np.asarray(fx, dtype=float), np.asarray(fy, dtype=float)
    with np.errstate(all="ignore"):
        ex, ey = px - fcx, py - fcy
        d2 = ex * ex + ey * ey
        spread = np.abs(ex) + np.abs(ey)
        ax, ay = np.abs(px) + abs(fcx), np.abs(py) + abs(fcy)
        slack = (ax * ax + ay * ay + abs(fr2)) * 2.0 ** -40 + 1e-290 \
            + 4 * (spread + rad) * rad + rad2
        if errors is not None:
            # |(e + t)^2 - e^2| <= 2 |e| t + t^2 per coordinate, t the float's error
            err = np.asarray(errors, dtype=float)
            slack += (2 * spread * err + 2 * err * err) * 1.01
        elif not is_plain_rational(points[0][0]):    # given floats of algebraic points
            slack += 4 * (np.abs(px) + np.abs(py)) * 2.0 ** -40 * (spread + 1)
        if np.any(d2 - slack > fr2):
            return False
        unsure = np.flatnonzero(~(d2 + slack < fr2))
    on_circle = set(circle.support)         # through the support by construction
    return all(sign(circle.scaled_power(points[i])) <= 0 for i in unsure.tolist()
               if i not in on_circle)


def _ball(v):
    return v.enclosure(64) if hasattr(v, "enclosure") else arb(v)


def point_floats(points) -> tuple[list, list, list | None]:
    """``(fx, fy, errors)``: floats of the coordinates and, unless every coordinate is
    rational (then ``float`` is correctly rounded and ``errors`` is None), a bound
    ``errors[i]`` on the error of both floats of point i, from 64-bit Arb balls
    (``float`` of an algebraic number is only an approximation)."""
    if all_plain_rational(c for p in points for c in p):
        return [float(p[0]) for p in points], [float(p[1]) for p in points], None
    return floats_of_balls(*(list(b) for b in zip(*[(_ball(p[0]), _ball(p[1]))
                                                      for p in points])))


def floats_of_balls(xs, ys) -> tuple[list, list, list]:
    """``(fx, fy, errors)`` of :func:`point_floats` from balls of the coordinates."""
    fx, fy, errors = [], [], []
    for bx, by in zip(xs, ys):
        x, y = float(bx.mid()), float(by.mid())
        r = max(float(bx.rad()), float(by.rad()))
        fx.append(x)
        fy.append(y)
        errors.append(math.nextafter(r, math.inf) + (abs(x) + abs(y)) * 2.0 ** -52)
    return fx, fy, errors


def smallest_enclosing_circle(points: list[Point], floats=None, errors=None) -> Circle:
    """The SEC of a non-empty list of distinct exact points.  ``floats``: the points'
    correctly rounded float coordinates (``geometry.float_coordinates``), if known, or
    with ``errors`` (:func:`point_floats`) approximations within ``errors[i]``."""
    n = len(points)
    if n == 1:
        return _circle(points, (0,))
    order = list(range(n))
    random.Random(_SEED).shuffle(order)
    try:
        # float filter only: the proposed support is verified exactly below
        if floats is not None:
            fx, fy = floats
        else:
            fx, fy, errors = point_floats(points)
        guess = _circle(points, _float_support(points, order, fx, fy))
        if sec_is_minimal(points, guess) and _exact_contains_all(points, guess, fx, fy,
                                                                  errors):
            return _canonical(points, guess)
    except (ValueError, OverflowError, ZeroDivisionError):
        pass
    exact = _welzl(points, order,
                   lambda circle, i: circle.contains(points[i]),
                   lambda support: _circle(points, support))
    return _canonical(points, exact)


def _canonical(points, circle: Circle) -> Circle:
    """Report the support sorted by index (the circle itself is unique), and a rational
    centre as rational (:func:`_rational_centre`)."""
    support = tuple(sorted(circle.support))
    centre = _rational_centre(circle.homogeneous)
    if centre is not None:
        return Circle(centre, circle._radius_squared, support,
                      through=circle._through or points[support[0]])
    return Circle(circle._centre, circle._radius_squared, support, circle.homogeneous,
                  circle._through)


def _rational_centre(homogeneous):
    """``(X/D, Y/D)`` when both are rational, else None: a rational guessed from Arb balls
    of the quotients, then proved by D q - X == 0 exactly (a scalar product).  With three
    support points D is a determinant; in a tower over the sparse Q(zeta_N), or in the
    sparse field with square roots as Gauss sums, every |D p - (X, Y)|^2 of the levels and
    every direction D p - (X, Y) of the polygons carried its terms (100 robots with radii
    sqrt(1+sqrt(2)), ... about (0, 1/7): check 8 s, 1.4 s with p - C; certify of the same
    with radii sqrt(5), sqrt(7), ...: 6.8 s, 1 s)."""
    from fractions import Fraction
    x, y, d = homogeneous
    if not costly_inverse(d):
        return None
    with ctx.workprec(128):
        bd = d.enclosure(128)
        out = []
        for v in (x, y):
            b = enclosure(v, 128) / bd
            if not b.is_finite() or b.rad() > 2.0 ** -80:
                return None
            man, exp = b.mid().man_exp()
            guess = (Fraction(int(man)) * Fraction(2) ** int(exp)).limit_denominator(1 << 24)
            q = fmpq(guess.numerator, guess.denominator)
            if not b.contains(arb(guess.numerator) / guess.denominator) or \
                    sign(d * q - v) != 0:
                return None
            out.append(q)
    return tuple(out)


def sec_by_brute_force(points: list[Point]) -> Circle:
    """O(n^4) reference: the smallest circle over all pairs and triples that contains all points."""
    from itertools import combinations
    best = None
    if len(points) == 1:
        return _circle(points, (0,))
    for size in (2, 3):
        for support in combinations(range(len(points)), size):
            try:
                circle = _circle(points, support)
            except ValueError:
                continue
            if all(circle.contains(p) for p in points):
                if best is None or circle.radius_squared < best.radius_squared:
                    best = circle
    return best
