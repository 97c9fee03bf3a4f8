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

import random
from dataclasses import dataclass

from .exact import sign
from .geometry import Point, Turn, circumcentre, midpoint, orientation, squared_distance

_SEED = 20100707


@dataclass(frozen=True)
class Circle:
    centre: Point
    radius_squared: object
    support: tuple[int, ...]     # indices of the points on the circle that determine it

    def contains(self, p: Point) -> bool:
        return squared_distance(self.centre, p) <= self.radius_squared


def _circle(points, support: tuple[int, ...]) -> Circle:
    if len(support) == 1:
        p = points[support[0]]
        return Circle(p, p[0] * 0, support)
    if len(support) == 2:
        a, b = (points[i] for i in support)
        c = midpoint(a, b)
        return Circle(c, squared_distance(c, a), support)
    a, b, c = (points[i] for i in support)
    centre = circumcentre(a, b, c)
    return Circle(centre, squared_distance(centre, a), support)


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

    def circle_of(support):
        if len(support) == 1:
            i, = support
            return (fx[i], fy[i], 0.0, support)
        if len(support) == 2:
            i, j = support
            cx, cy = (fx[i] + fx[j]) / 2, (fy[i] + fy[j]) / 2
            return (cx, cy, (fx[i] - cx) ** 2 + (fy[i] - cy) ** 2, support)
        i, j, k = support
        bx, by, qx, qy = fx[j] - fx[i], fy[j] - fy[i], fx[k] - fx[i], fy[k] - fy[i]
        d = 2 * (bx * qy - by * qx)
        if d == 0:
            return (fx[i], fy[i], float("inf"), support)
        b2, q2 = bx * bx + by * by, qx * qx + qy * qy
        cx, cy = fx[i] + (qy * b2 - by * q2) / d, fy[i] + (bx * q2 - qx * b2) / d
        return (cx, cy, (fx[i] - cx) ** 2 + (fy[i] - cy) ** 2, support)

    def contains(circle, i):
        cx, cy, r2, _ = circle
        return (fx[i] - cx) ** 2 + (fy[i] - cy) ** 2 <= r2 * (1 + 1e-12) + 1e-300

    return _welzl(points, order, contains, circle_of)[3]


def sec_is_minimal(points, circle: Circle) -> bool:
    """A circle through its support is the SEC of points it contains iff the support
    is a diameter pair, or a triangle with the centre inside or on it (non-obtuse)."""
    s = circle.support
    if len(s) == 1:
        return True
    if len(s) == 2:
        return True
    a, b, c = (points[i] for i in s)
    o = circle.centre
    turns = {orientation(a, b, o), orientation(b, c, o), orientation(c, a, o)}
    return not (Turn.LEFT in turns and Turn.RIGHT in turns)


def _exact_contains_all(points, circle: Circle, fx, fy) -> bool:
    """Every point inside or on ``circle``.  A float test with a proven error bound
    (relative 2^-40, far above the few ulps it can be off, plus an absolute term for
    underflow) clears the points well inside; the rest are decided exactly.  A point
    the filter sees well outside makes the caller fall back to exact Welzl."""
    cx, cy = circle.centre
    r2 = circle.radius_squared
    fcx, fcy, fr2 = float(cx), float(cy), float(r2)
    for p, px, py in zip(points, fx, fy):
        d2 = (px - fcx) ** 2 + (py - fcy) ** 2
        slack = ((abs(px) + abs(fcx)) ** 2 + (abs(py) + abs(fcy)) ** 2 + abs(fr2)) * 2.0 ** -40 + 1e-290
        if d2 + slack < fr2:
            continue
        if d2 - slack > fr2:
            return False
        dx, dy = p[0] - cx, p[1] - cy
        if sign(dx * dx + dy * dy - r2) > 0:
            return False
    return True


def smallest_enclosing_circle(points: list[Point]) -> Circle:
    """The SEC of a non-empty list of distinct exact points."""
    n = len(points)
    if n == 1:
        return _circle(points, (0,))
    order = list(range(n))
    random.Random(_SEED).shuffle(order)
    try:
        # float filter only: the proposed support is verified exactly below
        fx = [float(p[0]) for p in points]
        fy = [float(p[1]) for p in points]
        guess = _circle(points, _float_support(points, order, fx, fy))
        if sec_is_minimal(points, guess) and _exact_contains_all(points, guess, fx, fy):
            return _canonical(points, guess)
    except (ValueError, OverflowError, ZeroDivisionError):
        pass
    exact = _welzl(points, order,
                   lambda circle, i: circle.contains(points[i]),
                   lambda support: _circle(points, support))
    return _canonical(points, exact)


def _canonical(points, circle: Circle) -> Circle:
    """Report the support sorted by index (the circle itself is unique)."""
    return Circle(circle.centre, circle.radius_squared, tuple(sorted(circle.support)))


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
