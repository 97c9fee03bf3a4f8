"""The strings of polygons of at most three vertices, compared through ball filters.

For n <= 3 the efficient string algorithms of :mod:`.strings` and :mod:`.types` fall
back to the literal strings; with algebraic coordinates of many terms (nine square
roots: a product costs seconds) every exact chord is expensive.  Two chords of one
circle are compared here first by Arb balls of their keys (``-u.v``, the polygon's
:meth:`~exactsym.paper.circle_polygon.CirclePolygon.chord_key` on one circle): disjoint
balls mean different chords; only overlapping ones are settled by the exact keys.  The
string classes and edge palindromes are then exactly those of the literal strings (equal
strings are equal entry by entry, and each entry comparison is exact).
"""

from __future__ import annotations

from ...exact.number import any_algebraic
from ...exact.fused import complex_product
from ..circle_polygon import CirclePolygon
from ..filtered import ball


def applies(polygon: CirclePolygon) -> bool:
    """Cartesian, on one circle, algebraic coordinates (else the exact keys are cheap)."""
    if polygon.polar or not polygon.one_circle or polygon.n > 3:
        return False
    return any_algebraic(c for d in polygon.directions for c in d)


def _dot_ball(u, v):
    return ball(u[0]) * ball(v[0]) + ball(u[1]) * ball(v[1])


def _disjoint(a, b) -> bool:
    return bool(a < b) or bool(a > b)


def chords_equal(polygon: CirclePolygon, p: tuple, q: tuple) -> bool:
    """Whether the chords of the vertex pairs ``p`` and ``q`` are equal (exact)."""
    if frozenset(p) == frozenset(q):
        return True
    d = polygon.directions
    if _disjoint(_dot_ball(d[p[0]], d[p[1]]), _dot_ball(d[q[0]], d[q[1]])):
        return False
    return polygon.chord_key(*p) == polygon.chord_key(*q)


def string_classes_small(polygon: CirclePolygon, orientation: int = 1):
    """``(cw, acw)`` class ids of the 2n vertex strings, as
    :func:`.strings.string_classes_reference` numbers them (first appearance, CW_0,
    ACW_0, CW_1, ...), the entries compared by :func:`chords_equal`."""
    n = polygon.n
    seen: list = []

    def intern(pairs) -> int:
        for other, k in seen:
            if all(chords_equal(polygon, p, q) for p, q in zip(pairs, other)):
                return k
        seen.append((pairs, len(seen)))
        return len(seen) - 1
    cw, acw = [], []
    for m in range(n):
        pairs = tuple((m, (m - orientation * s) % n) for s in range(1, n))
        cw.append(intern(pairs))
        acw.append(intern(pairs[::-1]))
    return cw, acw


def edge_palindromes_small(polygon: CirclePolygon) -> list[int]:
    """Edges whose edge string CW_m equals its reverse (as the literal test).  For n <= 3
    the string of edge (e, e+1) reads v_e, v_{e-1}, v_{e+1} (n = 3) or v_e, v_{e+1}
    (n = 2), so the only entries compared are the edge's two endpoints, equidistant from
    its midpoint m: m = C is at distance r from both when the edge is a diameter, and
    otherwise, with w = v_e + v_{e+1} and |v_e| = |v_{e+1}| (one circle),
    w.v_e = r^2 + v_e.v_{e+1} = w.v_{e+1}.  Every edge is therefore a palindrome; the
    loop below checks that this is the only comparison."""
    n = polygon.n
    out = []
    for e in range(n):
        order = [(e - s) % n for s in range(n)]
        pairs = {frozenset((order[s], order[n - 1 - s])) for s in range(n // 2)}
        if not pairs <= {frozenset((e, (e + 1) % n))}:
            raise AssertionError("edge_palindromes_small is for at most three vertices")
        out.append(e)
    return out


def line_count_small(polygon: CirclePolygon, vertices, edges) -> int:
    """The number of distinct lines through C among those of the vertices ``vertices``
    and of the edge points of ``edges`` (as :func:`exactsym.paper.keys.circle_line_keys`
    tells them apart: vectors of length r^2 along the doubled angle, equal iff the lines
    are), the vectors compared by balls first and exactly on overlap."""
    d = polygon.directions
    n = polygon.n
    items = []          # (ball x, ball y, exact thunk)
    for i in vertices:
        x, y = d[i]
        bx, by = ball(x), ball(y)
        items.append((bx * bx - by * by, 2 * bx * by,
                      lambda x=x, y=y: ((x - y) * (x + y), 2 * (x * y))))
    for e in edges:
        (ax, ay), (cx, cy) = d[e], d[(e + 1) % n]
        bax, bay, bcx, bcy = ball(ax), ball(ay), ball(cx), ball(cy)
        items.append((bax * bcx - bay * bcy, bax * bcy + bay * bcx,
                      lambda ax=ax, ay=ay, cx=cx, cy=cy: complex_product((ax, ay), (cx, cy))))
    exact: dict = {}

    def value(k):
        if k not in exact:
            exact[k] = items[k][2]()
        return exact[k]
    distinct: list = []
    for k, (bx, by, _) in enumerate(items):
        same = False
        for j in distinct:
            if items[j][0].overlaps(bx) and items[j][1].overlaps(by) and value(j) == value(k):
                same = True
                break
        if not same:
            distinct.append(k)
    return len(distinct)


__all__ = ["applies", "chords_equal", "string_classes_small", "edge_palindromes_small",
           "line_count_small"]
