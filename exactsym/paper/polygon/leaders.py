"""Leader election on one polygon (Section 4.1): ``Elect_Leader_Sym`` (``1sym_le``),
``Make_SymToAsym``, ``Elect_Leader_Asym`` (``lem-asym-ord``).
"""

from __future__ import annotations

from dataclasses import dataclass

from ...exact import fmpq, normal_turn
from ..circle_polygon import CirclePolygon, polygon_from_directions
from ..keys import ccw_gap_key
from .check_symmetry import CheckResult, check_symmetry, visit_order
from .definitions import definition_mirror_keys, theorem1_asymmetric
from .types import vertices_on_line
from .strings import check_orientation, cw_string, vertex_strings


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
    the line passes through a vertex (by the definition: the unique exact mirror): of
    the vertices v_i, v_j on it (both have CW = ACW) return v_i if CW(v_i) > CW(v_j)
    (lexicographically) else v_j.

    ``degree="paper"`` uses the degree the check reports (for even n that is deg_sym/2,
    which for a line through two vertices is (n+2)/4, so the branch "degree = 1" is only
    reached for n = 2: a finding); ``degree="lines"`` uses the number of lines of
    straight symmetry instead (the evident intent), counted by the definition (exact
    mirrors, :func:`exactsym.paper.polygon.definition_mirrors`), not from the strings,
    which can find more lines than there are (``lemma-straight-sym``)."""
    check = check_symmetry(polygon, orientation)
    n = polygon.n
    if degree == "lines":
        deg = fmpq(len(definition_mirror_keys(polygon)))
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
    if deg == 1 and n % 2 == 0:
        # "the line of symmetry passes through either a single vertex or through two
        # vertices": a property without an algorithm, evaluated by the definition (the
        # unique exact mirror and the vertices on it); "find two vertices v_i and v_j
        # with CW = ACW" read as the vertices on that line (both have CW = ACW; other
        # vertices may too, by the free middle entry of an odd-length string)
        mirrors = definition_mirror_keys(polygon)
        on = vertices_on_line(polygon, mirrors[0]) if len(mirrors) == 1 else ()
        if not on:
            return SymLeader(None, None, "Leader Election is not possible for G (the line "
                             "of symmetry passes through no vertex)", check)
        if len(on) == 1:
            i = on[0]
            return SymLeader(i, polygon.labels[i], "one vertex on the line of symmetry", check)
        vi, vj = on[0], on[1]
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
    a = ccw_gap_key(polygon.polar, prev, new)
    b = ccw_gap_key(polygon.polar, prev, nxt)
    return a < b and a != ccw_gap_key(polygon.polar, prev, prev)


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
    halvings = max_halvings
    if n == 1 and max_halvings > 0 and not theorem1_asymmetric(polygon):
        # one vertex: its strings do not depend on where it stands (one gap, a full
        # turn), so no rotation makes it asymmetric and the loop below would run to its
        # end: only its last rotation is made (in a field of degree thousands each
        # rotation of the exact vector costs milliseconds)
        tau /= 2 ** (max_halvings - 1)
        halvings = 1
    for _ in range(halvings):
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
    out = CirclePolygon(polygon.labels[:i] + polygon.labels[i + 1:],
                        polygon.directions[:i] + polygon.directions[i + 1:], polygon.polar)
    if polygon.__dict__.get("one_circle") is True:
        out.__dict__["one_circle"] = True       # a subset of one circle: no length product
    return out


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
    check_orientation(orientation)
    n = polygon.n
    strings = vertex_strings(polygon, orientation)
    if reading == "literal":
        tuples = [(cw, acw) for cw, acw in strings]
    elif reading == "unordered":
        tuples = [tuple(sorted((cw, acw))) for cw, acw in strings]
    else:
        raise ValueError("reading must be 'literal' or 'unordered'")
    order = visit_order(n, orientation)
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
