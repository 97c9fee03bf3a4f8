"""Section 3 and Section 4.1 of the paper for one convex polygon inscribed in a circle.

Everything here follows the paper's words; where the paper is ambiguous the
reading chosen is stated in the docstring and in ``docs/interpretations.md``.
This module never imports the ground truth (:mod:`exactsym.symmetry`).

Strings (Section 3, before ``lemma-straight-sym``)
--------------------------------------------------
For a point m where a line meets the polygon, "the vertices are labeled starting
from the vertex next (clockwise) to m up to the previous vertex of m, as
v_1, ..., v_n" (n = k-1 for a vertex m, n = k for a point m on an edge) and
``CW_m = (|m v_1|, ..., |m v_n|)``, ``ACW_m`` its reverse.  Our polygons are stored
counter-clockwise, so for the observer of ``orientation = +1`` (same handedness
as the file's axes) "next clockwise" is the previous index; an observer of the
other handedness (``orientation = -1``) swaps CW and ACW.  Distances are exact
*keys* (:mod:`.circle_polygon`): strictly increasing maps preserve equality and
lexicographic order, which is all the paper uses.  For m on an edge we take the
edge's midpoint (where the edge's perpendicular bisector meets the polygon).

Two facts used throughout (proved in ``docs/interpretations.md``):

* equal chord strings do not always mean congruent views: a chord length
  ``2r sin(pi d)`` does not tell an arc d from its complement 1-d.  For a string
  of odd length (a vertex of an even polygon, an edge point of an odd polygon)
  ``CW_m = ACW_m`` says nothing about the middle vertex, so it does *not* imply a
  mirror through m; and two vertices may have equal strings with no isometry
  mapping one to the other (the farthest vertex read on the other side);
* a string is determined by its *canonical angle sequence*: read each chord as
  the arc below half a turn up to the first maximum of the string, as the
  complement after it.  :func:`string_classes` groups the 2n vertex strings by
  this canonical form in near-linear time (rolling hashes proposing, exact
  comparison deciding), and is proved equal to the literal strings by tests.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from ..exact import fmpq, normal_turn, sign
from ..strings import cyclic_period, first_occurrence
from .circle_polygon import CirclePolygon, polygon_from_directions

__all__ = [
    "cw_string", "acw_string", "cw_string_edge", "acw_string_edge", "vertex_strings",
    "edge_strings", "is_straight_symmetric", "is_skew_symmetric", "is_symmetric",
    "definition_mirrors", "theorem1_asymmetric", "theorem1_1_asymmetric",
    "theorem1_violations", "string_classes", "string_classes_reference",
    "vertex_palindromes", "edge_palindromes", "StraightLine", "straight_lines",
    "is_regular", "TypeVerdict", "polygon_type", "CheckResult",
    "check_symmetry_odd", "check_symmetry_even", "check_symmetry",
    "check_symmetry_odd_reference", "check_symmetry_even_reference",
    "check_symmetry_odd_literal", "SymLeader", "elect_leader_sym", "MoveResult",
    "make_sym_to_asym", "AsymLeader", "elect_leader_asym", "remove_vertex",
    "reflect_polygon",
]

_HALF = fmpq(1, 2)


# ============================================================ directions (exact)
def _cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def _dot(u, v):
    return u[0] * v[0] + u[1] * v[1]


def _ccw_angle_key(polygon: CirclePolygon, a, b):
    """An exact key, strictly increasing in the counter-clockwise angle from direction a
    to direction b, taken in (0, 1] turns (a full turn when a == b)."""
    return ccw_gap_key(polygon.polar, a, b)


def ccw_gap_key(polar: bool, a, b):
    """:func:`_ccw_angle_key` for bare directions: turns when ``polar``, else exact vectors."""
    if polar:
        d = normal_turn(b - a)
        return d if d != 0 else fmpq(1)
    c, d = sign(_cross(a, b)), _dot(a, b)
    if c > 0:
        return (0, -sign(d) * d * d / (_dot(a, a) * _dot(b, b)))
    if c < 0:
        return (2, sign(d) * d * d / (_dot(a, a) * _dot(b, b)))
    return (1, 0) if sign(d) < 0 else (3, 0)


def _below_half(polygon: CirclePolygon, a, b, ccw: bool) -> int:
    """-1, 0, 1: the angle from a to b (counter-clockwise if ``ccw``, else clockwise)
    compared with half a turn; a != b."""
    if polygon.polar:
        d = normal_turn(b - a) if ccw else normal_turn(a - b)
        return -1 if d < _HALF else (0 if d == _HALF else 1)
    c = sign(_cross(a, b))
    c = c if ccw else -c
    return -1 if c > 0 else (1 if c < 0 else 0)


def _reflect(polygon: CirclePolygon, w, axis):
    """Direction of w reflected across the line through C and direction ``axis``."""
    if polygon.polar:
        return normal_turn(2 * axis - w)
    ux, uy = axis
    a, b = ux * ux - uy * uy, 2 * ux * uy        # u^2 as a complex number; u^2 conj(w)
    return (a * w[0] + b * w[1], b * w[0] - a * w[1])


def _line_key(polygon: CirclePolygon, direction):
    """Exact hashable key of the line through C with this direction."""
    if polygon.polar:
        t = normal_turn(direction)
        return t - _HALF if t >= _HALF else t
    x, y = direction
    return _line_key_dir((x * x - y * y, 2 * x * y))     # the doubled angle's ray


def _perpendicular(polygon: CirclePolygon, direction):
    if polygon.polar:
        return normal_turn(direction + fmpq(1, 4))
    return (-direction[1], direction[0])


# ============================================================ the paper's strings
def _check_orientation(orientation: int) -> None:
    if orientation not in (1, -1):
        raise ValueError("orientation must be +1 or -1")


def cw_string(polygon: CirclePolygon, m: int, orientation: int = 1) -> tuple:
    """CW_m for the vertex m: distances (keys) from m to v_1..v_{k-1}, v_1 next clockwise."""
    _check_orientation(orientation)
    k = polygon.n
    return tuple(polygon.separation(m, (m - orientation * s) % k) for s in range(1, k))


def acw_string(polygon: CirclePolygon, m: int, orientation: int = 1) -> tuple:
    """ACW_m for the vertex m: CW_m reversed."""
    return cw_string(polygon, m, orientation)[::-1]


def cw_string_edge(polygon: CirclePolygon, e: int, orientation: int = 1) -> tuple:
    """CW_m for m the midpoint of edge e = (e, e+1) (storage order, counter-clockwise):
    distances to v_1..v_k, v_1 the endpoint next clockwise to m."""
    _check_orientation(orientation)
    k = polygon.n
    first = e if orientation == 1 else e + 1
    return tuple(polygon.separation_from_edge(e, (first - orientation * s) % k) for s in range(k))


def acw_string_edge(polygon: CirclePolygon, e: int, orientation: int = 1) -> tuple:
    return cw_string_edge(polygon, e, orientation)[::-1]


def vertex_strings(polygon: CirclePolygon, orientation: int = 1) -> list[tuple[tuple, tuple]]:
    """``[(CW_v, ACW_v) for every vertex v]`` (storage order): O(n^2) keys."""
    out = []
    for i in range(polygon.n):
        cw = cw_string(polygon, i, orientation)
        out.append((cw, cw[::-1]))
    return out


def edge_strings(polygon: CirclePolygon, orientation: int = 1) -> list[tuple[tuple, tuple]]:
    out = []
    for e in range(polygon.n):
        cw = cw_string_edge(polygon, e, orientation)
        out.append((cw, cw[::-1]))
    return out


# ============================================================ definitions, exactly
def _direction_set(polygon: CirclePolygon):
    if polygon.polar:
        return set(polygon.directions)
    return {_line_key_dir(d) for d in polygon.directions}


def _line_key_dir(d):
    """Exact hashable key of the *ray* of direction d (not the line)."""
    x, y = d
    if sign(x) != 0:
        return (sign(x), y / x)
    return (0, sign(y))


def _maps_onto_itself(polygon: CirclePolygon, image) -> bool:
    dirs = _direction_set(polygon)
    if polygon.polar:
        return all(image(t) in dirs for t in polygon.directions)
    return all(_line_key_dir(image(d)) in dirs for d in polygon.directions)


def definition_mirrors(polygon: CirclePolygon) -> list:
    """The lines of straight symmetry of ``def-straight-symmetric-poly`` (as line keys),
    computed from the definition with exact reflections.  Lines of symmetry of a
    polygon pass through its centre C (``lemma-LOS-Passes-CenterSECP``; the line through
    both points of a 2-gon is excluded by the definition: it contains all the points);
    a single vertex has exactly the line through C (the paper's note).  O(n^2).

    Candidates: the reflection mapping vertex 0 to vertex j, for each j.  Polar:
    t -> t_0 + t_j - t.  Cartesian, as complex numbers: w -> z_0 z_j conj(w) (up to a
    positive factor, which directions ignore), whose axis is the line whose doubled
    angle is the direction of z_0 z_j."""
    n = polygon.n
    if n == 0:
        return []
    if n == 1:
        return [_line_key(polygon, polygon.directions[0])]
    found = {}
    d0 = polygon.directions[0]
    for dj in polygon.directions:
        if polygon.polar:
            image = (lambda c: lambda t: normal_turn(c - t))(d0 + dj)
            key = _line_key(polygon, (d0 + dj) / 2)
        else:
            a = d0[0] * dj[0] - d0[1] * dj[1]
            b = d0[0] * dj[1] + d0[1] * dj[0]
            image = (lambda a, b: lambda w: (a * w[0] + b * w[1], b * w[0] - a * w[1]))(a, b)
            key = _line_key_dir((a, b))
        if _maps_onto_itself(polygon, image):
            found[key] = True
    if n == 2:      # the line through both points contains all of them: not a line of symmetry
        found.pop(_line_key(polygon, polygon.directions[0]), None)
    return list(found)


def is_straight_symmetric(polygon: CirclePolygon) -> bool:
    """``def-straight-symmetric-poly``: the vertex set has a line of straight symmetry."""
    return bool(definition_mirrors(polygon))


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
        return _maps_onto_itself(polygon, lambda t: normal_turn(t + _HALF))
    return _maps_onto_itself(polygon, lambda d: (-d[0], -d[1]))


def is_symmetric(polygon: CirclePolygon) -> bool:
    """``def-symmetric-poly``: straight or skew symmetric (a single point is symmetric)."""
    return polygon.n == 1 or is_straight_symmetric(polygon) or is_skew_symmetric(polygon)


# ============================================================ Theorem 1
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


# ============================================================ string classes
def string_classes_reference(polygon: CirclePolygon, orientation: int = 1):
    """``(cw, acw)`` class ids from the literal strings: CW_i == CW_j iff cw[i] == cw[j],
    CW_i == ACW_j iff cw[i] == acw[j].  O(n^2) keys."""
    ids: dict = {}
    cw, acw = [], []
    for a, b in vertex_strings(polygon, orientation):
        cw.append(ids.setdefault(a, len(ids)))
        acw.append(ids.setdefault(b, len(ids)))
    return cw, acw


_MOD = (1 << 61) - 1
_BASE = 1_000_003


class _Hasher:
    """Polynomial hashes of windows of an int list (they only *propose* equalities)."""

    def __init__(self, seq: Sequence[int]):
        self.seq = list(seq)
        pre = [0]
        for x in self.seq:
            pre.append((pre[-1] * _BASE + x) % _MOD)
        self.pre = pre

    def window(self, start: int, length: int, powers) -> int:
        return (self.pre[start + length] - self.pre[start] * powers[length]) % _MOD


def _gap_ids(polygon: CirclePolygon):
    ids: dict = {}
    n = polygon.n
    h = [ids.setdefault(_ccw_angle_key(polygon, polygon.directions[b],
                                       polygon.directions[(b + 1) % n]), len(ids) + 1)
         for b in range(n)]
    return ids, h


def string_classes(polygon: CirclePolygon, orientation: int = 1):
    """``(cw, acw)`` class ids of the 2n vertex strings (as :func:`string_classes_reference`),
    in O(n log n) plus O(n) per string equal to an earlier one of another rotation.

    Method: a string CW_i is the sequence d_s = min(theta_s, 1 - theta_s) of the clockwise
    angles theta_s from v_i; it determines the *canonical* reading (theta_s = d_s up to
    the first maximum of d, 1 - d_s after), which differs from the true angles in at
    most one place (the first vertex past half a turn, when it is nearer than the one
    before).  Two strings are equal iff their canonical gap sequences are equal; these
    are rotations of the polygon's gap sequence with at most two entries changed, hashed
    in O(1) each, and every equality the hashes propose is decided by exact comparison.
    """
    _check_orientation(orientation)
    n = polygon.n
    if n <= 3:
        return string_classes_reference(polygon, orientation)
    dirs = polygon.directions
    ids, h = _gap_ids(polygon)
    r_seq = h[::-1]                         # R[k] = h(n-1-k): clockwise reading
    bases = {True: h + h, False: r_seq + r_seq}    # ccw -> H, cw -> R
    hashers = {key: _Hasher(seq) for key, seq in bases.items()}
    powers = [1]
    for _ in range(n + 1):
        powers.append(powers[-1] * _BASE % _MOD)

    def canonical(i: int, ccw: bool):
        """(base, start, patches) of the canonical gap sequence of the string of v_i
        read counter-clockwise (ACW_i) or clockwise (CW_i)."""
        step = 1 if ccw else -1
        start = i if ccw else (n - i) % n

        def w(s):
            return (i + step * s) % n
        lo, hi = 0, n - 1           # p = number of s in 1..n-1 with angle < 1/2
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if _below_half(polygon, dirs[i], dirs[w(mid)], ccw) < 0:
                lo = mid
            else:
                hi = mid - 1
        p = lo
        f = p + 1
        if f > n - 1 or _below_half(polygon, dirs[i], dirs[w(f)], ccw) <= 0:
            return ccw, start, ()
        if p > 0 and not polygon.separation(i, w(f)) > polygon.separation(i, w(p)):
            return ccw, start, ()
        flipped = _reflect(polygon, dirs[w(f)], dirs[i])
        before = dirs[w(f - 1)]
        after = dirs[w(f + 1)]              # w(n) = i
        if ccw:
            g1 = _ccw_angle_key(polygon, before, flipped)
            g2 = _ccw_angle_key(polygon, flipped, after)
        else:
            g1 = _ccw_angle_key(polygon, flipped, before)
            g2 = _ccw_angle_key(polygon, after, flipped)
        return ccw, start, ((f - 1, ids.setdefault(g1, len(ids) + 1)),
                            (f, ids.setdefault(g2, len(ids) + 1)))

    def hash_of(form) -> int:
        base, start, patches = form
        value = hashers[base].window(start, n, powers)
        seq = bases[base]
        for q, new in patches:
            value = (value + (new - seq[start + q]) * powers[n - 1 - q]) % _MOD
        return value

    def materialise(form) -> list:
        base, start, patches = form
        seq = bases[base][start:start + n]
        for q, new in patches:
            seq[q] = new
        return seq

    period = cyclic_period(h)
    mirror = first_occurrence(r_seq, h + h[:-1])     # R rotated 0 == H rotated `mirror`

    def true_equal(a, b) -> bool:
        """The true (unpatched) angle sequences of the forms a, b are equal (exact: from
        the period of the gap sequence and one occurrence of its reversal)."""
        sa, sb = a[1], b[1]
        if a[0] != b[0]:
            if mirror is None:
                return False
            if not a[0]:
                sa = (mirror + sa) % n
            else:
                sb = (mirror + sb) % n
        return (sa - sb) % period == 0
    forms = [canonical(i, False) for i in range(n)] + [canonical(i, True) for i in range(n)]
    groups: dict = {}
    classes = []
    next_id = 0
    for form in forms:
        key = hash_of(form)
        members = groups.setdefault(key, [])
        cls = None
        mine = None
        for rep in members:
            rep_form = rep[0]
            if true_equal(rep_form, form):
                cls = rep[1]            # equal angle sequences: equal strings
                break
            if mine is None:
                mine = materialise(form)
            if rep[2] is None:
                rep[2] = materialise(rep_form)
            if rep[2] == mine:
                cls = rep[1]
                break
        if cls is None:
            cls = next_id
            next_id += 1
            members.append([form, cls, mine])
        classes.append(cls)
    cw, acw = classes[:n], classes[n:]
    if orientation == -1:
        cw, acw = acw, cw
    return cw, acw


# ============================================================ palindromes and lines
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
    ids, h = _gap_ids(polygon)
    hh = h + h
    rr = h[::-1] * 2
    powers = [1]
    for _ in range(n + 1):
        powers.append(powers[-1] * _BASE % _MOD)
    fwd, bwd = _Hasher(hh), _Hasher(rr)
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
        found.setdefault(_line_key(polygon, polygon.directions[i]), []).append(("vertex", i))
    if n >= 2:
        for e in edge_palindromes(polygon, reference):
            w = polygon.edge_direction(e)
            if w is None:
                w = _perpendicular(polygon, polygon.directions[e])
            found.setdefault(_line_key(polygon, w), []).append(("edge", e))
    vkeys: dict = {}
    for i, d in enumerate(polygon.directions):
        vkeys.setdefault(_line_key(polygon, d), []).append(i)
    ekeys: dict = {}
    if n >= 2:
        for e in range(n):
            w = polygon.edge_direction(e)
            if w is None:
                w = _perpendicular(polygon, polygon.directions[e])
            ekeys.setdefault(_line_key(polygon, w), []).append(e)
    return [StraightLine(key, tuple(vkeys.get(key, ())), tuple(ekeys.get(key, ())), tuple(at))
            for key, at in found.items()]


def is_regular(polygon: CirclePolygon) -> bool:
    """All angular gaps between consecutive vertices equal (a single vertex, and two
    diametrically opposite vertices, are regular)."""
    n = polygon.n
    if n <= 1:
        return True
    keys = {_ccw_angle_key(polygon, polygon.directions[b], polygon.directions[(b + 1) % n])
            for b in range(n)}
    return len(keys) == 1


def _is_prime(n: int) -> bool:
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
    if not _is_prime(n) and 1 < count < n:
        return TypeVerdict("type-4", f"odd composite, {count} lines", lines)
    return TypeVerdict("unclassified", f"odd, not regular, {count} lines, n = {n}"
                       + (" prime" if _is_prime(n) else ""), lines)


def _perpendicular_keys(polygon: CirclePolygon, a, b) -> bool:
    if polygon.polar:
        return normal_turn(a - b) in (fmpq(1, 4), fmpq(3, 4))
    # line keys are rays of the doubled angle: perpendicular lines have opposite rays
    return a == ((-b[0], b[1]) if b[0] != 0 else (0, -b[1]))


# ============================================================ Check_Symmetry_*
@dataclass(frozen=True)
class CheckResult:
    """What Check_Symmetry_Odd / Check_Symmetry_Even report.

    ``degree``: the degree of symmetry as reported (``deg_sym`` for the odd check,
    ``deg_sym/2`` as an exact rational for the even check; 0 when asymmetric);
    ``deg_sym``: the raw counter; ``axis_vertices``: vertices with CW = ACW;
    ``terminated``/``steps``: for the literal odd loop, whether it stopped within the
    step bound."""
    symmetric: bool
    straight: bool
    skew: bool
    degree: object
    reports: tuple
    algorithm: str
    deg_sym: int
    axis_vertices: tuple = ()
    terminated: bool = True
    steps: int = 0


def _order(n: int, orientation: int) -> list[int]:
    """The paper's v_1..v_n as storage indices: counter-clockwise from index 0 for the
    observer +1, clockwise from index 0 for the observer -1."""
    return [(orientation * k) % n for k in range(n)]


def _odd_result(algorithm, deg_sym, axis, terminated=True, steps=0) -> CheckResult:
    if deg_sym > 0:
        reports = ("G is symmetric", f"The degree of symmetry is: {deg_sym}")
    else:
        reports = ("G is asymmetric",)
    if not terminated:
        reports += (f"(did not terminate within {steps} steps: the printed loop only "
                    "increments i when CW != ACW)",)
    return CheckResult(deg_sym > 0, deg_sym > 0, False, fmpq(deg_sym), reports, algorithm,
                       deg_sym, tuple(axis), terminated, steps)


def check_symmetry_odd_literal(polygon: CirclePolygon, orientation: int = 1,
                               max_steps: int | None = None) -> CheckResult:
    """Check_Symmetry_Odd *as printed* (Section 4.1)::

        deg_sym = 0; i = 1
        while i <= n: compute CW_vi, ACW_vi
            if CW_vi = ACW_vi: deg_sym = deg_sym + 1   else: i++

    i is only incremented in the else branch, so once some vertex has CW = ACW the loop
    never ends.  We run at most ``max_steps`` iterations (default 4n) and report
    ``terminated=False`` (a finding) instead of looping."""
    n = polygon.n
    if n % 2 == 0:
        raise ValueError("Check_Symmetry_Odd needs an odd number of vertices")
    max_steps = 4 * n if max_steps is None else max_steps
    v = _order(n, orientation)
    deg_sym, i, steps, axis = 0, 1, 0, []
    while i <= n:
        if steps >= max_steps:
            return _odd_result("Check_Symmetry_Odd (literal)", deg_sym, sorted(set(axis)),
                               False, steps)
        steps += 1
        cw = cw_string(polygon, v[i - 1], orientation)
        acw = cw[::-1]
        if cw == acw:
            deg_sym += 1
            axis.append(v[i - 1])
        else:
            i += 1
    return _odd_result("Check_Symmetry_Odd (literal)", deg_sym, sorted(axis), True, steps)


def check_symmetry_odd_reference(polygon: CirclePolygon, orientation: int = 1) -> CheckResult:
    """Check_Symmetry_Odd as evidently intended (i++ after every vertex), with the paper's
    strings: deg_sym = number of vertices with CW = ACW.  O(n^2)."""
    n = polygon.n
    if n % 2 == 0:
        raise ValueError("Check_Symmetry_Odd needs an odd number of vertices")
    axis = []
    for i in _order(n, orientation):
        cw = cw_string(polygon, i, orientation)
        if cw == cw[::-1]:
            axis.append(i)
    return _odd_result("Check_Symmetry_Odd", len(axis), sorted(axis))


def check_symmetry_odd(polygon: CirclePolygon, orientation: int = 1) -> CheckResult:
    """Check_Symmetry_Odd (intended reading, i++ after every vertex), efficient: the
    vertices with CW = ACW from :func:`string_classes`.  Reports the degree of symmetry =
    the number of such vertices; "symmetric" iff it is positive.  Note it never looks at
    conditions 2-3 of Theorem 1: a polygon with only rotational symmetry is reported
    asymmetric (as the definitions say, not as Theorem 1 says)."""
    n = polygon.n
    if n % 2 == 0:
        raise ValueError("Check_Symmetry_Odd needs an odd number of vertices")
    cw, acw = string_classes(polygon, orientation)
    axis = [i for i in range(n) if cw[i] == acw[i]]
    return _odd_result("Check_Symmetry_Odd", len(axis), axis)


def _even_result(deg_sym, st_sym, sk_sym, axis) -> CheckResult:
    reports = []
    degree = fmpq(deg_sym, 2)
    if deg_sym > 0 and st_sym:
        reports += ["G is straight symmetric", f"The degree of symmetry is: {degree}"]
    if deg_sym > 0 and sk_sym:
        reports += ["G is skew symmetric", f"The degree of symmetry is: {degree}"]
    if deg_sym == 0:
        reports.append("G is asymmetric")
    return CheckResult(deg_sym > 0, deg_sym > 0 and st_sym, deg_sym > 0 and sk_sym, degree,
                       tuple(reports), "Check_Symmetry_Even", deg_sym, tuple(axis))


def check_symmetry_even_reference(polygon: CirclePolygon, orientation: int = 1) -> CheckResult:
    """Check_Symmetry_Even exactly as printed (the paper's loops, O(n^3))::

        for i = 1..n: if CW_vi = ACW_vi: st_sym = True; deg_sym++
                      else for j = 1..i-1:
                          if CW_vi = CW_vj or CW_vi = ACW_vj or ACW_vi = CW_vj:
                              sk_sym = True; deg_sym++
        report deg_sym/2

    So deg_sym counts the vertices on a (string) mirror plus the pairs j < i, i not on
    one, with equal strings in either direction -- not twice the number of lines."""
    n = polygon.n
    if n % 2:
        raise ValueError("Check_Symmetry_Even needs an even number of vertices")
    v = _order(n, orientation)
    deg_sym, st_sym, sk_sym, axis = 0, False, False, []
    for i in range(1, n + 1):
        cw_i = cw_string(polygon, v[i - 1], orientation)
        acw_i = cw_i[::-1]
        if cw_i == acw_i:
            st_sym = True
            deg_sym += 1
            axis.append(v[i - 1])
        else:
            for j in range(1, i):
                cw_j = cw_string(polygon, v[j - 1], orientation)
                acw_j = cw_j[::-1]
                if cw_i == cw_j or cw_i == acw_j or acw_i == cw_j:
                    sk_sym = True
                    deg_sym += 1
    return _even_result(deg_sym, st_sym, sk_sym, sorted(axis))


def check_symmetry_even(polygon: CirclePolygon, orientation: int = 1) -> CheckResult:
    """Check_Symmetry_Even, same counts as :func:`check_symmetry_even_reference` from the
    string classes in near-linear time (see its docstring for what is counted)."""
    n = polygon.n
    if n % 2:
        raise ValueError("Check_Symmetry_Even needs an even number of vertices")
    cw, acw = string_classes(polygon, orientation)
    deg_sym, st_sym, sk_sym, axis = 0, False, False, []
    seen: dict = {}
    for i in _order(n, orientation):
        if cw[i] == acw[i]:
            st_sym = True
            deg_sym += 1
            axis.append(i)
        else:
            count = seen.get(cw[i], 0)
            if count:
                sk_sym = True
                deg_sym += count
        seen[cw[i]] = seen.get(cw[i], 0) + 1
        if acw[i] != cw[i]:
            seen[acw[i]] = seen.get(acw[i], 0) + 1
    return _even_result(deg_sym, st_sym, sk_sym, sorted(axis))


def check_symmetry(polygon: CirclePolygon, orientation: int = 1) -> CheckResult:
    """Check_Symmetry_Odd or Check_Symmetry_Even by the parity of n (efficient versions)."""
    if polygon.n % 2:
        return check_symmetry_odd(polygon, orientation)
    return check_symmetry_even(polygon, orientation)


# ============================================================ leader election
@dataclass(frozen=True)
class SymLeader:
    """Result of Elect_Leader_Sym: ``leader`` (storage index) or None, and the report."""
    leader: int | None
    label: object
    report: str
    check: CheckResult


def elect_leader_sym(polygon: CirclePolygon, orientation: int = 1,
                     degree: str = "paper") -> SymLeader:
    """Elect_Leader_Sym (Section 4.1), for a symmetric polygon.

    Odd n: Check_Symmetry_Odd; degree > 1: "not possible"; degree = 1: the vertex with
    CW = ACW.  Even n: Check_Symmetry_Even; degree > 1: "not possible"; degree = 1 and
    the line passes through a vertex: of the vertices v_i, v_j with CW = ACW return v_i if
    CW(v_i) > CW(v_j) (lexicographically) else v_j.

    ``degree="paper"`` uses the degree the check reports (for even n that is deg_sym/2,
    which for a line through two vertices is (n+2)/4, so the branch "degree = 1" is only
    reached for n = 2: a finding); ``degree="lines"`` uses the number of distinct lines
    found from the strings instead (the evident intent)."""
    check = check_symmetry(polygon, orientation)
    n = polygon.n
    if degree == "lines":
        deg = fmpq(len(straight_lines(polygon)))
    elif degree == "paper":
        deg = check.degree
    else:
        raise ValueError("degree must be 'paper' or 'lines'")
    if not check.symmetric and degree == "paper":
        return SymLeader(None, None, "G is asymmetric: Elect_Leader_Sym does not apply", check)
    if deg > 1:
        return SymLeader(None, None, "Leader Election is not possible for G", check)
    axis = list(check.axis_vertices)
    if deg == 1 and n % 2 and len(axis) >= 1:
        return SymLeader(axis[0], polygon.labels[axis[0]], "leader on the line of symmetry",
                         check)
    if deg == 1 and n % 2 == 0 and axis:
        if len(axis) == 1:
            i = axis[0]
            return SymLeader(i, polygon.labels[i], "one vertex on the line of symmetry", check)
        vi, vj = axis[0], axis[1]
        VI, VJ = cw_string(polygon, vi, orientation), cw_string(polygon, vj, orientation)
        win = vi if VI > VJ else vj
        return SymLeader(win, polygon.labels[win], "VI > VJ" if win == vi else "VI <= VJ",
                         check)
    return SymLeader(None, None, "Leader Election is not possible for G", check)


@dataclass(frozen=True)
class MoveResult:
    """Make_SymToAsym: the leader moved along the circle.  ``parameter`` is the turn moved
    (polar) or the Pythagorean parameter tau of the rotation (Cartesian);
    ``asymmetric``: Theorem 1 says the new polygon is asymmetric."""
    leader: int | None
    label: object
    polygon: CirclePolygon
    parameter: object
    asymmetric: bool
    orientation: int


def _strictly_between(polygon: CirclePolygon, prev, new, nxt) -> bool:
    """``new`` lies strictly inside the counter-clockwise arc from prev to nxt."""
    a = _ccw_angle_key(polygon, prev, new)
    b = _ccw_angle_key(polygon, prev, nxt)
    return a < b and a != _ccw_angle_key(polygon, prev, prev)


def make_sym_to_asym(polygon: CirclePolygon, orientation: int = 1, degree: str = "paper",
                     max_halvings: int = 64) -> MoveResult:
    """Make_SymToAsym (Section 4.1): v_l = Elect_Leader_Sym(G); "move v_l, epsilon
    distance, to its right side, on the circumference of the circle inscribing G".

    Reading: "its right side" is the *clockwise* direction for the observer of the given
    handedness (orientation +1: clockwise in the file's frame).  Exact epsilon: polar,
    a rational turn delta = gap/4, gap the angle to the clockwise neighbour, halved until
    Theorem 1 says the result is asymmetric; Cartesian, the rotation with
    cos = (1 - tau^2)/(1 + tau^2), sin = 2 tau/(1 + tau^2) (tau = -orientation/4, halved
    until the point stays strictly between its neighbours and the result is asymmetric):
    rational rotations keep the point exactly on the circle in the same number field, for
    any radius.  Returns the leader None (and the polygon unchanged) when no leader is
    elected."""
    sym = elect_leader_sym(polygon, orientation, degree)
    n = polygon.n
    if sym.leader is None:
        return MoveResult(None, None, polygon, None, False, orientation)
    l = sym.leader
    dirs = list(polygon.directions)
    prev, nxt = dirs[(l - 1) % n], dirs[(l + 1) % n]
    if polygon.polar:
        gap = normal_turn(dirs[l] - prev) if orientation == 1 else normal_turn(nxt - dirs[l])
        if n == 1:
            gap = fmpq(1)
        delta = gap / 4
        for _ in range(max_halvings):
            dirs[l] = normal_turn(polygon.directions[l] - orientation * delta)
            moved = CirclePolygon(polygon.labels, tuple(dirs), True)
            moved = polygon_from_directions(moved.labels, moved.directions, True)
            if theorem1_asymmetric(moved):
                return MoveResult(l, polygon.labels[l], moved, -orientation * delta, True,
                                  orientation)
            delta /= 2
        return MoveResult(l, polygon.labels[l], moved, -orientation * delta, False, orientation)
    tau = fmpq(-orientation, 4)
    u = polygon.directions[l]
    moved = polygon
    for _ in range(max_halvings):
        c, s = (1 - tau * tau) / (1 + tau * tau), 2 * tau / (1 + tau * tau)
        new = (u[0] * c - u[1] * s, u[0] * s + u[1] * c)
        if n < 2 or _strictly_between(polygon, prev, new, nxt):
            dirs[l] = new
            moved = polygon_from_directions(polygon.labels, dirs, False)
            if theorem1_asymmetric(moved):
                return MoveResult(l, polygon.labels[l], moved, tau, True, orientation)
        tau /= 2
    return MoveResult(l, polygon.labels[l], moved, tau, False, orientation)


@dataclass(frozen=True)
class AsymLeader:
    """Elect_Leader_Asym: ``leader`` (storage index) or None, the vertex v_m of the
    lexicographic minimum, the ordering (storage indices) and whether the minimum was tied."""
    leader: int | None
    label: object
    v_m: int
    ordering: tuple
    direction: str
    tie: bool
    reading: str


def remove_vertex(polygon: CirclePolygon, i: int) -> CirclePolygon:
    """G \\ v_i: the polygon of the other vertices (same circle, same order)."""
    return CirclePolygon(polygon.labels[:i] + polygon.labels[i + 1:],
                         polygon.directions[:i] + polygon.directions[i + 1:], polygon.polar)


def elect_leader_asym(polygon: CirclePolygon, orientation: int = 1,
                      reading: str = "literal") -> AsymLeader:
    """Elect_Leader_Asym (Section 4.1) for an asymmetric polygon::

        for k: compute the tuple {CW(v_k), ACW(v_k)}
        {CW(v_m), ACW(v_m)} = lexicographic minimum of the tuples
        if CW(v_m) < ACW(v_m): CW(v_m) is the ordering of G else ACW(v_m) is
        i = 1; while G \\ v_i is symmetric: i++;  v_l = v_i

    ``reading="literal"``: the tuples are ordered pairs (CW, ACW), so the minimum is taken
    over the observer's clockwise strings first (depends on the handedness: tested);
    ``reading="unordered"``: the braces read as a set, each tuple sorted (min, max), which
    no reflection changes.  The ordering of G is v_m followed by the vertices in the order
    of the chosen string (v_1 = v_m); "G \\ v_i is symmetric" is decided by Theorem 1.  If
    every G \\ v_i is symmetric the loop runs past n: leader None."""
    _check_orientation(orientation)
    n = polygon.n
    strings = vertex_strings(polygon, orientation)
    if reading == "literal":
        tuples = [(cw, acw) for cw, acw in strings]
    elif reading == "unordered":
        tuples = [tuple(sorted((cw, acw))) for cw, acw in strings]
    else:
        raise ValueError("reading must be 'literal' or 'unordered'")
    order = _order(n, orientation)
    best = min(order, key=lambda k: tuples[k])
    tie = sum(1 for k in range(n) if tuples[k] == tuples[best]) > 1
    cw, acw = strings[best]
    step = -orientation if cw < acw else orientation
    direction = "CW" if cw < acw else "ACW"
    ordering = tuple((best + step * s) % n for s in range(n))
    for i in ordering:
        if theorem1_asymmetric(remove_vertex(polygon, i)):
            return AsymLeader(i, polygon.labels[i], best, ordering, direction, tie, reading)
    return AsymLeader(None, None, best, ordering, direction, tie, reading)


def reflect_polygon(polygon: CirclePolygon) -> CirclePolygon:
    """The mirror image across the x axis through C (labels kept), re-sorted."""
    if polygon.polar:
        return polygon_from_directions(polygon.labels,
                                       [normal_turn(-t) for t in polygon.directions], True)
    return polygon_from_directions(polygon.labels, [(x, -y) for x, y in polygon.directions],
                                   False)
