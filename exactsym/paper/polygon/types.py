"""Lines of straight symmetry from palindromic strings and the polygon types of
Section 3 (``type-0`` .. ``type-4``, ``obs-sym-type-0``, ``lem-sym-type-01``).
"""

from __future__ import annotations

from dataclasses import dataclass

from ...exact import fmpq, normal_turn
from ..circle_polygon import CirclePolygon
from ..keys import ccw_gap_key, line_value
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


def is_regular(polygon: CirclePolygon) -> bool:
    """All angular gaps between consecutive vertices equal (a single vertex, and two
    diametrically opposite vertices, are regular)."""
    n = polygon.n
    if n <= 1:
        return True
    keys = {ccw_gap_key(polygon.polar, polygon.directions[b], polygon.directions[(b + 1) % n])
            for b in range(n)}
    return len(keys) == 1


def is_prime(n: int) -> bool:
    return n >= 2 and all(n % p for p in range(2, int(n ** 0.5) + 1))


class TypeVerdict(str):
    """``"type-0"`` .. ``"type-4"`` or ``"unclassified"``; ``.reason`` says why, ``.lines``
    are the straight lines counted."""
    reason: str
    lines: tuple

    def __new__(cls, name: str, reason: str, lines=()):
        obj = super().__new__(cls, name)
        obj.reason = reason
        obj.lines = tuple(lines)
        return obj


def polygon_type(polygon: CirclePolygon, lines: list[StraightLine] | None = None):
    """The type (Section 3, after ``lemma-sym-regular``) of a straight symmetric polygon, or
    None when the strings find no line of straight symmetry.

    type 0: regular; type 1: even, exactly two perpendicular straight lines through no
    vertex; type 2: even, exactly one straight line, through two vertices or two edges;
    type 3: odd, exactly one straight line, through a vertex and an edge; type 4: odd, n
    not prime, more than one and fewer than n lines.  Otherwise ``"unclassified"`` with a
    reason (``obs-exh-poly`` claims this never happens)."""
    if lines is None:
        lines = straight_lines(polygon)
    n = polygon.n
    if not lines:
        return None
    count = len(lines)
    if is_regular(polygon):
        return TypeVerdict("type-0", "regular", lines)
    through = [len(line.vertices) for line in lines]
    if n % 2 == 0:
        if count == 2 and all(t == 0 for t in through):
            a, b = lines
            if _perpendicular_keys(polygon, a.key, b.key):
                return TypeVerdict("type-1", "even, two perpendicular lines through no vertex",
                                   lines)
            return TypeVerdict("unclassified", "even, two lines through no vertex, not "
                               "perpendicular", lines)
        if count == 1:
            line = lines[0]
            if len(line.vertices) == 2 or (len(line.vertices) == 0 and len(line.edges) == 2):
                return TypeVerdict("type-2", "even, one line through two vertices or two edges",
                                   lines)
            return TypeVerdict("unclassified", f"even, one line through {len(line.vertices)} "
                               f"vertices and {len(line.edges)} edge midpoints", lines)
        return TypeVerdict("unclassified", f"even, not regular, {count} lines of straight "
                           f"symmetry ({sum(1 for t in through if t)} through vertices)", lines)
    if count == 1:
        line = lines[0]
        if len(line.vertices) == 1 and len(line.edges) == 1:
            return TypeVerdict("type-3", "odd, one line through a vertex and an edge", lines)
        return TypeVerdict("unclassified", f"odd, one line through {len(line.vertices)} "
                           f"vertices and {len(line.edges)} edge midpoints", lines)
    if not is_prime(n) and 1 < count < n:
        return TypeVerdict("type-4", f"odd composite, {count} lines", lines)
    return TypeVerdict("unclassified", f"odd, not regular, {count} lines, n = {n}"
                       + (" prime" if is_prime(n) else ""), lines)


def _perpendicular_keys(polygon: CirclePolygon, a, b) -> bool:
    if polygon.polar:
        return normal_turn(a - b) in (fmpq(1, 4), fmpq(3, 4))
    # line keys are rays of the doubled angle: perpendicular lines have opposite rays
    return a == ((-b[0], b[1]) if b[0] != 0 else (0, -b[1]))
