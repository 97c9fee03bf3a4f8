"""Levels and rays of configurations with irrational coordinates, by certified Arb balls.

The ground truth (:mod:`exactsym.geometry.levels`, :mod:`exactsym.truth.symmetry`) needs, about the SEC
centre C = (X/D, Y/D), the classes of equal distance, the counter-clockwise order of
directions, the rays and the angles between consecutive rays.  For points in a number
field each of these exact predicates costs field products (0.4 ms each in a cyclotomic
field of degree 960, issue 9).  Here every point gets Arb balls, at :data:`PREC` bits, of
``p - C``, of its squared distance from C and of its angle in [0, 2 pi); a predicate is
decided by the balls when they exclude the tie (two disjoint balls are two different
numbers, in the order of the balls), and only otherwise by exact arithmetic, on that
pair alone (the exact vectors ``D p - (X, Y)``, ``D > 0``, need no division).  Balls never
decide a tie: equal distances and equal angles are always confirmed exactly.

An asymmetric configuration is then certified C1 without exact arithmetic: the string of
ray symbols is read with *provisional* symbols (equal when the balls cannot tell them
apart, so coarser than the exact ones); a rotation or reflection that fails on the
provisional string fails on the exact one.  The canonical labelling, the least of the 2m
readings of the string, is found by eliminating readings symbol by symbol; two symbols
whose balls overlap are compared exactly.  When the provisional string admits a
symmetry, :func:`certified_c1` returns None and the exact algorithm runs.
"""

from __future__ import annotations

import math
from functools import cmp_to_key

from flint import arb, ctx, fmpq

from ..exact import exact_sorted, sign as _sign
from ..exact.balls import expression_ball
from ..exact.fused import product_sum
from ..exact.context import Cache
from .predicates import PseudoAngle
from .strings import cyclic_occurrences, cyclic_period

#: working precision of the balls (bits): ties closer than about 2^-120 go to exact
PREC = 128


def _ball(v):
    return v.enclosure(PREC) if hasattr(v, "enclosure") else arb(v)


def _bounds(b: arb) -> tuple[float, float]:
    """Floats ``lo <= b <= hi`` (outward rounded; infinite when unknown)."""
    if not b.is_finite():
        return -math.inf, math.inf
    lo = math.nextafter(float(b.lower()), -math.inf)
    hi = math.nextafter(float(b.upper()), math.inf)
    if math.isnan(lo) or math.isnan(hi):
        return -math.inf, math.inf
    return lo, hi


def interval_groups(lo: list, hi: list, order: list) -> list[list[int]]:
    """Split ``order`` (indices sorted by their midpoints) into consecutive groups such
    that every value of a group is certainly less than every value of any later group
    (value i lies in ``[lo[i], hi[i]]``)."""
    n = len(order)
    suffix_lo = [0.0] * n
    low = math.inf
    for p in range(n - 1, -1, -1):
        low = min(low, lo[order[p]])
        suffix_lo[p] = low
    groups, current, high = [], [], -math.inf
    for p, i in enumerate(order):
        if current and high < suffix_lo[p]:
            groups.append(current)
            current = []
        current.append(i)
        high = max(high, hi[i])
    if current:
        groups.append(current)
    return groups


_BALLS = Cache("coordinate balls")     # id(points) -> (points, xs, ys): the last few point tuples' balls


