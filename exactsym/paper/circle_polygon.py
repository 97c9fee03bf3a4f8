"""Convex polygons inscribed in a circle about the centre C (Section 3).

Section 3: "by convex polygon we mean such polygons which are inscribed in a
circle".  A :class:`CirclePolygon` stores, for each vertex counter-clockwise, a
label (the configuration point index, or any hashable label) and the exact
*direction* of the vertex seen from C: a rational turn in ``[0, 1)`` on the polar
path, or a non-zero exact vector ``(dx, dy)`` on the Cartesian path.

Distances without square roots
------------------------------
The paper's strings (``CW_m``, ``ACW_m``, Section 3) are sequences of Euclidean
distances.  All we ever do with them is test equality and compare them
lexicographically, and both are preserved by *any strictly increasing map*
applied to every element (the same map for every string compared).  So we keep
an exact *key* that is a strictly increasing function of the distance:

* **polar** (``metric = "angular-distance"``): two vertices on a common circle
  at turns ``a, b`` are at chord ``2 r sin(pi d)`` with ``d = min(|a-b|, 1-|a-b|)``
  in ``[0, 1/2]``; ``sin(pi d)`` is strictly increasing there, so the key is ``d``;
* **Cartesian** (``metric = "signed-squared-cosine"``): for directions ``u, v``
  with angle ``theta`` in ``[0, pi]`` the chord is ``2 r sin(theta/2)``, strictly
  increasing in ``theta``; ``-cos(theta)`` is too, and so is
  ``-sign(cos) cos^2`` = ``-sign(u.v) (u.v)^2 / (|u|^2 |v|^2)``: the key
  (:meth:`CirclePolygon.separation`).  The strings use :meth:`CirclePolygon.chord_key`:
  on one circle ``-u.v = -r^2 cos(theta)``, another strictly increasing function of
  ``theta``, with no division (an inverse in a number field of large degree can cost
  seconds) and one product; it compares the chords of one polygon (and of the polygons
  G minus v_i, on the same circle), which is all the strings do.

The point m on an edge
----------------------
For ``m`` the midpoint of the edge ``(a, b)`` (where the perpendicular bisector
of the edge, a line through C, meets the polygon) we use the point ``m'`` of the
circle on the ray C->m.  Proof that the distances from m are an increasing
function of the distances from m' (so the key from m' serves for m): put C at
the origin, ``|v| = |m'| = r`` and ``m = lambda m'`` with
``lambda = |m| / r = |cos(pi g)|`` for the edge's angular gap ``g`` (``m`` lies on
the ray through ``m'`` by choice of ``m'``, so ``lambda >= 0``).  Then

    |m - v|^2 = |m|^2 + r^2 - 2 lambda (m' . v)
             = |m|^2 + r^2 + lambda (|m' - v|^2 - 2 r^2)
             = const + lambda |m' - v|^2,

strictly increasing in ``|m' - v|`` when ``lambda > 0``.  The constant and
``lambda`` depend only on the edge's length, so strings from *different* edge
points are comparable as long as their first elements (the half edge lengths,
whose keys ``min(g, 1-g)/2`` order the half chords correctly) are equal; when
they differ the first element decides and the keys order it correctly too.
When ``lambda = 0`` (the edge is a diameter, ``m = C``) every distance from m is
r, the half edge: every key is then the key of that half edge, ``1/4`` (polar) or
``0`` (Cartesian).

``m'`` is the midpoint of the arc ``a -> b`` when that arc is below half a turn
and its antipode when it is above (the chord midpoint is then on the far side
of C).  The edge strings (:meth:`CirclePolygon.edge_key`) drop the constant ``|w|^2 r^2`` of
their edge point likewise: they compare within the strings of one edge point (a
palindrome test); use :meth:`CirclePolygon.separation_from_edge` to compare across
edges.  Note: an edge key and a vertex key are *not* on one scale (vertex
strings start with a chord, edge strings with a half chord); compare strings of
the same kind only.

Cartesian edge points need the bisector ``u_a/|u_a| + u_b/|u_b|``; on a level
``|u_a| = |u_b|`` and ``u_a + u_b`` (the chord midpoint direction) is exact.  For
directions of different lengths we scale exactly when ``|u_a|^2/|u_b|^2`` is the
square of a rational, and otherwise raise :class:`NotImplementedError` (the
bisector would need a square root outside the configuration's field).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, cmp_to_key

from ..exact import fmpq, normal_turn, rational_sqrt, sign
from ..exact.number import any_algebraic, is_algebraic, is_sparse, tower_of
from ..exact.context import Cache
from .filtered import ball, compare_directions
from .homogeneous import is_short, register
from .inverses import inverse_length, squared_length

__all__ = ["CirclePolygon", "level_polygon", "polygon_from_directions", "angular_distance",
           "POLAR_METRIC", "CARTESIAN_METRIC"]

POLAR_METRIC = "angular-distance"
CARTESIAN_METRIC = "signed-squared-cosine"

_QUARTER = fmpq(1, 4)
_HALF = fmpq(1, 2)


def angular_distance(a: fmpq, b: fmpq) -> fmpq:
    """``min(d, 1 - d)`` for ``d = |a - b| mod 1``: the angle between two turns, in turns."""
    d = normal_turn(a - b)
    return d if d <= _HALF else 1 - d


def _dot(u, v):
    return u[0] * v[0] + u[1] * v[1]


def _cosine_key(u, v):
    """``-sign(u.v) (u.v)^2 / (|u|^2 |v|^2)``: strictly increasing in the angle of u, v."""
    d = _dot(u, v)
    s = sign(d)
    if s == 0:
        return d * 0
    return -s * d * d * inverse_length(squared_length(u)) * inverse_length(squared_length(v))


def _circle_chord(u, v):
    """``-u.v``: :meth:`CirclePolygon.chord_key` on one circle (strictly increasing in
    the angle of u and v for |u| |v| fixed, as ``-sign(u.v) (u.v)^2`` is; one product
    less, and no sign, which matters when a product costs a second: nine square roots)."""
    return -_dot(u, v)


_PAIRS = Cache("direction pairs")     # (f, id(u), id(v)) -> (u, v, f(u, v))
_PAIRS_LIMIT = 1 << 16


def _pair_value(f, u, v):
    """``f(u, v)`` for a symmetric ``f`` of two direction vectors, remembered per pair of
    vector *objects* when they hold algebraic numbers (each product costs a millisecond
    in a large number field, and the strings, Theorem 1 and Elect_Leader_Asym's polygons
    G minus v_i read the same chords again).  The entry keeps both vectors, so an id is
    never mistaken for another object's; rational vectors are recomputed (cheap)."""
    if not any_algebraic((u[0], u[1], v[0], v[1])):
        return f(u, v)
    key = (f, id(u), id(v)) if id(u) <= id(v) else (f, id(v), id(u))
    pairs = _PAIRS.table()
    hit = pairs.get(key)
    if hit is not None and ((hit[0] is u and hit[1] is v) or (hit[0] is v and hit[1] is u)):
        return hit[2]
    value = f(u, v)
    if len(pairs) >= _PAIRS_LIMIT:
        pairs.clear()
    pairs[key] = (u, v, value)
    return value


