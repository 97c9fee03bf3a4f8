"""Ground truth: the symmetry group of a configuration as a finite subgroup of O(2).

Independent of the paper's algorithms (``docs/architecture.md``: ground truth and
paper-faithful code never share logic).  Every isometry mapping a finite set P
onto itself fixes the centre C of its smallest enclosing circle (the SEC of P is
unique, so it is mapped onto itself).  About C, the points of P lie on *rays*;
reading the rays counter-clockwise gives a cyclic string of symbols

    (squared radii of the points on ray i, angle from ray i to ray i + 1)

and an isometry fixing C maps P onto itself iff it maps this string onto
itself: the rotations are the cyclic periods of the string, the reflections the
occurrences in the doubled string of the string read clockwise (ray i with the
angle to its *previous* ray).  Both are found with the prefix function (KMP) in
linear time (or with one list comparison when the least symbol occurs once) after
an O(n log n) angular sort, so the whole computation is O(n log n) exact
operations.  Floats never decide anything: the angular sort is an exact sort,
which a float pre-sort only speeds up (:func:`sort_by_exact_keys`).

The centre is the SEC centre on both paths (rather than the centroid, which every
symmetry fixes too): the levels, and so the sparsest level of ``reference``, are
about it; one point set then gets the same ordering whether it is given in polar
or Cartesian form; and the exact centroid of many random rationals has a
denominator of thousands of digits.

Angles are held as exact, similarity-invariant keys that increase with the
angle: on the *polar path* (``levels_of(config).polar``: C is the origin and every
point is ``(r^2, turn)``) the rational turn itself; on the *Cartesian path* the
"diamond angle" :func:`pseudo_angle` of a vector (a rational function of its
coordinates, monotone in its angle), which for the angle between two rays u, v is
taken of ``(u . v, u x v)``.  Since both keys order angles as angles, the
canonical labelling (:attr:`SymmetryGroup.ordering`) of one point set is the same
whichever path computes it.

Canonical labelling (``ordering``): among the rotations of the string read
counter-clockwise and of the string read clockwise, take the lexicographically
least (symbols ordered by their radius tuple, then by their angle key; Booth's
algorithm); list the point at C first (if any), then the rays from the starting
ray in that orientation, the points of each ray by increasing distance from C.
Scaling multiplies every radius by one positive factor and keeps angles, so
this order is unchanged by any similarity, and a reflection only exchanges the
two orientations.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cmp_to_key
from typing import Iterator, Sequence

import numpy as np
from flint import arb, ctx

from ..geometry.configuration import Configuration, no_cycle_collection
from ..geometry.predicates import PseudoAngle, intern_by_value
from .isometries import Isometry, Layout, identity, reflection, rotation
from ..exact import fmpq
from ..exact.number import all_plain_rational, any_algebraic, enclosure, is_plain_rational
from ..exact.fused import complex_product, product_sum
from .symbols import Symbols, intern_symbols, least_rotation, rotation_less
from ..geometry.algebraic_filtered import certified_c1
from ..exact.context import Cache
from ..geometry.levels import Levels, RationalLevels, levels_of
from ..geometry.sec import LazyCentre
from .rays_filtered import SingletonRays, filtered_rays, firsts, \
    integer_pseudo_angle as _pseudo_angle_of_integers, level_ranks
from ..geometry.strings import cyclic_occurrences as occurrences, cyclic_period

__all__ = ["Isometry", "SymmetryGroup", "symmetry_group", "pseudo_angle", "least_rotation",
           "cyclic_period", "occurrences", "sort_by_exact_keys"]

# From this many rational Cartesian points the rays are grouped by certified floats
# (rays_filtered.py).  Measured (CPU per symmetry_group, levels given): random sets break
# even near 24 points (64: 0.2 ms against 0.6 ms exact), D4 orbits near 48 (64: 0.41
# against 0.54 ms; 1,024: 4.5 against 7.1 ms).
_FILTER_MIN = 64


@dataclass(frozen=True)
class SymmetryGroup:
    """The symmetry group of a configuration (``exactsym check``: ``group``, ``orderable``,
    ``ordering``, ``leader`` of ``docs/cli.md``).

    ``name``: ``"Ck"`` (k rotations, no mirror), ``"Dk"`` (k rotations, k mirrors)
    or ``"O2"`` for a single point (then ``rotations == mirrors == 0`` stand for
    "infinitely many" and :meth:`symmetries` yields the identity only).
    ``centre`` is fixed by every symmetry (the SEC centre).  ``reference``: a
    point, not at the centre, on the sparsest level (fewest points; the nearest
    such level on a tie); the Cartesian matrices are built from its images.
    ``orderable``: no symmetry moves any point (C1; D1 of a collinear set, whose
    mirror is its own line; a single point).  ``ordering``: the canonical
    labelling when orderable, else None.  ``leader``: the first of ``ordering``
    when orderable; else the point at the centre; else, for D1, the point on the
    mirror chosen canonically; else None (no point is fixed by every symmetry).
    """
    name: str
    rotations: int
    mirrors: int
    centre: tuple
    polar: bool
    rotation_generator: Isometry | None
    mirror: Isometry | None
    reference: int | None
    orderable: bool
    ordering: tuple[int, ...] | None
    leader: int | None
    _layout: Layout | None = field(default=None, repr=False, compare=False)

    def symmetries(self) -> Iterator[Isometry]:
        """All ``rotations + mirrors`` symmetries, generated lazily: the identity first,
        then the rotations by ``j/k`` turn (j = 1..k-1), then the reflections."""
        layout = self._layout
        if layout is None:          # O2: one point
            yield identity(self.polar, self.centre)
            return
        m = len(layout.rays)
        for j in range(self.rotations):
            yield rotation(layout, j * layout.period % m)
        for offset in layout.mirror_offsets:
            yield reflection(layout, offset)


# ---------------------------------------------------------------- exact angle keys

def pseudo_angle(x, y):
    """The diamond angle of the non-zero vector ``(x, y)``: an exact number in [0, 4)
    that strictly increases with the angle of the vector in [0, 2 pi), equal for equal
    directions, unchanged when the vector is multiplied by a positive number."""
    if y >= 0:
        if x > 0:
            return y / (x + y)
        return 1 + x / (x - y)              # x <= 0, y >= 0: 1 at (0, +), 2 at (-, 0)
    if x < 0:
        return 2 + y / (x + y)              # both negative: (2, 3)
    return 3 + x / (x - y)                  # x >= 0, y < 0: 3 at (0, -)


# ---------------------------------------------------------------- the rays

def sort_by_exact_keys(indices: list[int], keys: Sequence) -> None:
    """Sort ``indices`` in place by ``keys[i]``, exactly (a stable sort).

    The exact sort decides everything.  For many ``fmpq`` keys it is preceded by a sort
    on the keys' float values, which costs little (comparisons in C) and leaves the list
    nearly sorted, so that the exact sort (Timsort, which finds the sorted runs) needs
    little more than one exact comparison per element instead of log2(n): a float that
    is off, or equal for unequal keys, only leaves more work to the exact sort.
    """
    if len(indices) > 64 and is_plain_rational(keys[indices[0]]):
        try:
            approx = [float(keys[i]) for i in indices]      # a filter: the sort below decides
        except (OverflowError, ValueError):
            approx = None
        if approx is not None:
            order = sorted(range(len(indices)), key=approx.__getitem__)
            indices[:] = [indices[a] for a in order]
    indices.sort(key=keys.__getitem__)


def _polar_rays(polar):
    """``(centre_index, rays, ray_turns)`` of a polar configuration about the origin."""
    n = len(polar)
    centre_index = None
    turns = [t for _, t in polar]
    idx = []
    for i in range(n):
        if polar[i][0] == 0:
            centre_index = i
        else:
            idx.append(i)
    sort_by_exact_keys(idx, turns)
    rays, ray_turns = [], []
    start = 0
    for a in range(1, len(idx) + 1):
        if a == len(idx) or turns[idx[a]] != turns[idx[start]]:
            ray = idx[start:a]
            if len(ray) > 1:
                ray.sort(key=lambda i: polar[i][0])
            rays.append(tuple(ray))
            ray_turns.append(turns[idx[start]])
            start = a
    radii = [tuple(polar[i][0] for i in ray) for ray in rays]
    m = len(rays)
    gaps = [ray_turns[i + 1] - ray_turns[i] for i in range(m - 1)]
    if m:
        gaps.append(ray_turns[0] + 1 - ray_turns[-1])
    return centre_index, rays, ray_turns, radii, gaps


def _directions(points, centre, integers: bool, homogeneous=None):
    """``(centre_index, idx, vectors, r2s, keys)``: for each point i off the centre (listed
    in ``idx``) a vector pointing from the centre to it, its exact squared distance to
    the centre and the pseudo-angle of the vector.

    With ``integers`` (rational points and centre) each vector is scaled by its own
    positive integer so that it has integer coordinates: angles and pseudo-angles do
    not change, and integer arithmetic avoids a gcd after every operation."""
    n = len(points)
    centre_index = None
    keys, r2s, vectors = [None] * n, [None] * n, [None] * n
    idx = []
    cx, cy = centre
    if integers:
        den = cx.q * cy.q // cx.q.gcd(cy.q)                 # centre = (a, b) / den
        a, b = cx.p * (den // cx.q), cy.p * (den // cy.q)
        for i in range(n):
            x, y = points[i]
            qx, qy = x.q, y.q
            dx = (x.p * den - a * qx) * qy                 # (x - cx) * qx * qy * den
            dy = (y.p * den - b * qy) * qx
            if not dx and not dy:
                centre_index = i
                continue
            scale = qx * qy * den
            vectors[i] = (dx, dy)
            r2s[i] = fmpq(dx * dx + dy * dy, scale * scale)
            if dy >= 0:
                keys[i] = fmpq(dy, dx + dy) if dx > 0 else fmpq(2 * dx - dy, dx - dy)
            else:
                keys[i] = fmpq(2 * dx + 3 * dy, dx + dy) if dx < 0 else \
                    fmpq(4 * dx - 3 * dy, dx - dy)
            idx.append(i)
    else:
        cx, cy, cd = homogeneous if homogeneous is not None else (cx, cy, 1)
        for i in range(n):
            found = _point_about(points[i], cx, cy, cd)
            if found is None:
                centre_index = i
                continue
            vectors[i], r2s[i], keys[i] = found
            idx.append(i)
    return centre_index, idx, vectors, r2s, keys


_ABOUT = Cache("truth vectors")      # id(point) -> (point, cx, cy, cd, result): see _point_about
_ABOUT_LIMIT = 1 << 14


def _point_about(point, cx, cy, cd):
    """``(vector, squared length, pseudo-angle)`` of D (point - centre) for the centre
    (cx, cy) / cd (D = cd > 0: no division), or None at the centre.  Remembered per point
    *object* and centre objects (the entry holds them, so an id is never mistaken for
    another object's): the audit asks for the groups of many unions of levels about one
    centre, made of the very same point objects, and in a cyclotomic field of degree
    thousands each vector costs products of milliseconds."""
    about = _ABOUT.table()
    hit = about.get(id(point))
    if hit is not None and hit[0] is point and hit[1] is cx and hit[2] is cy \
            and hit[3] is cd:
        return hit[4]
    x, y = point
    dx, dy = cd * x - cx, cd * y - cy       # D (p - centre), D > 0: no division
    if dx == 0 and dy == 0:
        found = None
    else:
        found = ((dx, dy), product_sum([(dx, dx), (dy, dy)]), _Angle(dx, dy))  # no inverse
    if any_algebraic((dx, dy)):
        if len(about) >= _ABOUT_LIMIT:
            about.clear()
        about[id(point)] = (point, cx, cy, cd, found)
    return found


def _cartesian_rays(points, centre, integers: bool | None = None, homogeneous=None):
    """``(centre_index, rays, radii, gaps)`` about ``centre``: rays by pseudo-angle.
    ``integers`` (default: when the points and the centre are ``fmpq``) chooses the
    integer arithmetic of :func:`_directions`; both ways give the same result."""
    if integers is None:
        integers = all_plain_rational((centre[0], centre[1], points[0][0]))
    centre_index, idx, vectors, r2s, keys = _directions(points, centre, integers, homogeneous)
    if integers:
        sort_by_exact_keys(idx, keys)
    else:
        idx = _sorted_by_value(idx, keys)
    groups: list[list[int]] = []
    last = None
    for i in idx:
        key = keys[i]
        if last is not None and key == last:
            groups[-1].append(i)
        else:
            groups.append([i])
            last = key
    rays, radii = [], []
    for ray in groups:
        if len(ray) == 1:
            rays.append((ray[0],))
            radii.append((r2s[ray[0]],))
        else:
            ray.sort(key=r2s.__getitem__)
            rays.append(tuple(ray))
            radii.append(tuple([r2s[i] for i in ray]))
    m = len(rays)
    gaps = []
    if integers:
        for a in range(m):
            (ux, uy), (vx, vy) = vectors[rays[a][0]], vectors[rays[(a + 1) % m][0]]
            gaps.append(_pseudo_angle_of_integers(ux * vx + uy * vy, ux * vy - uy * vx))
    else:
        for a in range(m):
            gaps.append(_gap(vectors[rays[a][0]], vectors[rays[(a + 1) % m][0]]))
    return centre_index, rays, radii, gaps


class _Angle(PseudoAngle):
    """A :class:`PseudoAngle` that remembers its 64-bit Arb ball (the angles of
    :func:`_point_about` and :func:`_gap` are shared by many groups; in a field of degree
    thousands a ball costs milliseconds)."""

    __slots__ = ("_ball64",)

    def __init__(self, x, y):
        super().__init__(x, y)
        self._ball64 = None

    def ball(self, prec: int = 64):
        if prec != 64:
            return super().ball(prec)
        if self._ball64 is None:
            self._ball64 = super().ball(64)
        return self._ball64

    def _cmp(self, other) -> int:
        # a filter: disjoint remembered balls decide (each holds the exact value); only
        # overlapping ones reach the exact products of PseudoAngle._cmp
        if isinstance(other, _Angle):
            a, b = self.ball(), other.ball()
            if a < b:
                return -1
            if a > b:
                return 1
        return super()._cmp(other)


class _LazyGap(_Angle):
    """The pseudo-angle of (u.v, u x v) (:func:`_gap`) whose exact parts are made only
    when read (``quadrant``, ``num``, ``den``: an unset slot falls to ``__getattr__``).
    Its 64-bit ball is computed from the balls of u's and v's coordinates (Arb: it holds
    the exact value); the audit's unions of levels in a field of degree thousands compare
    most gaps by these balls alone, and each exact gap costs three products."""

    __slots__ = ("_u", "_v")

    def __init__(self, u, v):
        self._u, self._v = u, v
        self._ball64 = None

    def __getattr__(self, name):
        if name in ("quadrant", "num", "den"):
            (ux, uy), v = self._u, self._v
            # conj(u) v = (u.v, u x v): three products (Gauss), two reductions
            PseudoAngle.__init__(self, *complex_product((ux, -uy), v))
            return object.__getattribute__(self, name)
        raise AttributeError(name)

    def ball(self, prec: int = 64):
        if prec != 64:
            return PseudoAngle.ball(self, prec)
        if self._ball64 is None:
            self._ball64 = _gap_ball(self._u, self._v)
            if self._ball64 is None:               # a sign the balls leave open
                self._ball64 = PseudoAngle.ball(self, 64)
        return self._ball64


_BALLS = Cache("truth balls")      # id(number) -> (number, 64-bit ball): see _ball64


def _ball64(x):
    """The 64-bit Arb ball of a coordinate, remembered per object (a vector of
    :func:`_point_about` is shared by many gaps)."""
    balls = _BALLS.table()
    hit = balls.get(id(x))
    if hit is not None and hit[0] is x:
        return hit[1]
    ball = enclosure(x, 64)
    if len(balls) >= _ABOUT_LIMIT:
        balls.clear()
    balls[id(x)] = (x, ball)
    return ball


def _gap_ball(u, v):
    """A ball around the pseudo-angle of (u.v, u x v) from the coordinates' balls, or None
    when a sign that picks the quadrant (PseudoAngle's cases) is not decided by them."""
    if u is v:
        # one ray (a union of levels on one ray): u x u is 0 exactly and u.u > 0 (u is
        # not zero), so the pseudo-angle is exactly 0 (quadrant 0, num 0)
        return arb(0)
    with ctx.workprec(80):
        ux, uy, vx, vy = _ball64(u[0]), _ball64(u[1]), _ball64(v[0]), _ball64(v[1])
        x, y = ux * vx + uy * vy, ux * vy - uy * vx
        if y > 0:
            if x > 0:
                return y / (x + y)
            if x < 0:
                return 1 + (-x) / (y - x)
            return None
        if y < 0:
            if x < 0:
                return 2 + (-y) / (-(x + y))
            if x > 0:
                return 3 + x / (x - y)
        return None


def _sorted_by_value(indices: list, keys) -> list:
    """:func:`exactsym.geometry.predicates.sorted_by_value` (the same list), with each adjacent pair of
    the proposal first checked by the balls: a ball entirely below the next one proves
    the order, and only overlapping balls are compared exactly (products in the field)."""
    balls = {i: keys[i].ball() for i in indices}
    proposal = sorted(indices, key=lambda i: balls[i].mid())
    for a, b in zip(proposal, proposal[1:]):
        if balls[a] < balls[b] or keys[a] <= keys[b]:
            continue
        return sorted(indices, key=cmp_to_key(lambda a, b: keys[a]._cmp(keys[b])))
    return proposal


_GAPS = Cache("truth gaps")       # (id(u), id(v)) -> (u, v, gap): see _gap


def _gap(u, v) -> PseudoAngle:
    """The pseudo-angle of (u.v, u x v), the counter-clockwise angle from u to v, with
    three products (Gauss: conj(u) v) instead of four, remembered per pair of vector
    objects when they hold field elements (the vectors of :func:`_point_about` are
    shared by the audit's unions of levels, whose consecutive rays often recur)."""
    field = any_algebraic((u[0], u[1], v[0], v[1]))
    if field:
        gaps = _GAPS.table()
        hit = gaps.get((id(u), id(v)))
        if hit is not None and hit[0] is u and hit[1] is v:
            return hit[2]
    if field:
        gap = _LazyGap(u, v)
    else:
        (ux, uy), (vx, vy) = u, v
        k = vx * (ux - uy)
        gap = _Angle(k + uy * (vx + vy), k + ux * (vy - vx))
    if field:
        if len(gaps) >= _ABOUT_LIMIT:
            gaps.clear()
        gaps[(id(u), id(v))] = (u, v, gap)
    return gap


# ---------------------------------------------------------------- the group

def symmetry_group(config: Configuration, rings: Levels | None = None) -> SymmetryGroup:
    """The symmetry group of ``config`` (all isometries of the plane mapping its point
    set onto itself), with the canonical ordering and the leader of
    ``docs/cli.md``.  ``rings`` (from :func:`exactsym.geometry.levels.levels_of`) is
    computed when not given.  O(n log n) exact operations; never raises on a valid
    configuration.

    The centre is ``rings.sec.centre``.  Given ``Levels`` whose centre is not the SEC
    centre of ``config`` (say, that of a larger configuration), the result is the group
    of the isometries that fix that centre and map the points onto themselves, with
    ``reference`` taken from the sparsest of ``rings.levels``.

    >>> from exactsym import Configuration, symmetry_group
    >>> group = symmetry_group(Configuration.from_points([(1, 0), (0, 1), (-1, 0), (0, -1)]))
    >>> group.name, group.rotations, group.mirrors, group.orderable, group.leader
    ('D4', 4, 4, False, None)
    >>> kite = symmetry_group(Configuration.from_points([(0, 2), (1, 0), (0, -1), (-1, 0)]))
    >>> kite.name, kite.orderable, kite.leader   # robots 0 and 2 lie on the only mirror
    ('D1', False, 2)
    >>> len(list(kite.symmetries()))
    2
    """
    with no_cycle_collection():       # bulk construction: the collector's passes cost more
        return _symmetry_group(config, rings if rings is not None else levels_of(config))


def _symmetry_group(config: Configuration, ring: Levels) -> SymmetryGroup:
    if not ring.polar and ring.enclosures is not None \
            and ring.enclosures.points is config.points:
        certified = _certified_c1(config, ring)
        if certified is not None:
            return certified
    centre = ring.sec.centre
    n = config.n
    if n == 1 and (not config.polar[0][0] if ring.polar else config.points[0] == centre):
        return SymmetryGroup("O2", 0, 0, centre, ring.polar, None, None, None, True, (0,), 0)

    filtered = None
    if ring.polar:
        centre_index, rays, ray_turns, radii, gaps = _polar_rays(config.polar)
        points = None
    else:
        points = config.points
        filtered = None
        if n >= _FILTER_MIN and all_plain_rational((centre[0], centre[1], points[0][0])):
            rank = level_ranks(ring, n)
            if rank is not None:
                shared = ring.floats       # the floats of these very points, if computed
                floats = shared[1:] if shared is not None and shared[0] is points else None
                filtered = filtered_rays(points, centre, rank, floats)
        if filtered is not None:
            centre_index, rays, radii, gaps, gap_ids = filtered
        else:
            centre_index, rays, radii, gaps = _cartesian_rays(points, centre,
                                                              homogeneous=ring.sec.homogeneous)
        ray_turns = None
    m = len(rays)

    # symbols, interned: equal ids iff equal symbols; values are compared only lazily
    if filtered is None:
        ray_ids = intern_symbols(radii, True)
        gap_ids = intern_by_value(gaps) if gaps and isinstance(gaps[0], PseudoAngle) \
            else intern_symbols(gaps, False)
        width = max(gap_ids) + 1
        ccw = [ray_ids[i] * width + gap_ids[i] for i in range(m)]
        cw = [ray_ids[-i % m] * width + gap_ids[(-i - 1) % m] for i in range(m)]
        ccw_values, cw_values = Symbols(radii, gaps, False), Symbols(radii, gaps, True)
        least = ray_ids[radii.index(min(radii))]      # the least symbols are on these rays
    else:                       # ray and gap ids are ranks: symbols compare as their ids
        rid, gid = radii, np.asarray(gap_ids, dtype=np.int64)
        width = int(gid.max()) + 1
        back = (-np.arange(m)) % m
        ccw = (rid * width + gid).tolist()
        cw = (rid[back] * width + gid[(back - 1) % m]).tolist()
        ray_ids = rid.tolist()
        ccw_values, cw_values = ccw, cw
        least = int(rid.min())

    # canonical labelling: least rotation over both orientations
    rays_least = [r for r in range(m) if ray_ids[r] == least] if filtered is None else \
        np.flatnonzero(rid == least).tolist()
    s = least_rotation(ccw, ccw_values, rays_least)
    t = least_rotation(cw, cw_values, [-r % m for r in rays_least])
    use_cw = rotation_less(cw, cw_values, t, ccw, ccw_values, s)

    # rotations: the periods of ccw; reflections: ray i -> ray (j - i) mod m for the j
    # with ccw rotated by j equal to cw.  When the least symbol occurs once in ccw (the
    # usual case) no rotation but the identity keeps it in place, and a reflection must
    # carry its one place in cw to its one place in ccw: no string search is needed.
    if ccw.count(ccw[s]) == 1:
        period = m
        if ccw[s] != cw[t]:
            offsets: tuple = ()
        else:
            j = (s - t) % m
            offsets = (j,) if ccw[j:] + ccw[:j] == cw else ()
    else:
        period = cyclic_period(ccw)
        offsets = tuple(occurrences(cw, ccw))
    k = m // period
    mirrors = len(offsets)

    steps = np.arange(m)
    ray_order = (-(t + steps)) % m if use_cw else (s + steps) % m
    if m > 64 and n == m + (centre_index is not None):      # one point per ray
        labelling = firsts(rays)[ray_order].tolist()
    else:
        labelling = [i for r in ray_order.tolist() for i in rays[r]]
    if centre_index is not None:
        labelling.insert(0, centre_index)

    collinear = m == 1 or (m == 2 and all(_is_half_turn(g, ring.polar) for g in gaps))
    orderable = k == 1 and (mirrors == 0 or collinear)
    ordering = tuple(labelling) if orderable else None
    reference = _reference(ring, labelling, centre_index)

    if orderable:
        leader = labelling[0]
    elif centre_index is not None:
        leader = centre_index
    elif k == 1 and mirrors == 1:
        leader = _leader_on_mirror(rays, ccw, ccw_values, offsets[0])
    else:
        leader = None

    layout = Layout(centre, reference, centre_index,
                    rays if isinstance(rays, SingletonRays) else tuple(rays),
                     tuple(ray_turns) if ray_turns is not None else None, points, n, period,
                     offsets)
    return SymmetryGroup(f"{'D' if mirrors else 'C'}{k}", k, mirrors, centre, ring.polar,
                         rotation(layout, period % m) if k > 1 else None,
                         reflection(layout, offsets[0]) if offsets else None,
                         reference, orderable, ordering, leader, layout)


def _certified_c1(config: Configuration, ring: Levels) -> SymmetryGroup | None:
    """C1 certified by Arb balls (:func:`exactsym.geometry.algebraic_filtered.certified_c1`), with
    the same canonical labelling as the exact path below; None when the balls leave a
    symmetry possible.  The centre is divided out only when read."""
    enc = ring.enclosures
    rank = level_ranks(ring, config.n)
    if rank is None:
        return None
    found = certified_c1(enc, rank, enc.centre_index)
    if found is None:
        return None
    rays, labelling = found
    centre_index = enc.centre_index
    if centre_index is not None:
        labelling.insert(0, centre_index)
    reference = _reference(ring, labelling, centre_index)
    centre = LazyCentre(ring.sec)
    layout = Layout(centre, reference, centre_index, tuple(rays), None, config.points,
                     config.n, len(rays), ())
    return SymmetryGroup("C1", 1, 0, centre, False, None, None, reference, True,
                         tuple(labelling), labelling[0], layout)


def _is_half_turn(gap, polar: bool) -> bool:
    return gap == (fmpq(1, 2) if polar else 2)


def _reference(ring: Levels, labelling: list[int], centre_index: int | None) -> int | None:
    """The first point, in the canonical labelling, of the sparsest level off the centre
    (fewest points; the nearest on a tie).  The level of radius 0 is the one point at the
    centre: no radius is read (a lazy level's exact radius costs field products)."""
    levels = ring.levels
    if isinstance(levels, RationalLevels):
        flat, bounds = levels.flat, levels.bounds
        members_of = (flat[bounds[k]:bounds[k + 1]] for k in range(len(bounds) - 1))
    else:
        members_of = (level.points for level in levels)
    sparsest = None
    for points in members_of:
        if not points or (centre_index is not None and len(points) == 1
                          and points[0] == centre_index):
            continue
        if sparsest is None or len(points) < len(sparsest):
            sparsest = points
            if len(points) == 1:         # none is sparser, and nearer ones came first
                break
    if sparsest is not None:
        members = set(sparsest)
        for i in labelling:
            if i in members and i != centre_index:
                return i
    return next((i for i in labelling if i != centre_index), None)


def _leader_on_mirror(rays, ids, values, offset: int) -> int | None:
    """D1: the points on the mirror are those on the rays it fixes (2r = offset mod m).
    Among those rays, the one whose counter-clockwise reading is least (that reading
    equals the clockwise one, by the mirror; two fixed rays cannot read alike, or the
    half turn would be a symmetry); on it, the point nearest the centre."""
    m = len(rays)
    fixed = [r for r in range(m) if (2 * r - offset) % m == 0]
    if not fixed:
        return None
    best = fixed[0]
    for r in fixed[1:]:
        if rotation_less(ids, values, r, ids, values, best):
            best = r
    return rays[best][0]
