"""The paper's strings of one polygon (Section 3, before ``lemma-straight-sym``):
CW/ACW strings of vertices and edge points, and their classes (:func:`string_classes`:
the 2n vertex strings grouped by canonical angle sequence in near-linear time, rolling
hashes proposing, exact comparison deciding; equal to the literal strings, tested).
See :mod:`exactsym.paper.polygon` for the readings.
"""

from __future__ import annotations

from typing import Sequence

from ...exact import fmpq, normal_turn
from ...geometry.strings import cyclic_period, first_occurrence
from ..circle_polygon import CirclePolygon
from ..filtered import circle_gap_tokens, cross_sign, gap_classes_on_circle
from ..inverses import squared_length
from . import small
from ...exact.number import any_algebraic, general_field, huge_field
from ..keys import HALF, ccw_gap_key
from ..ratio_keys import chord_key as ordered_chord_key


def below_half(polygon: CirclePolygon, a, b, ccw: bool) -> int:
    """-1, 0, 1: the angle from a to b (counter-clockwise if ``ccw``, else clockwise)
    compared with half a turn; a != b."""
    if polygon.polar:
        d = normal_turn(b - a) if ccw else normal_turn(a - b)
        return -1 if d < HALF else (0 if d == HALF else 1)
    c = cross_sign(a, b)                    # ball-filtered, exact
    c = c if ccw else -c
    return -1 if c > 0 else (1 if c < 0 else 0)


def reflect_direction(polygon: CirclePolygon, w, axis):
    """Direction of w reflected across the line through C and direction ``axis``."""
    if polygon.polar:
        return normal_turn(2 * axis - w)
    ux, uy = axis
    a, b = ux * ux - uy * uy, 2 * ux * uy        # u^2 as a complex number; u^2 conj(w)
    return (a * w[0] + b * w[1], b * w[0] - a * w[1])


def perpendicular(polygon: CirclePolygon, direction):
    if polygon.polar:
        return normal_turn(direction + fmpq(1, 4))
    return (-direction[1], direction[0])


def check_orientation(orientation: int) -> None:
    if orientation not in (1, -1):
        raise ValueError("orientation must be +1 or -1")


def cw_string(polygon: CirclePolygon, m: int, orientation: int = 1) -> tuple:
    """CW_m for the vertex m: distances (keys) from m to v_1..v_{k-1}, v_1 next clockwise.
    The keys are the polygon's :meth:`~exactsym.paper.circle_polygon.CirclePolygon.chord_key`:
    equal and ordered as the distances, comparable between strings of one polygon."""
    check_orientation(orientation)
    k = polygon.n
    if _ordered_chords(polygon):
        # the same keys held unmultiplied: balls order them
        return tuple(ordered_chord_key(polygon, m, (m - orientation * s) % k)
                     for s in range(1, k))
    return tuple(polygon.chord_key(m, (m - orientation * s) % k) for s in range(1, k))


def _ordered_chords(polygon: CirclePolygon) -> bool:
    """Whether the strings of ``polygon`` hold :func:`~exactsym.paper.ratio_keys.chord_key`
    keys: a Cartesian polygon in a huge field (:func:`exactsym.exact.number.huge_field`; off one circle,
    a radial projection's, each exact key is four products and two inverses in a tower
    over the sparse Q(zeta_N)), or off one circle in a field given by a minimal polynomial
    (:func:`exactsym.exact.number.general_field`: the gathering search's Q(gamma), where
    one inverse of a squared length cost seconds); decided once per polygon, so that
    every string of it holds one kind of key."""
    found = polygon.__dict__.get("_ordered_chords")
    if found is None:
        found = polygon.__dict__["_ordered_chords"] = not polygon.polar and \
            (any(huge_field(*d) for d in polygon.directions) or
             (any(general_field(*d) for d in polygon.directions) and not polygon.one_circle))
    return found


def acw_string(polygon: CirclePolygon, m: int, orientation: int = 1) -> tuple:
    """ACW_m for the vertex m: CW_m reversed."""
    return cw_string(polygon, m, orientation)[::-1]


def cw_string_edge(polygon: CirclePolygon, e: int, orientation: int = 1) -> tuple:
    """CW_m for m the midpoint of edge e = (e, e+1) (storage order, counter-clockwise):
    distances to v_1..v_k, v_1 the endpoint next clockwise to m (keys of
    :meth:`~exactsym.paper.circle_polygon.CirclePolygon.edge_key`: comparable within the
    strings of one edge point)."""
    check_orientation(orientation)
    k = polygon.n
    first = e if orientation == 1 else e + 1
    return tuple(polygon.edge_key(e, (first - orientation * s) % k) for s in range(k))


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


def string_classes_reference(polygon: CirclePolygon, orientation: int = 1):
    """``(cw, acw)`` class ids from the literal strings: CW_i == CW_j iff cw[i] == cw[j],
    CW_i == ACW_j iff cw[i] == acw[j].  O(n^2) keys."""
    ids: dict = {}
    cw, acw = [], []
    if polygon.n <= 8:
        # few strings: intern by exact equality, not by hashing (hashing a number of a
        # field of degree hundreds costs milliseconds; equality is a comparison)
        seen: list = []

        def intern(s):
            for t, k in seen:
                if t == s:
                    return k
            seen.append((s, len(seen)))
            return len(seen) - 1
        for a, b in vertex_strings(polygon, orientation):
            cw.append(intern(a))
            acw.append(intern(b))
        return cw, acw
    for a, b in vertex_strings(polygon, orientation):
        cw.append(ids.setdefault(a, len(ids)))
        acw.append(ids.setdefault(b, len(ids)))
    return cw, acw


HASH_MOD = (1 << 61) - 1