@dataclass(frozen=True)
class CirclePolygon:
    """A convex polygon inscribed in a circle about the centre C (Section 3: 'by convex
    polygon we mean such polygons which are inscribed in a circle'); vertices counter-clockwise.

    ``labels[i]``: the configuration point index (or any hashable label) of vertex i;
    ``directions[i]``: a rational turn in [0, 1) (``polar``) or an exact non-zero vector
    ``(dx, dy)`` from C (Cartesian; only the direction matters).

    :meth:`separation` and :meth:`separation_from_edge` return exact keys, strictly
    increasing functions of the Euclidean distances the paper uses (see the module
    docstring); equality and the lexicographic order of the paper's strings are
    preserved by any strictly increasing map.
    """
    labels: tuple
    directions: tuple
    polar: bool

    @property
    def n(self) -> int:
        return len(self.labels)

    @property
    def metric(self) -> str:
        """What the keys are: ``"angular-distance"`` (turns) or ``"signed-squared-cosine"``."""
        return POLAR_METRIC if self.polar else CARTESIAN_METRIC

    def separation(self, i: int, j: int):
        """Exact key, strictly increasing in the chord |v_i v_j| (equal iff equal chords)."""
        n = self.n
        i, j = i % n, j % n
        a, b = self.directions[i], self.directions[j]
        if self.polar:
            return angular_distance(a, b)
        d = _dot(a, b)
        s = sign(d)
        if s == 0:
            return d * 0
        inverse = self.inverse_lengths           # -s d^2 / (|a|^2 |b|^2), one inverse per length
        return -s * d * d * inverse[i] * inverse[j]

    @cached_property
    def inverse_lengths(self) -> tuple:
        """Cartesian: ``1 / |u|^2`` of each direction, one inverse per distinct length."""
        return tuple(inverse_length(squared_length(d)) for d in self.directions)

    @cached_property
    def one_circle(self) -> bool:
        """Cartesian: every direction vector has the same length (a level polygon)."""
        if self.polar or len(self.directions) < 2:     # one vertex: one length
            return True
        dirs = self.directions
        if any_algebraic(c for d in dirs for c in d):
            # Arb balls of the squared lengths first: disjoint balls prove two lengths
            # differ (the usual answer for a union of levels), without the exact squares
            # (products of degree thousands in a large cyclotomic field, issue 9)
            first = _length_ball(dirs[0])
            if any(not first.overlaps(_length_ball(d)) for d in dirs[1:]):
                return False
        first = squared_length(dirs[0])
        return all(squared_length(d) == first for d in dirs)

    def chord_key(self, i: int, j: int):
        """An exact key, strictly increasing in the chord |v_i v_j|, for comparing the
        chords of *this* polygon (the strings, Section 3): :meth:`separation`, or on one
        circle (:attr:`one_circle`) ``-u.v = -r^2 cos(angle)``, strictly increasing in the
        angle in [0, pi], hence in the chord ``2 r sin(angle / 2)`` -- no division (a field
        inverse can cost seconds in a large number field) and a single product."""
        n = self.n
        a, b = self.directions[i % n], self.directions[j % n]
        if self.polar:
            return angular_distance(a, b)
        if not self.one_circle:
            return _pair_value(_cosine_key, a, b)
        return _pair_value(_circle_chord, a, b)

    def edge_key(self, i: int, j: int):
        """An exact key, strictly increasing in the distance from m (the point of edge
        (i, i+1), as :meth:`separation_from_edge`) to vertex j, for comparing the
        distances from *one* edge point (an edge string CW_m, ACW_m): on one circle
        ``-w.v``, strictly increasing in the angle of w and v (|w| and |v| fixed for that
        edge point), no division."""
        if self.polar or not self.one_circle:
            return self.separation_from_edge(i, j)
        w = self.edge_direction(i)
        if w is None:      # the edge is a diameter: m = C, every vertex at distance r
            return self._zero()
        return _pair_value(_circle_chord, w, self.directions[j % self.n])

    def edge_direction(self, i: int):
        """Direction (turn or vector) from C of the point m' of the circle on the ray C->m,
        m the midpoint of edge (i, i+1); None when the edge is a diameter (m = C).
        Computed once per edge (the edge strings read it n times)."""
        n = self.n
        cache = self.__dict__.setdefault("_edge_directions", {})
        i %= n
        if i not in cache:
            cache[i] = self._edge_direction(i)
        return cache[i]

    def _edge_direction(self, i: int):
        n = self.n
        a, b = self.directions[i % n], self.directions[(i + 1) % n]
        if self.polar:
            gap = normal_turn(b - a)
            if n == 1:
                gap = fmpq(1)
            if gap == _HALF:
                return None
            mid = a + gap / 2
            if gap > _HALF:
                mid += _HALF
            return normal_turn(mid)
        la, lb = squared_length(a), squared_length(b)
        if not self.one_circle and la != lb:
            scale = _rational_ratio_root(la, lb)
            if scale is None:
                raise NotImplementedError(
                    "edge point m of a Cartesian polygon whose direction vectors have "
                    "different lengths: the bisector u_a/|u_a| + u_b/|u_b| needs sqrt(|u_a|^2/|u_b|^2),"
                    " which is not a rational square here; give equal-length directions")
            b = (b[0] * scale, b[1] * scale)           # now |b| = |a|
        w = (a[0] + b[0], a[1] + b[1])
        if sign(w[0]) == 0 and sign(w[1]) == 0:
            return None
        return w

    def separation_from_edge(self, i: int, j: int):
        """Exact key, strictly increasing in the distance from m (midpoint of edge (i, i+1),
        where the edge's perpendicular bisector meets the polygon) to vertex j."""
        w = self.edge_direction(i)
        if w is None:      # the edge is a diameter: m = C, every vertex at distance r
            return _QUARTER if self.polar else self._zero()
        v = self.directions[j % self.n]
        if self.polar:
            return angular_distance(w, v)
        return _cosine_key(w, v)

    def _zero(self):
        x = self.directions[0][0]
        return x * 0