def coordinate_balls(points, polar=None, specs=None) -> tuple[list, list]:
    """Arb balls of the coordinates of ``points`` (a tuple, kept alive by the cache entry,
    so its id is not reused while cached); computed once per point tuple (the duplicate
    check of ``load`` and the levels share them).  ``polar``: ``(radii, turns)`` of the
    same points, when given in polar form: ``r cos(2 pi t)``, ``r sin(2 pi t)`` are then
    enclosed directly (a cosine in a cyclotomic field of degree 5,760 is a polynomial of
    that degree to evaluate).  ``specs``: the expressions the points were evaluated
    from (``Configuration.specs``), enclosed by :func:`exactsym.exact.balls.expression_ball` (0.4 ms less per
    coordinate in degree 960); a coordinate whose ball is not finite is enclosed from
    its exact value."""
    known = _BALLS.table()
    hit = known.get(id(points))
    if hit is not None and hit[0] is points:
        return hit[1], hit[2]
    xs = ys = None
    with ctx.workprec(PREC):
        if polar is not None:
            radii = [_ball(r) for r in polar[0]]
            xs = [r * arb.cos_pi_fmpq(2 * t) for r, t in zip(radii, polar[1])]
            ys = [r * arb.sin_pi_fmpq(2 * t) for r, t in zip(radii, polar[1])]
        elif specs is not None and len(specs) == len(points):
            try:
                xs, ys = [], []
                for spec in specs:
                    if spec.is_polar:
                        r, t = expression_ball(spec.r), fmpq(spec.turn.numerator,
                                                            spec.turn.denominator)
                        xs.append(r * arb.cos_pi_fmpq(2 * t))
                        ys.append(r * arb.sin_pi_fmpq(2 * t))
                    else:
                        xs.append(expression_ball(spec.x))
                        ys.append(expression_ball(spec.y))
            except (RecursionError, TypeError, ValueError, ZeroDivisionError):
                xs = ys = None
            if xs is not None:
                for i, p in enumerate(points):
                    if not xs[i].is_finite():
                        xs[i] = _ball(p[0])
                    if not ys[i].is_finite():
                        ys[i] = _ball(p[1])
        if xs is None:
            xs = [_ball(p[0]) for p in points]
            ys = [_ball(p[1]) for p in points]
    if len(known) >= 4:
        known.clear()
    known[id(points)] = (points, xs, ys)
    return xs, ys


def overlapping_pairs(xs: list, ys: list) -> list[tuple[int, int]]:
    """The pairs ``(j, i)``, ``j < i``, that the balls cannot separate: every pair of equal
    points is among them.  Points are split into certainly ordered groups by x
    (:func:`interval_groups`), each group by y; pairs are taken inside the final groups."""
    lx, ly = [_bounds(b) for b in xs], [_bounds(b) for b in ys]
    ylo, yhi = [b[0] for b in ly], [b[1] for b in ly]
    pairs = []
    by_x = sorted(range(len(xs)), key=lambda i: float(xs[i].mid()))
    for gx in interval_groups([b[0] for b in lx], [b[1] for b in lx], by_x):
        if len(gx) < 2:
            continue
        by_y = sorted(gx, key=lambda i: float(ys[i].mid()))
        for g in interval_groups(ylo, yhi, by_y):
            g = sorted(g)
            pairs.extend((j, i) for k, i in enumerate(g) for j in g[:k])
    return pairs


_CENTRES = Cache("centre balls")    # id(homogeneous) -> (homogeneous, cx, cy balls): the audit's
                       # unions of levels share the whole configuration's centre