HASH_BASE = 1_000_003


class Hasher:
    """Polynomial hashes of windows of an int list (they only *propose* equalities)."""

    def __init__(self, seq: Sequence[int]):
        self.seq = list(seq)
        pre = [0]
        for x in self.seq:
            pre.append((pre[-1] * HASH_BASE + x) % HASH_MOD)
        self.pre = pre

    def window(self, start: int, length: int, powers) -> int:
        return (self.pre[start + length] - self.pre[start] * powers[length]) % HASH_MOD


def gap_classes(polygon: CirclePolygon):
    """``(ids, h)``: h[b] a positive integer per gap (v_b, v_b+1), equal iff the
    counter-clockwise angles are equal; ``ids`` maps the gap keys to them."""
    ids: dict = {}
    n = polygon.n
    dirs = polygon.directions
    if _circle_tokens(polygon):
        tokens = gap_classes_on_circle(dirs)
    else:
        tokens = [ccw_gap_key(polygon.polar, dirs[b], dirs[(b + 1) % n]) for b in range(n)]
    return ids, [ids.setdefault(t, len(ids) + 1) for t in tokens]


def _circle_tokens(polygon: CirclePolygon) -> bool:
    """Whether the gaps are told apart by :func:`.filtered.circle_gap_tokens`: a Cartesian
    polygon on one circle with algebraic coordinates.  Its :func:`ccw_gap_key` divides by
    the squared lengths, and in a tower of square roots over the sparse Q(zeta_N) that
    inverse is a dense quotient: two mirror pairs at turns +-2j/997, radii sqrt(k), took
    minutes per string partition."""
    return not polygon.polar and polygon.one_circle and \
        any_algebraic(c for d in polygon.directions for c in d)


def canonical(polygon: CirclePolygon, i: int, ccw: bool):
    """(base, start, patches) of the canonical gap sequence of the string of v_i
    read counter-clockwise (ACW_i) or clockwise (CW_i) (:func:`string_classes`); a patch
    is (position, (a, b)), the gap from direction a to b (one of them reflected), its
    class given by :func:`_gap_ids`."""
    n, dirs = polygon.n, polygon.directions
    step = 1 if ccw else -1
    start = i if ccw else (n - i) % n

    def w(s):
        return (i + step * s) % n
    lo, hi = 0, n - 1           # p = number of s in 1..n-1 with angle < 1/2
    while lo < hi:
        mid = (lo + hi + 1) // 2
        if below_half(polygon, dirs[i], dirs[w(mid)], ccw) < 0:
            lo = mid
        else:
            hi = mid - 1
    p = lo
    f = p + 1
    if f > n - 1 or below_half(polygon, dirs[i], dirs[w(f)], ccw) <= 0:
        return ccw, start, ()
    if p > 0 and not polygon.chord_key(i, w(f)) > polygon.chord_key(i, w(p)):
        return ccw, start, ()
    flipped = reflect_direction(polygon, dirs[w(f)], dirs[i])
    before = dirs[w(f - 1)]
    after = dirs[w(f + 1)]              # w(n) = i
    if ccw:
        return ccw, start, ((f - 1, (before, flipped)), (f, (flipped, after)))
    return ccw, start, ((f - 1, (flipped, before)), (f, (after, flipped)))


def _gap_ids(polygon: CirclePolygon, forms: list) -> tuple[list, list]:
    """``(h, forms)``: the class (a positive integer) of each gap (v_b, v_b+1), and
    ``forms`` with each patch's gap replaced by its class, classes equal iff the angles
    are.  On one circle (:func:`_circle_tokens`, squared radius L) a reflected direction
    u^2 conj(w) has length L^(3/2), so the polygon's own gaps are scaled by L to compare
    with the patches' (:func:`.filtered.circle_gap_tokens`): no division."""
    n, dirs = polygon.n, polygon.directions
    patches = [gap for form in forms for _, gap in form[2]]
    if _circle_tokens(polygon):
        length = squared_length(dirs[0])
        tokens = circle_gap_tokens([(dirs[b], dirs[(b + 1) % n], length) for b in range(n)] +
                                   [(a, b, None) for a, b in patches])
    else:
        tokens = [ccw_gap_key(polygon.polar, dirs[b], dirs[(b + 1) % n]) for b in range(n)] + \
            [ccw_gap_key(polygon.polar, a, b) for a, b in patches]
    ids: dict = {}
    classes = iter([ids.setdefault(t, len(ids) + 1) for t in tokens])
    h = [next(classes) for _ in range(n)]
    return h, [(base, start, tuple((q, next(classes)) for q, _ in patch))
               for base, start, patch in forms]


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
    check_orientation(orientation)
    n = polygon.n
    if n <= 3:
        if small.applies(polygon):          # entries compared by balls, exact on overlap
            return small.string_classes_small(polygon, orientation)
        return string_classes_reference(polygon, orientation)
    forms = [canonical(polygon, i, False) for i in range(n)] + \
        [canonical(polygon, i, True) for i in range(n)]
    h, forms = _gap_ids(polygon, forms)
    r_seq = h[::-1]                         # R[k] = h(n-1-k): clockwise reading
    bases = {True: h + h, False: r_seq + r_seq}    # ccw -> H, cw -> R
    hashers = {key: Hasher(seq) for key, seq in bases.items()}
    powers = [1]
    for _ in range(n + 1):
        powers.append(powers[-1] * HASH_BASE % HASH_MOD)

    def hash_of(form) -> int:
        base, start, patches = form
        value = hashers[base].window(start, n, powers)
        seq = bases[base]
        for q, new in patches:
            value = (value + (new - seq[start + q]) * powers[n - 1 - q]) % HASH_MOD
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
