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

from ...exact import FieldElement
from ..circle_polygon import CirclePolygon
from ..filtered import ball


def applies(polygon: CirclePolygon) -> bool:
    """Cartesian, on one circle, algebraic coordinates (else the exact keys are cheap)."""
    if polygon.polar or not polygon.one_circle or polygon.n > 3:
        return False
    return any(isinstance(c, FieldElement) for d in polygon.directions for c in d)


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
    """Edges whose edge string CW_m equals its reverse (as the literal test), the
    entries -w.v compared by balls first, exactly on overlap."""
    n = polygon.n
    d = polygon.directions
    out = []
    for e in range(n):
        w = polygon.edge_direction(e)
        order = [(e - s) % n for s in range(n)]
        if w is None:              # a diameter: m = C, every entry equal
            out.append(e)
            continue
        ok = True
        for s in range(n // 2):
            a, b = order[s], order[n - 1 - s]
            if a == b:
                continue
            if _disjoint(_dot_ball(w, d[a]), _dot_ball(w, d[b])) or \
                    polygon.edge_key(e, a) != polygon.edge_key(e, b):
                ok = False
                break
        if ok:
            out.append(e)
    return out


__all__ = ["applies", "chords_equal", "string_classes_small", "edge_palindromes_small"]