class Enclosures:
    """Balls of the points about the centre ``(X/D, Y/D)`` (``homogeneous``, ``D > 0``),
    and their exact counterparts computed on demand.  ``balls``: ``(xs, ys)``, balls of
    the points' coordinates when known (else :func:`coordinate_balls`); kept as
    ``self.balls``."""

    def __init__(self, points, homogeneous, balls=None):
        self.points = points
        self.homogeneous = homogeneous
        x, y, d = homogeneous
        self.unit = d == 1
        with ctx.workprec(PREC):
            centres = _CENTRES.table()
            hit = centres.get(id(homogeneous))
            if hit is not None and hit[0] is homogeneous:
                cx, cy = hit[1], hit[2]
            else:
                bd = _ball(d)
                cx, cy = _ball(x) / bd, _ball(y) / bd
                if len(centres) >= 8:
                    centres.clear()
                centres[id(homogeneous)] = (homogeneous, cx, cy)
            xs, ys = balls if balls is not None else coordinate_balls(points)
            self.balls = (xs, ys)
            self.vx = [b - cx for b in xs]
            self.vy = [b - cy for b in ys]
            self.r2 = [a * a + b * b for a, b in zip(self.vx, self.vy)]
            self.two_pi = 2 * arb.pi()
        self._vectors: dict = {}
        self._angles: dict = {}
        self._scaled: dict = {}
        self.centre_index = None
        self.theta = [self._theta(i) for i in range(len(points))]

    def __reduce__(self):
        # Arb balls do not pickle: a pickled Levels loses its enclosures (the exact path
        # then decides), never its values
        return (_dropped, ())

    # -- exact values, on demand -------------------------------------------------------
    def vector(self, i: int):
        """``D (p_i - C)``, exactly."""
        v = self._vectors.get(i)
        if v is None:
            x, y, d = self.homogeneous
            p = self.points[i]
            v = self._vectors[i] = (p[0] - x, p[1] - y) if self.unit else \
                (d * p[0] - x, d * p[1] - y)
        return v

    def scaled_r2(self, i: int):
        """``D^2 |p_i - C|^2``, exactly."""
        r = self._scaled.get(i)
        if r is None:
            vx, vy = self.vector(i)
            r = self._scaled[i] = product_sum([(vx, vx), (vy, vy)])
        return r

    def angle(self, i: int) -> PseudoAngle:
        a = self._angles.get(i)
        if a is None:
            a = self._angles[i] = PseudoAngle(*self.vector(i))
        return a

    # -- angles ----------------------------------------------------------------------------
    def _theta(self, i: int):
        """A ball around the angle of ``p_i - C`` in [0, 2 pi), or None (then every
        comparison of this direction is exact); marks the point at the centre."""
        bx, by = self.vx[i], self.vy[i]
        with ctx.workprec(PREC):
            if by > 0:
                return arb.atan2(by, bx)
            if by < 0:
                return arb.atan2(by, bx) + self.two_pi
            if bx < 0:                  # near the -x ray: pi + the angle of -(p - C)
                return arb.pi() + arb.atan2(-by, -bx)
            if bx > 0:                  # near the +x ray: the exact sign of y says which end
                s = _sign(self.vector(i)[1])
                if s == 0:
                    return arb(0)
                t = arb.atan2(by, bx)
                return t if s > 0 else t + self.two_pi
            vx, vy = self.vector(i)
            if _sign(vx) == 0 and _sign(vy) == 0:
                self.centre_index = i
            return None

    def compare_directions(self, i: int, j: int) -> int:
        """-1, 0, 1: the angles of ``p_i - C`` and ``p_j - C`` compared (exact when the
        balls overlap)."""
        a, b = self.theta[i], self.theta[j]
        if a is not None and b is not None:
            if a < b:
                return -1
            if a > b:
                return 1
        return self.angle(i)._cmp(self.angle(j))

    def sorted_by_direction(self, indices: list[int]) -> tuple[list[int], list[int]]:
        """``(order, adjacent)``: ``indices`` counter-clockwise from the +x ray, and the
        comparison of each adjacent pair (0: the same direction)."""
        def mid(i):
            t = self.theta[i]
            if t is not None:
                return float(t.mid())
            vx, vy = self.vector(i)
            a = math.atan2(float(vy), float(vx))
            return a + 2 * math.pi if a < 0 else a
        order = sorted(indices, key=mid)
        adjacent = [self.compare_directions(a, b) for a, b in zip(order, order[1:])]
        if any(c > 0 for c in adjacent):
            order = sorted(indices, key=cmp_to_key(self.compare_directions))
            adjacent = [self.compare_directions(a, b) for a, b in zip(order, order[1:])]
        return order, adjacent


def _dropped() -> None:
    return None


# ---------------------------------------------------------------- levels

