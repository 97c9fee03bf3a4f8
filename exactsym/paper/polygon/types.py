"""Lines of straight symmetry as the CW/ACW strings find them (``lemma-straight-sym``:
:func:`straight_lines`, reported as ``lines_by_strings``) and the polygon types of Section 3
(``type-0`` .. ``type-4``) by their definition, from the exact mirrors (:func:`polygon_type`).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..circle_polygon import CirclePolygon
from . import small
from ..keys import LineKey, circle_line_keys, gap_ids, line_key, line_value
from .definitions import definition_mirror_keys
from .strings import (HASH_BASE, HASH_MOD, Hasher, cw_string_edge, gap_classes, perpendicular,
                      string_classes, vertex_strings)


def vertex_palindromes(polygon: CirclePolygon) -> list[int]:
    """Vertices m with CW_m = ACW_m (independent of the orientation)."""
    cw, acw = string_classes(polygon)
    return [i for i in range(polygon.n) if cw[i] == acw[i]]


def edge_palindromes(polygon: CirclePolygon, reference: bool = False) -> list[int]:
    """Edges e (from vertex e to e+1, counter-clockwise) whose midpoint m has CW_m = ACW_m.

    Efficient version (default): the pairs (v_s, v_{k+1-s}) of the string are at equal
    distance from m iff they are mirror images across the line C m (arc vs complement
    cannot both fit, the two vertices being distinct), i.e. iff the gap sequence reads the
    same backwards from e-1 and forwards from e+1 for floor(k/2)-1 gaps; the middle vertex
    of an odd string is unconstrained; an edge that is a diameter has m = C and every
    distance equal to r.  ``reference=True`` compares the literal strings (O(n^2))."""
    n = polygon.n
    if not reference and small.applies(polygon):     # n <= 3: balls, exact on overlap
        return small.edge_palindromes_small(polygon)
    if reference or n <= 3:
        out = []
        for e in range(n):
            s = cw_string_edge(polygon, e)
            if s == s[::-1]:
                out.append(e)
        return out
    ids, h = gap_classes(polygon)
    hh = h + h
    rr = h[::-1] * 2
    powers = [1]
    for _ in range(n + 1):
        powers.append(powers[-1] * HASH_BASE % HASH_MOD)
    fwd, bwd = Hasher(hh), Hasher(rr)
    length = n // 2 - 1
    out = []
    for e in range(n):
        if polygon.edge_direction(e) is None:
            out.append(e)
            continue
        b = (e + 1) % n
        a = (e - 1) % n
        ra = (n - 1 - a) % n
        if length <= 0 or (fwd.window(b, length, powers) == bwd.window(ra, length, powers)
                           and hh[b:b + length] == rr[ra:ra + length]):
            out.append(e)
    return out


@dataclass(frozen=True)
class StraightLine:
    """A line of straight symmetry found from the strings (through the centre C).

    ``key``: exact key of the line; ``vertices``: vertices lying on it (geometrically);
    ``edges``: edges whose midpoint lies on it; ``found_at``: the palindromes that
    produced it, as ("vertex", i) / ("edge", e)."""
    key: object
    vertices: tuple
    edges: tuple
    found_at: tuple


def straight_lines(polygon: CirclePolygon, reference: bool = False) -> list[StraightLine]:
    """Lines of straight symmetry as the strings find them (``lemma-straight-sym``): one per
    vertex m with CW_m = ACW_m and one per edge midpoint m with CW_m = ACW_m, deduplicated
    (for an even polygon a line meets two vertices/edges and is found twice; for an odd one
    it meets a vertex and an edge).  A vertex/edge *lies on* a line when its direction (the
    direction of its midpoint) does."""
    n = polygon.n
    if n == 0:
        return []
    found: dict = {}
    if reference:
        vp = [i for i, (a, b) in enumerate(vertex_strings(polygon)) if a == b]
    else:
        vp = vertex_palindromes(polygon)
    circle = circle_line_keys(polygon) if n >= 2 else None
    if circle is not None:
        return _straight_lines_on_circle(polygon, vp, circle, reference)
    for i in vp:
        found.setdefault(line_value(polygon.polar, polygon.directions[i]), []).append(("vertex", i))
    if n >= 2:
        for e in edge_palindromes(polygon, reference):
            w = polygon.edge_direction(e)
            if w is None:
                w = perpendicular(polygon, polygon.directions[e])
            found.setdefault(line_value(polygon.polar, w), []).append(("edge", e))
    vkeys: dict = {}
    for i, d in enumerate(polygon.directions):
        vkeys.setdefault(line_value(polygon.polar, d), []).append(i)
    ekeys: dict = {}
    if n >= 2:
        for e in range(n):
            w = polygon.edge_direction(e)
            if w is None:
                w = perpendicular(polygon, polygon.directions[e])
            ekeys.setdefault(line_value(polygon.polar, w), []).append(e)
    return [StraightLine(key, tuple(vkeys.get(key, ())), tuple(ekeys.get(key, ())), tuple(at))
            for key, at in found.items()]


def straight_line_count(polygon: CirclePolygon) -> int:
    """``len(straight_lines(polygon))`` (the report's ``lines_by_strings``) without the
    lines' exact keys: the same palindromes, the lines told apart by
    :func:`exactsym.paper.keys.circle_line_keys` on one circle, else by
    :class:`~exactsym.paper.keys.LineKey` (no division)."""
    n = polygon.n
    if n == 0:
        return 0
    vp = vertex_palindromes(polygon)
    edges = edge_palindromes(polygon) if n >= 2 else []
    if n >= 2 and small.applies(polygon):       # the same keys, compared by balls first
        return small.line_count_small(polygon, vp, edges)
    circle = circle_line_keys(polygon) if n >= 2 else None
    if circle is not None:
        vk, ek = circle
        return len({vk[i] for i in vp} | {ek[e] for e in edges})
    keys = {line_key(polygon.polar, polygon.directions[i]) for i in vp}
    for e in edges:
        w = polygon.edge_direction(e)
        if w is None:
            w = perpendicular(polygon, polygon.directions[e])
        keys.add(line_key(polygon.polar, w))
    return len(keys)


def _straight_lines_on_circle(polygon, vp, circle, reference) -> list[StraightLine]:
    """:func:`straight_lines` with the division-free line keys of
    :func:`exactsym.paper.keys.circle_line_keys` (same lines, same order); the exact key of
    a line found is computed once, from its first vertex or edge point."""
    vk, ek = circle
    found: dict = {}
    first: dict = {}
    for i in vp:
        found.setdefault(vk[i], []).append(("vertex", i))
        first.setdefault(vk[i], polygon.directions[i])
    for e in edge_palindromes(polygon, reference):
        if ek[e] not in first:
            w = polygon.edge_direction(e)
            first[ek[e]] = w if w is not None else perpendicular(polygon, polygon.directions[e])
        found.setdefault(ek[e], []).append(("edge", e))
    vkeys: dict = {}
    for i, k in enumerate(vk):
        vkeys.setdefault(k, []).append(i)
    ekeys: dict = {}
    for e, k in enumerate(ek):
        ekeys.setdefault(k, []).append(e)
    return [StraightLine(line_value(False, first[k]), tuple(vkeys.get(k, ())),
                         tuple(ekeys.get(k, ())), tuple(at)) for k, at in found.items()]


def is_regular(polygon: CirclePolygon) -> bool:
    """All angular gaps between consecutive vertices equal (a single vertex, and two
    diametrically opposite vertices, are regular)."""
    n = polygon.n
    if n <= 1:
        return True
    return len(set(gap_ids(polygon))) == 1


class TypeVerdict(str):
    """``"type-0"`` .. ``"type-4"`` or ``"unclassified"``; ``.reason`` says why, ``.lines``
    are the lines of straight symmetry counted (line keys), ``.through`` the number of
    vertices on each."""
    reason: str
    lines: tuple
    through: tuple

    def __new__(cls, name: str, reason: str, lines=(), through=()):
        obj = super().__new__(cls, name)
        obj.reason = reason
        obj.lines = tuple(lines)
        obj.through = tuple(through)
        return obj


def vertices_on_line(polygon: CirclePolygon, key) -> tuple:
    """The vertices (storage indices) whose direction from C lies on the line ``key``
    (a line key of :func:`exactsym.paper.polygon.definition_mirrors`, or a
    :class:`~exactsym.paper.keys.LineKey`: compared without a division)."""
    if isinstance(key, LineKey):
        return tuple(i for i, d in enumerate(polygon.directions)
                     if line_key(polygon.polar, d) == key)
    return tuple(i for i, d in enumerate(polygon.directions)
                 if line_value(polygon.polar, d) == key)


def polygon_type(polygon: CirclePolygon, mirrors=None):
    """The type (Section 3, after ``lemma-sym-regular``: ``type-0`` .. ``type-4``) of a
    straight symmetric polygon by its definition, or None when the polygon has no line of
    straight symmetry (a skew-only or asymmetric polygon has no type).

    ``mirrors``: its lines of straight symmetry as line keys or
    :class:`~exactsym.paper.keys.LineKey`\\ s, default the exact mirrors of the definition
    (:func:`exactsym.paper.polygon.definition_mirror_keys`); the family layer passes its
    O(n) :func:`exactsym.paper.family.mirror_lines`.  The lines the
    CW/ACW strings find (:func:`straight_lines`) are *not* used: they can exceed the
    mirrors (``lemma-straight-sym``, reported separately as ``lines_by_strings``).

    Rules: regular -> type 0.  Even n (a mirror passes through 0 or 2 vertices): exactly
    two mirrors, both through no vertex -> type 1 (two mirrors of an inscribed polygon
    are perpendicular, else their product would be a rotation of order > 2 and there
    would be more mirrors); exactly one mirror -> type 2 (through two vertices or two
    edge midpoints); otherwise "unclassified" (``obs-exh-poly`` says this never
    happens).  Odd n (every mirror passes through exactly one vertex and one edge
    midpoint, ``proofs/check_symmetry_odd.md``): one mirror -> type 3; k > 1 mirrors ->
    type 4 (k divides n, k < n as the polygon is not regular, so n is composite).  An
    odd polygon is therefore never unclassified."""
    if mirrors is None:
        mirrors = definition_mirror_keys(polygon)
    mirrors = list(mirrors)
    n = polygon.n
    if not mirrors:
        return None
    count = len(mirrors)
    on_line: dict = {}
    for d in polygon.directions:            # LineKeys: no division
        k = line_key(polygon.polar, d)
        on_line[k] = on_line.get(k, 0) + 1
    through = [on_line.get(key if isinstance(key, LineKey) else LineKey.of(key), 0)
               for key in mirrors]
    if is_regular(polygon):
        return TypeVerdict("type-0", "regular", mirrors, through)
    on_vertices = sum(1 for t in through if t)
    if n % 2 == 0:
        if count == 2 and on_vertices == 0:
            return TypeVerdict("type-1", "even, two (perpendicular) mirrors through no "
                               "vertex", mirrors, through)
        if count == 1:
            where = "two vertices" if through[0] == 2 else "two edge midpoints"
            return TypeVerdict("type-2", f"even, one mirror, through {where}", mirrors,
                               through)
        return TypeVerdict("unclassified", f"even, not regular, {count} mirrors "
                           f"({on_vertices} through vertices)", mirrors, through)
    if count == 1:
        return TypeVerdict("type-3", "odd, one mirror, through a vertex and an edge midpoint",
                           mirrors, through)
    return TypeVerdict("type-4", f"odd, not regular, {count} mirrors (n = {n} composite)",
                       mirrors, through)