def _rational_ratio_root(la, lb):
    """``sqrt(la / lb)`` when it is rational (both rational), else None."""
    if is_algebraic(la):
        if not (la.is_rational() and lb.is_rational()):
            return None
        la, lb = la.to_fmpq(), lb.to_fmpq()
    return rational_sqrt(fmpq(la) / fmpq(lb))


def polygon_from_directions(labels, directions, polar: bool) -> CirclePolygon:
    """The polygon with these vertices, sorted counter-clockwise from angle 0 (the +x ray).

    Polar directions are turns (normalised to [0, 1)); Cartesian ones non-zero exact
    vectors.  Two vertices in the same direction raise ValueError (they cannot both lie
    on one circle about C).  Used by radial projection (G_ij) in the family layer.
    """
    labels, directions = tuple(labels), tuple(directions)
    if len(labels) != len(directions):
        raise ValueError("labels and directions differ in length")
    if polar:
        directions = tuple(normal_turn(fmpq(t)) for t in directions)
        order = sorted(range(len(labels)), key=lambda k: directions[k])
        same = lambda p, q: directions[p] == directions[q]   # noqa: E731
    else:
        for d in directions:
            if d[0] == 0 and d[1] == 0:      # exact zero tests (no certified sign)
                raise ValueError("a vertex at the centre C has no direction")
        order = sorted(range(len(labels)),
                       key=cmp_to_key(lambda p, q: compare_directions(directions[p], directions[q])))
        same = lambda p, q: compare_directions(directions[p], directions[q]) == 0  # noqa: E731
    for p, q in zip(order, order[1:]):
        if same(p, q):
            raise ValueError(f"vertices {labels[p]!r} and {labels[q]!r} have the same direction")
    return CirclePolygon(tuple(labels[k] for k in order), tuple(directions[k] for k in order),
                         polar)


