"""The definitions of Section 3 evaluated exactly on one polygon
(``def-straight-symmetric-poly``, ``def-skew-symmetric-poly``, ``def-symmetric-poly``), and
Theorem 1 (``theorem1``: the string conditions for asymmetry).
"""

from __future__ import annotations

from ...exact import normal_turn
from ...exact.number import any_algebraic
from ...exact.ordering import value_key
from ...exact.fused import complex_product
from ..filtered import ball
from ..circle_polygon import CirclePolygon
from ..keys import HALF, LineKey, line_canon, line_key, line_value, ray_key
from .strings import string_classes


def _point_key(v) -> tuple:
    return (_number_key(v[0]), _number_key(v[1]))


_number_key = value_key          # equal iff the numbers are equal


def direction_set(polygon: CirclePolygon, scale=None):
    """The vertices' directions as a set of hashable keys: turns (polar); on one circle
    (:attr:`~exactsym.paper.circle_polygon.CirclePolygon.one_circle`) the vectors times
    ``scale`` themselves (no division); else the rays (:func:`exactsym.paper.keys.ray_key`)."""
    if polygon.polar:
        return set(polygon.directions)
    if scale is not None:
        return {_point_key((scale * d[0], scale * d[1])) for d in polygon.directions}
    return {ray_key(False, d) for d in polygon.directions}


def maps_onto_itself(polygon: CirclePolygon, image, scale=None) -> bool:
    """``image`` maps every vertex direction to a vertex direction.  Cartesian, on one
    circle of radius r: pass ``scale`` with |image(v)| = scale r for every vertex v; then
    image(v) points at a vertex iff it *equals* scale times that vertex's vector (same ray
    and same length), compared exactly without a division."""
    if polygon.polar:
        dirs = direction_set(polygon)
        return all(image(t) in dirs for t in polygon.directions)
    if scale is not None and polygon.one_circle:
        dirs = direction_set(polygon, scale)
        return all(_point_key(image(d)) in dirs for d in polygon.directions)
    dirs = direction_set(polygon)
    return all(ray_key(False, image(d)) in dirs for d in polygon.directions)


def definition_mirrors(polygon: CirclePolygon) -> list:
    """The lines of straight symmetry of ``def-straight-symmetric-poly`` (as line keys),
    computed from the definition with exact reflections: the values of
    :func:`definition_mirror_keys`."""
    return [key.value for key in definition_mirror_keys(polygon)]


def definition_mirror_keys(polygon: CirclePolygon) -> list:
    """The lines of straight symmetry of ``def-straight-symmetric-poly``, as
    :class:`~exactsym.paper.keys.LineKey`\\ s (no division), computed from the definition
    with exact reflections.  Lines of symmetry of a
    polygon pass through its centre C (``lemma-LOS-Passes-CenterSECP``; the line through
    both points of a 2-gon is excluded by the definition: it contains all the points);
    a single vertex has exactly the line through C (the paper's note).  O(n^2).

    Candidates: the reflection mapping vertex 0 to vertex j, for each j.  Polar:
    t -> t_0 + t_j - t.  Cartesian, as complex numbers: w -> z_0 z_j conj(w) (up to a
    positive factor, which directions ignore), whose axis is the line whose doubled
    angle is the direction of z_0 z_j.  Computed once per polygon (kept in its
    ``__dict__``: the report and Elect_Leader_Sym, in both orientations, ask again)."""
    known = polygon.__dict__.get("_definition_mirror_keys")
    if known is None:
        known = polygon.__dict__["_definition_mirror_keys"] = _definition_mirror_keys(polygon)
    return list(known)


def _definition_mirror_keys(polygon: CirclePolygon) -> list:
    n = polygon.n
    if n == 0:
        return []
    if n == 1:
        return [line_key(polygon.polar, polygon.directions[0])]
    found = {}
    d0 = polygon.directions[0]
    # on one circle of radius r, |z_0 z_j conj(w)| = r^2 |w|: the images are r^2 times
    # the reflected vertices
    scale = None if polygon.polar else d0[0] * d0[0] + d0[1] * d0[1]
    balls = _vertex_balls(polygon)
    for dj in polygon.directions:
        if polygon.polar:
            image = (lambda c: lambda t: normal_turn(c - t))(d0 + dj)
            if maps_onto_itself(polygon, image):
                found[LineKey.of(line_value(polygon.polar, (d0 + dj) / 2))] = True
        else:
            if balls is not None and _certainly_not_onto(balls, d0, dj):
                continue                    # the balls refute it: no exact product
            a, b = complex_product(d0, dj)      # fused: two reductions in a large field
            image = (lambda a, b: lambda w: (a * w[0] + b * w[1], b * w[0] - a * w[1]))(a, b)
            if maps_onto_itself(polygon, image, scale):
                found[LineKey(line_canon((a, b)), None, (a, b))] = True
    if n == 2:      # the line through both points contains all of them: not a line of symmetry
        found.pop(line_key(polygon.polar, polygon.directions[0]), None)
    return list(found)