def filtered_levels(enc: Enclosures, support: tuple[int, ...]):
    """``(flat, bounds)``: the points level by level (nearest first, each level
    counter-clockwise from the +x ray) and where each level starts.  Squared radii whose
    balls overlap are compared exactly; the SEC's support points lie on the circle by
    construction, so they are one level without computing."""
    n = len(enc.points)
    bounds_lohi = [_bounds(b) for b in enc.r2]
    lo = [b[0] for b in bounds_lohi]
    hi = [b[1] for b in bounds_lohi]
    order = sorted(range(n), key=lambda i: float(enc.r2[i].mid()))
    on_circle = set(support)
    flat: list[int] = []
    bounds: list[int] = []
    for group in interval_groups(lo, hi, order):
        if len(group) == 1 or all(i in on_circle for i in group):
            classes = [group]
        else:
            # exact classes by == (canonical forms; hashing a long polynomial costs more)
            found: list = []
            rep = None                  # one support point stands for all of them
            for i in group:
                if i in on_circle:
                    if rep is None:
                        rep = i
                    j = rep
                else:
                    j = i
                r = enc.scaled_r2(j)
                for c in found:
                    if c[0] == r:
                        c.append(i)
                        break
                else:
                    found.append([r, i])
            classes = [c[1:] for c in exact_sorted(found, key=lambda c: c[0])]
        for members in classes:
            bounds.append(len(flat))
            if len(members) > 1:
                members = enc.sorted_by_direction(members)[0]
            flat.extend(members)
    bounds.append(n)
    return flat, bounds


# ---------------------------------------------------------------- the C1 certificate

class _Gaps:
    """The angles from ray a to ray a + 1: balls, provisional classes (certified order
    between classes) and exact comparisons on demand.  ``rank[i]``: point i's level."""

    def __init__(self, enc: Enclosures, firsts: list[int], rank: list[int]):
        self.enc, self.firsts = enc, firsts
        m = len(firsts)
        theta = [enc.theta[i] for i in firsts]
        with ctx.workprec(PREC):
            self.balls = [theta[(a + 1) % m] - theta[a] + (enc.two_pi if a == m - 1 else 0)
                          for a in range(m)]
            pi = arb.pi()
            # -1: the gap is certainly below a half turn, 1: above, 0: unknown
            self.side = [-1 if g < pi else (1 if g > pi else 0) for g in self.balls]
        # the levels of the two rays of each gap (their nearest points)
        self.radii = [(rank[firsts[a]], rank[firsts[(a + 1) % m]]) for a in range(m)]
        lohi = [_bounds(b) for b in self.balls]
        order = sorted(range(m), key=lambda a: float(self.balls[a].mid()))
        self.cls = [0] * m
        for c, group in enumerate(interval_groups([b[0] for b in lohi], [b[1] for b in lohi],
                                                  order)):
            for a in group:
                self.cls[a] = c
        self._dot: dict = {}
        self._cross: dict = {}

    def _vectors(self, a: int):
        m = len(self.firsts)
        return self.enc.vector(self.firsts[a]), self.enc.vector(self.firsts[(a + 1) % m])

    def dot(self, a: int):
        """``u . v`` for the rays at and after gap a, exactly (scaled by D^2)."""
        d = self._dot.get(a)
        if d is None:
            (ux, uy), (vx, vy) = self._vectors(a)
            d = self._dot[a] = product_sum([(ux, vx), (uy, vy)])
        return d

    def cross(self, a: int):
        """``u x v`` for the rays at and after gap a, exactly (scaled by D^2)."""
        c = self._cross.get(a)
        if c is None:
            (ux, uy), (vx, vy) = self._vectors(a)
            c = self._cross[a] = product_sum([(ux, vy), (-uy, vx)])
        return c

    def compare(self, a: int, b: int) -> int:
        if a == b:
            return 0
        ca, cb = self.cls[a], self.cls[b]
        if ca != cb:
            return -1 if ca < cb else 1
        x, y = self.balls[a], self.balls[b]
        if x < y:
            return -1
        if x > y:
            return 1
        side = self.side[a]
        if side != 0 and side == self.side[b] and self.radii[a] == self.radii[b]:
            # equal |u|, |v| (same levels) and both angles on one side of a half turn:
            # u . v = |u| |v| cos(angle) decides alone (cos is monotone there)
            dot_a, dot_b = self.dot(a), self.dot(b)
            if dot_a == dot_b:
                return 0
            smaller = dot_a > dot_b if side < 0 else dot_a < dot_b
            return -1 if smaller else 1
        dot_a, dot_b = self.dot(a), self.dot(b)
        cross_a, cross_b = self.cross(a), self.cross(b)
        if dot_a == dot_b and cross_a == cross_b:     # the same angle (signs not needed)
            return 0
        return PseudoAngle(dot_a, cross_a)._cmp(PseudoAngle(dot_b, cross_b))