def level_polygon(config, rings, level_index: int, cleared: bool = False) -> CirclePolygon:
    """The polygon G_{level_index + 1} of ``levels_of(config)`` (levels are nearest first).

    The level's points are already counter-clockwise from the +x ray through C.
    Raises ValueError for the level of radius 0 (a point at C has no direction).
    ``cleared``: the directions p - C all multiplied by one positive number: D, when the
    centre C = (X/D, Y/D) is of a tower (the directions D p - (X, Y)), or in the sparse
    Q(zeta_N) one that clears C's denominator (:func:`_cleared`): a similarity about C,
    so every verdict on the polygon alone is the same, but the directions are not p - C
    (the polygon's ``cleared`` flag says so; only for the per-level verdicts).
    """
    level = rings.levels[level_index]
    if sign(level.radius_squared) == 0:
        raise ValueError("the level of radius 0 (a robot at the centre C) is not a polygon")
    labels = tuple(level.points)
    if rings.polar:
        return CirclePolygon(labels, tuple(config.polar[i][1] for i in labels), True)
    pts = config.points
    x, y, den = rings.sec.homogeneous
    if cleared and tower_of(den) is not None:
        # the homogeneous directions D p - (X, Y) = D (p - C), D > 0: no tower quotient
        # (over the sparse Q(zeta_N) its coordinates are quotients of sums of cosines, and
        # every product of the strings cross-multiplied them: two mirror pairs at turns
        # +-2j/997 and radii sqrt(k) took 5.8 s, 0.65 s homogeneous)
        dirs = scaled = tuple((den * pts[i][0] - x, den * pts[i][1] - y) for i in labels)
    else:
        cx, cy = rings.sec.centre
        dirs = tuple([(pts[i][0] - cx, pts[i][1] - cy) for i in labels])
        scaled = _cleared(dirs) if cleared else None
    poly = CirclePolygon(labels, scaled or dirs, False)
    homogeneous = rings.sec.homogeneous
    if is_short(homogeneous):       # else register records nothing (decided once here)
        for i, d in zip(labels, poly.directions):
            # its short text (.homogeneous): D p - (X, Y) is a positive multiple of it too
            register(d, pts[i], homogeneous)
    poly.__dict__["one_circle"] = True      # a level: one exact distance to C, by definition
    poly.__dict__["cleared"] = scaled is not None
    return poly


def _cleared(dirs):
    """``dirs`` (vectors of the sparse Q(zeta_N)) times f = |d|, d the denominator of
    their first quotient coordinate, when every quotient coordinate has it (then a
    coordinate a/d becomes +-a, the others a product by f), else None.  The sums of
    quotients with a denominator cross-multiplied it into every product of the strings:
    a 4-gon of two mirror pairs at turns j/997 took 6 s per string partition, 0.2 s
    cleared.  (Over a tower of square roots over the sparse base clearing the leaves did
    not help: 17 s per partition, the tower's inverses and products remain.)"""
    if not all(is_sparse(c) for d in dirs for c in d):
        return None
    den = next((c.den for d in dirs for c in d if c.den is not None), None)
    if den is None or not all(c.den is None or c.den == den for d in dirs for c in d):
        return None
    factor = dirs[0][0]._new(den)
    s = factor.sign()
    factor = factor * s
    return tuple(tuple(c._new(c.num) * s if c.den is not None else c * factor for c in d)
                 for d in dirs)


def _length_ball(d):
    """An Arb ball containing ``d_x^2 + d_y^2`` (from the cached balls of the coordinates)."""
    bx, by = ball(d[0]), ball(d[1])
    return bx * bx + by * by