def _vertex_balls(polygon: CirclePolygon):
    """Arb balls of the vertices of a Cartesian polygon on one circle with algebraic
    coordinates (a filter for :func:`definition_mirror_keys`), else None."""
    if polygon.polar or not polygon.one_circle or \
            not any_algebraic(c for d in polygon.directions for c in d):
        return None
    return [(ball(x), ball(y)) for x, y in polygon.directions]


def _certainly_not_onto(balls, d0, dj) -> bool:
    """The balls prove that w -> z_0 z_j conj(w) maps some vertex off every vertex's
    ray times r^2 (the test of :func:`maps_onto_itself` with its ``scale``): the exact
    image lies in the image ball, and a ball disjoint from every target ball cannot
    equal any target."""
    (x0, y0), (xj, yj) = (ball(d0[0]), ball(d0[1])), (ball(dj[0]), ball(dj[1]))
    a, b = x0 * xj - y0 * yj, x0 * yj + y0 * xj
    r2 = x0 * x0 + y0 * y0
    targets = [(r2 * x, r2 * y) for x, y in balls]
    for wx, wy in balls:
        ix, iy = a * wx + b * wy, b * wx - a * wy
        if not any(ix.overlaps(tx) and iy.overlaps(ty) for tx, ty in targets):
            return True
    return False


def is_straight_symmetric(polygon: CirclePolygon) -> bool:
    """``def-straight-symmetric-poly``: the vertex set has a line of straight symmetry."""
    return bool(definition_mirror_keys(polygon))


def is_skew_symmetric(polygon: CirclePolygon) -> bool:
    """``def-skew-symmetric-poly``, read as in ``docs/interpretations.md``: the skewed
    mirror image across L (reflect across L, then across L' perpendicular to L at the
    midpoint of the span of the points on L) is, for a line through the centre C with the
    midpoint taken at C, the point reflection about C; the polygon is skew symmetric iff
    that half-turn maps its vertex set onto itself (equivalently ``obs-parallel-edge-equal``:
    every edge has a parallel edge of equal length).  A single vertex is not skew symmetric."""
    if polygon.n < 2:
        return False
    if polygon.polar:
        return maps_onto_itself(polygon, lambda t: normal_turn(t + HALF))
    return maps_onto_itself(polygon, lambda d: (-d[0], -d[1]), 1)


def is_symmetric(polygon: CirclePolygon) -> bool:
    """``def-symmetric-poly``: straight or skew symmetric (a single point is symmetric)."""
    return polygon.n == 1 or is_straight_symmetric(polygon) or is_skew_symmetric(polygon)


def theorem1_violations(polygon: CirclePolygon, orientation: int = 1) -> dict:
    """Which conditions of Theorem 1 (``obs-asymmetric-polygon``) fail, with witnesses:
    ``{"1": [i with CW_i = ACW_i], "2": [(i, j) with CW_i = CW_j, i < j],
    "3": [(i, j) with CW_i = ACW_j, i != j]}`` (storage indices; the lists are quadratic in
    size for very symmetric polygons: use :func:`theorem1_asymmetric` for the verdict)."""
    cw, acw = string_classes(polygon, orientation)
    n = polygon.n
    c1 = [i for i in range(n) if cw[i] == acw[i]]
    by_cw: dict = {}
    by_acw: dict = {}
    for i in range(n):
        by_cw.setdefault(cw[i], []).append(i)
        by_acw.setdefault(acw[i], []).append(i)
    c2 = sorted((a, b) for group in by_cw.values() for x, a in enumerate(group)
                for b in group[x + 1:])
    c3 = sorted((i, j) for i in range(n) for j in by_acw.get(cw[i], ()) if j != i)
    return {"1": c1, "2": c2, "3": c3}


def theorem1_asymmetric(polygon: CirclePolygon, orientation: int = 1) -> bool:
    """Theorem 1 (``obs-asymmetric-polygon``): G is asymmetric iff (1) CW_i != ACW_i for all
    i, (2) CW_i != CW_j and (3) CW_i != ACW_j for all i != j.  Returns what the theorem's
    right-hand side says (True: "asymmetric")."""
    cw, acw = string_classes(polygon, orientation)
    n = polygon.n
    if any(cw[i] == acw[i] for i in range(n)) or len(set(cw)) < n:
        return False
    where: dict = {}
    for j in range(n):
        where.setdefault(acw[j], []).append(j)
    return not any(len(where.get(cw[i], ())) > 1 or where.get(cw[i], [i])[0] != i
                   for i in range(n))


def theorem1_1_asymmetric(polygon: CirclePolygon, orientation: int = 1) -> bool:
    """Theorem 1.1: (1) CW_i != ACW_i, (2) ACW_i != ACW_j, (3) ACW_i != CW_j (i != j).
    Equal to Theorem 1 because reversal is a bijection (the paper's note); computed
    separately from the classes so tests can confirm it."""
    cw, acw = string_classes(polygon, orientation)
    n = polygon.n
    if any(cw[i] == acw[i] for i in range(n)):
        return False
    if len(set(acw)) < n:
        return False
    cws: dict = {}
    for i in range(n):
        cws.setdefault(cw[i], []).append(i)
    return not any(j != i for i in range(n) for j in cws.get(acw[i], ()))