def certified_c1(enc: Enclosures, rank: list[int], centre_index: int | None):
    """``(rays, labelling)`` when the configuration is certified to have no symmetry but
    the identity (then ``labelling`` is the canonical one of :mod:`exactsym.truth.symmetry`, the
    point at the centre excluded), else None.  ``rank[i]``: the index of point i's level.
    Rays: tuples of indices by increasing distance, counter-clockwise from the +x ray."""
    n = len(enc.points)
    others = [i for i in range(n) if i != centre_index]
    if any(enc.theta[i] is None for i in others):
        return None
    order, adjacent = enc.sorted_by_direction(others)
    rays: list[list[int]] = [[order[0]]] if order else []
    for i, c in zip(order[1:], adjacent):
        if c == 0:
            rays[-1].append(i)
        else:
            rays.append([i])
    m = len(rays)
    if m < 3:
        return None
    rays_t = [tuple(sorted(ray, key=rank.__getitem__)) for ray in rays]
    keys = [tuple(rank[i] for i in ray) for ray in rays_t]
    distinct = sorted(set(keys))
    key_id = {k: r for r, k in enumerate(distinct)}
    ray_ids = [key_id[k] for k in keys]
    gaps = _Gaps(enc, [ray[0] for ray in rays_t], rank)
    width = max(gaps.cls) + 1
    ccw = [ray_ids[i] * width + gaps.cls[i] for i in range(m)]
    cw = [ray_ids[-i % m] * width + gaps.cls[(-i - 1) % m] for i in range(m)]
    if cyclic_period(ccw) != m or cyclic_occurrences(cw, ccw):
        return None                    # maybe symmetric: the exact algorithm decides

    def symbol(reading):               # (ray, gap) at position p of a reading
        clockwise, start, p = reading
        if clockwise:
            return -(start + p) % m, (-(start + p) - 1) % m
        return (start + p) % m, (start + p) % m

    def compare(r1, g1, r2, g2) -> int:
        if ray_ids[r1] != ray_ids[r2]:
            return -1 if ray_ids[r1] < ray_ids[r2] else 1
        return gaps.compare(g1, g2)

    readings = [(False, s, 0) for s in range(m)] + [(True, t, 0) for t in range(m)]
    for depth in range(m):
        best: list = []
        best_symbol = None
        for clockwise, start, _ in readings:
            r, g = symbol((clockwise, start, depth))
            c = -1 if best_symbol is None else compare(r, g, *best_symbol)
            if c < 0:
                best, best_symbol = [(clockwise, start, 0)], (r, g)
            elif c == 0:
                best.append((clockwise, start, 0))
        readings = best
        if len(readings) == 1:
            break
    if len(readings) != 1:
        return None
    clockwise, start, _ = readings[0]
    ray_order = [(-(start + p)) % m for p in range(m)] if clockwise else \
        [(start + p) % m for p in range(m)]
    labelling = [i for r in ray_order for i in rays_t[r]]
    return rays_t, labelling
