"""The combinatorial shape of a level polygon: the key under which the polygon layer's
verdicts (:func:`exactsym.paper.polygon_report.level_verdicts`) are computed once and
shared (issue 9, "one verdict per distinct shape").

:func:`combinatorial_key` interns everything the verdicts read to small integers::

    (polar, n, G, D, L, M)

* ``G``: the counter-clockwise gaps between consecutive vertices (from vertex 0, storage
  order), interned by first appearance: ``G[i] == G[j]`` iff the gaps are equal;
* ``D``: the edges that are diameters (gap exactly half a turn: their point m is C);
* ``L``: the lines through C of the n vertices and then of the n edge points (the
  direction of the edge's midpoint, or the perpendicular of a diameter edge), interned:
  equal ids iff equal lines;
* ``M``: for every pair i < j (row by row) the *rank* of the chord |v_i v_j| among the
  polygon's chords: equal ranks iff equal chords, and ranks ordered as the chords.

Why equal keys give equal verdicts (labels taken at the same storage positions), for
polygons of at least 4 vertices (:data:`MIN_VERTICES`; smaller ones use the exact gap
key):

* every CW/ACW vertex string is a row of chords (Section 3), so their equalities and
  their lexicographic order are functions of ``M``: the string classes (Theorem 1,
  vertex palindromes, Check_Symmetry_Odd/Even: the efficient
  :func:`exactsym.paper.polygon.string_classes` equals the literal strings' classes,
  proved in its docstring and tested), Elect_Leader_Sym's comparison ``CW(v_i) >
  CW(v_j)``, Elect_Leader_Asym's lexicographic minimum and its polygons G minus v_i
  (their chords are chords of G);
* the edge palindromes (n >= 4) read ``G`` and ``D`` only; ``lines_by_strings`` counts the
  distinct lines among the palindromic vertices and edges: ``L``;
* a reflection mapping the vertex set onto itself maps v_0 to some v_s and v_i to
  v_{s-i}; it exists iff g_i = g_{s-1-i} for every i (a function of ``G``); distinct s
  give distinct axes; a vertex v_k lies on the axis iff the reflection fixes it, iff
  2k = s (mod n).  So the definition's mirrors, their number, the vertices on each
  (the type's ``through``, Elect_Leader_Sym's vertices on the line) and the type are
  functions of ``(n, G)``; regularity is "all gaps equal"; the half-turn maps the set
  onto itself iff n is even and ``G`` has period n/2 (skew symmetry).

The rational Cartesian path computes the key on integers: the directions (one circle
about C) are scaled by one positive integer to integer vectors, chords are ranked by
``-(u.v)|u.v|`` (an increasing function of the angle, the lengths being equal), gaps
keyed by the sign of the cross product and ``(u.v)|u.v|``, lines by the primitive
integer vector of the doubled angle ``(x^2 - y^2, 2xy)``: no division and no fmpq
hashing.  Polar polygons and algebraic coordinates use the polygon's exact keys.
"""

from __future__ import annotations

from math import gcd

from ..exact import exact_key
from .circle_polygon import CirclePolygon
from .keys import (circle_line_keys, gap_ids, hashable_key, polygon_integer_directions,
                   integer_gap_key, line_value)
from .polygon.strings import perpendicular

#: Smallest polygon keyed combinatorially (for n <= 3 the edge palindromes compare edge
#: strings literally: those keep the exact gap key).
MIN_VERTICES = 4


def combinatorial_key(polygon: CirclePolygon):
    """``(polar, n, G, D, L, M)`` of ``polygon`` (module docstring), n >= 4."""
    n = polygon.n
    if n < MIN_VERTICES:
        raise ValueError(f"combinatorial keys are for polygons of at least {MIN_VERTICES} "
                         "vertices")
    if not polygon.polar:
        vectors = polygon_integer_directions(polygon)
        if vectors is not None:
            key = _integer_key(vectors)
            # its gaps are gap_ids' (interned in order of occurrence): kept for the
            # family layer's polygon of this level (issue 33: one gap key per edge)
            polygon.__dict__.setdefault("gap_ids", list(key[2]))
            return key
    return _exact_key(polygon)


def _primitive_line(x: int, y: int) -> tuple:
    """The line through C of direction (x, y) != 0, as the primitive integer vector of
    its doubled angle (x^2 - y^2, 2xy): equal iff the lines are equal."""
    a, b = x * x - y * y, 2 * x * y
    g = gcd(a, b)
    return (a // g, b // g)


def _intern(values) -> tuple:
    ids: dict = {}
    return tuple([ids.setdefault(v, len(ids)) for v in values])


def _ranks(values) -> tuple:
    order = {v: k for k, v in enumerate(sorted(set(values)))}
    return tuple([order[v] for v in values])


def _integer_key(u) -> tuple:
    """The key of integer direction vectors ``u`` of one length (``integer_gap_key`` and
    ``_primitive_line`` written out: 12,500 octagons of a D4 set of 100,000 robots
    made a million calls)."""
    n = len(u)
    gaps, diam, lines = [], [], []
    edge_lines = []
    for i in range(n):
        ax, ay = u[i]
        bx, by = u[(i + 1) % n] if i + 1 < n else u[0]
        # integer_gap_key(u[i], u[i + 1])
        c = ax * by - ay * bx
        d = ax * bx + ay * by
        if c > 0:
            gaps.append((0, -d * abs(d)))
        elif c < 0:
            gaps.append((2, d * abs(d)))
        else:
            gaps.append((1, 0) if d < 0 else (3, 0))
        wx, wy = ax + bx, ay + by
        if wx == 0 and wy == 0:        # a diameter: m = C; its line is the perpendicular
            diam.append(i)
            wx, wy = -ay, ax
        a, b = wx * wx - wy * wy, 2 * wx * wy         # _primitive_line(wx, wy)
        g = gcd(a, b)
        edge_lines.append((a // g, b // g))
        a, b = ax * ax - ay * ay, 2 * ax * ay         # _primitive_line(ax, ay)
        g = gcd(a, b)
        lines.append((a // g, b // g))
    lines += edge_lines
    # the chord keys -d|d| (d = u_i . u_j) rank as the dot products d in reverse:
    # -d|d| is strictly decreasing in d
    dots = [ax * bx + ay * by for i, (ax, ay) in enumerate(u) for bx, by in u[i + 1:]]
    order = {v: k for k, v in enumerate(sorted(set(dots), reverse=True))}
    return (False, n, _intern(gaps), tuple(diam), _intern(lines),
            tuple([order[v] for v in dots]))


def _exact_key(polygon: CirclePolygon) -> tuple:
    n, polar, dirs = polygon.n, polygon.polar, polygon.directions
    circle = circle_line_keys(polygon)
    diam, edge_lines = [], []
    for i in range(n):
        w = polygon.edge_direction(i)
        if w is None:
            diam.append(i)
            w = perpendicular(polygon, dirs[i])
        if circle is None:
            edge_lines.append(hashable_key(line_value(polar, w)))
    if circle is not None:      # the same equalities without a division
        lines = list(circle[0]) + list(circle[1])
    else:
        lines = [hashable_key(line_value(polar, d)) for d in dirs] + edge_lines
    chords = [polygon.chord_key(i, j) for i in range(n) for j in range(i + 1, n)]
    distinct = {exact_key(c): c for c in chords}
    order = {k: r for r, k in enumerate(sorted(distinct, key=distinct.__getitem__))}
    return (polar, n, tuple(gap_ids(polygon)), tuple(diam), _intern(lines),
            tuple([order[exact_key(c)] for c in chords]))


__all__ = ["combinatorial_key", "MIN_VERTICES"]
