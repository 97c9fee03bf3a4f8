"""The SEC of a configuration and its concentric polygons G1..Gt (Section 3, before
``def-sym-pair``; Section 4.3 "the robots equidistant from C form a convex polygon").

``levels`` are the classes of points at equal distance from the SEC centre C,
nearest first; each lists its points counter-clockwise starting from the +x ray
through C (a point at C itself forms the level of radius 0).

Polar configurations centred at the origin are handled without trigonometry:
the origin is the SEC centre iff the points at maximal radius leave no angular
gap above half a turn (then the origin lies in their convex hull), and radii and
angles are the given ``r^2`` and rational turns.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from .configuration import Configuration, no_cycle_collection
from .algebraic_filtered import Enclosures, coordinate_balls, filtered_levels
from ..exact import RationalSystem, exact_key, exact_sorted, fmpq
from ..exact.fused import product_sum
from ..exact.level_radius import lazy_level_radius, scaled_radius
from ..exact.number import any_algebraic, is_plain_rational, shares_inverse
from .predicates import (PseudoAngle, angular_ranks, angular_sort, certified_groups,
                       float_differences, float_squared_norms,
                       sorted_by_value, squared_distance)
from .sec import Circle, floats_of_balls, smallest_enclosing_circle

_FILTER_MIN = 64    # from this many rational points, levels are ordered by certified floats
_EXACT_SORT_BUDGET = 256    # points of levels sorted exactly before the filtered pass pays
#: irrational coordinates go through the Arb-ball filters (False: the exact path alone,
#: which the tests compare them with)
ALGEBRAIC_FILTER = True


@dataclass(frozen=True, slots=True)
class Level:
    """One level: its squared radius and its robots (slots: one per robot on random
    configurations, issue 33)."""
    radius_squared: object
    points: tuple[int, ...]


@dataclass(frozen=True)
class Levels:
    """The SEC and the levels G1..Gt; ``polar`` is True when both were computed from
    ``(r^2, turn)`` about the origin (then ``turns`` gives each point's turn).
    ``levels``: a tuple of :class:`Level`, or for many rational points a
    :class:`RationalLevels` (a sequence equal to that tuple, built as it is read), or in
    the audit's scaled frame a :class:`ScaledLevels` (the same)."""
    sec: Circle
    levels: Sequence[Level]
    polar: bool
    # (points, fx, fy): the configuration's point sequence itself and the float arrays of
    # its coordinates, when the rational filters computed them (reused by the rays)
    floats: tuple | None = field(default=None, repr=False, compare=False)
    # irrational coordinates: the Arb balls about the centre (algebraic_filtered.py),
    # reused by the rays
    enclosures: object = field(default=None, repr=False, compare=False)
    # (points, {i: (x - cx, y - cy)}): exact vectors from the SEC centre of points of the
    # sequence ``points`` (a dict or a VectorTable), computed with their level's squared
    # radius (:func:`exactsym.analysis.built_levels`) and taken by the family layer's polygons
    vectors: tuple | None = field(default=None, repr=False, compare=False)


class VectorTable(list):
    """The vectors p - C of a configuration's points by index (``Levels.vectors``), None
    where not computed: a list read like the dict it replaces (``get``, ``in``, ``items``;
    on a million robots the dict's table was 40 MB beside the vectors)."""

    __slots__ = ()

    def get(self, i, default=None):
        found = self[i]
        return default if found is None else found

    def __contains__(self, i) -> bool:
        return type(i) is int and 0 <= i < len(self) and self[i] is not None

    def items(self):
        return ((i, v) for i, v in enumerate(self) if v is not None)

    def complete(self) -> bool:
        """Whether every point has its vector."""
        return not list.__contains__(self, None)


def polar_sec(polar) -> Circle | None:
    """The SEC when it is centred at the origin of a polar configuration, else None."""
    r2max = max(r2 for r2, _ in polar)
    on_circle = [i for i, (r2, _) in enumerate(polar) if r2 == r2max]
    turns = sorted(polar[i][1] for i in on_circle)
    if len(turns) < 2 or r2max == 0:
        return None
    gaps = [b - a for a, b in zip(turns, turns[1:])] + [turns[0] + 1 - turns[-1]]
    if max(gaps) > fmpq(1, 2):
        return None
    zero = r2max * 0
    return Circle((zero, zero), r2max, tuple(on_circle))


def levels_of(config: Configuration) -> Levels:
    """The SEC and the concentric polygons of ``config``."""
    with no_cycle_collection():
        return _levels_of(config)


def _levels_of(config: Configuration) -> Levels:
    if config.polar is not None:
        circle = polar_sec(config.polar)
        if circle is not None:
            return Levels(circle, _polar_levels(config.polar), True)
    points = list(config.points)
    # many rational points: their floats, converted once, filter the SEC, the levels and
    # (through Levels.floats) the rays
    floats = config.float_points if len(points) >= _FILTER_MIN \
        and is_plain_rational(points[0][0]) and isinstance(config.system, RationalSystem) \
        else None
    if ALGEBRAIC_FILTER and len(points) >= 3 and floats is None and any_algebraic(
            c for p in points for c in p):
        # irrational coordinates: distances and directions decided by certified balls,
        # ties confirmed exactly; each level's exact radius computed when it is read
        balls = coordinate_balls(config.points, _polar_parts(config), config.specs or None)
        fx, fy, errors = floats_of_balls(*balls)
        circle = smallest_enclosing_circle(points, (fx, fy), errors)
        enc = Enclosures(config.points, circle.homogeneous)
        flat, bounds = filtered_levels(enc, circle.support)
        return Levels(circle, AlgebraicLevels(flat, bounds, enc, circle), False,
                      enclosures=enc)
    circle = smallest_enclosing_circle(points, floats)
    x, y, d = circle.homogeneous
    if is_plain_rational(d) and d == 1:
        centre = circle.centre
        cx, cy = centre
        diffs = None
        if floats is not None and is_plain_rational(cx) and is_plain_rational(cy):
            diffs = float_differences(points, centre, floats)
        if diffs is None:
            def order_level(members):
                return angular_sort(centre, points, members)
            return Levels(circle, _group_levels([squared_distance(centre, p) for p in points],
                                                order_level), False)
        ranks: list = []
        budget = [_EXACT_SORT_BUDGET]

        def order_level(members):
            # a few levels of two or more points (random input): sorted exactly; many
            # (symmetric input): one filtered pass over all points, made when first needed.
            # Both give the counter-clockwise order (no two points of a level share a ray).
            if not ranks and len(members) <= budget[0]:
                budget[0] -= len(members)
                return angular_sort(centre, points, members)
            if not ranks:
                ranks.append(angular_ranks(points, centre, diffs))
            return sorted(members, key=ranks[0].__getitem__)

        approx = float_squared_norms(*diffs)
        if approx is not None:                 # squared radii computed when needed
            levels = _group_levels(len(points), order_level, approx, (points, centre))
        else:
            levels = _group_levels([squared_distance(centre, p) for p in points], order_level)
        return Levels(circle, levels, False, (config.points, *floats))
    # centre X/D kept homogeneous: group by D^2 r^2 and sort by the directions D p - (X, Y),
    # which point as p - centre does (D > 0); divide by D^2 once per level
    vectors = [(d * p[0] - x, d * p[1] - y) for p in points]
    scaled = [vx * vx + vy * vy for vx, vy in vectors]
    d2 = d * d
    levels = _group_levels(scaled, lambda members: _angular_order(vectors, members))
    return Levels(circle, tuple(Level(level.radius_squared / d2, level.points)
                                for level in levels), False)


def _polar_parts(config: Configuration):
    """``(radii, turns)`` of a configuration given in polar form, else None."""
    if config.polar is None or config.radii is None:
        return None
    return config.radii, [t for _, t in config.polar]


def _angular_order(vectors, members: list[int]) -> list[int]:
    """``members`` counter-clockwise from the +x ray (as :func:`angular_sort`), the vector
    zero first; vectors of one direction keep their order."""
    at_centre = [i for i in members if vectors[i][0] == 0 and vectors[i][1] == 0]
    rest = [i for i in members if i not in at_centre]
    keys = {i: PseudoAngle(*vectors[i]) for i in rest}
    return at_centre + sorted_by_value(rest, keys)


def _group_levels(radii_squared, order_level, approx=None, radius=None):
    """Levels from each point's squared radius; ``order_level`` sorts one level's indices.
    ``approx``: ``(floats, errs)`` enclosing the squared radii, if known; ``radius``:
    ``(points, centre)``, then ``radii_squared`` is only the number of points and each
    squared radius is computed when needed (:class:`RationalLevels`)."""
    n = radii_squared if radius is not None else len(radii_squared)
    if n >= _FILTER_MIN and (radius is not None or is_plain_rational(radii_squared[0])):
        levels = _group_rational_levels(n, None if radius is not None else radii_squared,
                                        order_level, approx, radius)
        if levels is not None:
            return levels
    groups: dict = {}
    for i, r2 in enumerate(radii_squared):
        groups.setdefault(exact_key(r2), [r2]).append(i)
    return tuple(Level(group[0], tuple(order_level(group[1:]) if len(group) > 2 else group[1:]))
                 for group in exact_sorted(list(groups.values()), key=lambda g: g[0]))


def _polar_levels(polar) -> tuple[Level, ...]:
    return _group_levels([r2 for r2, _ in polar],
                         lambda members: sorted(members, key=lambda i: polar[i][1]))


class TupleView(Sequence):
    """A read-only sequence equal to the tuple of its items (``==``, ``hash``, ``repr``),
    each item made when it is read: subclasses give ``__len__`` and ``__getitem__``.  The
    lazy level and ray sequences below stand for tuples that were too large to hold
    (issues 9 and 33), so they compare as those tuples do."""

    __slots__ = ()

    def __iter__(self):
        return (self[k] for k in range(len(self)))

    def __eq__(self, other):
        if isinstance(other, (tuple, list, TupleView)):
            return len(self) == len(other) and tuple(self) == tuple(other)
        return NotImplemented

    def __hash__(self) -> int:
        return hash(tuple(self))

    def __repr__(self) -> str:
        return repr(tuple(self))


class RationalLevels(TupleView):
    """The levels of many points with rational squared radii, as a read-only sequence of
    :class:`Level` equal to the tuple of them (``==``, ``hash``): the order of the points
    is kept in two lists (``flat``: the points level by level; ``bounds``: where each
    level starts) and each :class:`Level`, with its exact squared radius, is built when
    it is read.  The truth never reads most of them (``ranks`` gives it what it needs), and
    on a million points building them all cost more than the float baseline (issue 9)."""

    __slots__ = ("flat", "bounds", "known", "radii", "points", "centre")

    def __init__(self, flat: list, bounds: list, known: dict, radii=None, points=None,
                 centre=None):
        self.flat, self.bounds, self.known = flat, bounds, known
        self.radii, self.points, self.centre = radii, points, centre

    def level_radius(self, k: int, i: int):
        """The squared radius of level ``k``, whose point is ``i``."""
        return self.radius_squared(i)

    def radius_squared(self, i: int):
        """The exact squared distance of point i from the centre."""
        if self.radii is not None:
            return self.radii[i]
        (x, y), (cx, cy) = self.points[i], self.centre
        dx, dy = x - cx, y - cy
        return dx * dx + dy * dy

    def __len__(self) -> int:
        return len(self.bounds) - 1

    def __getitem__(self, k):
        if isinstance(k, slice):
            return tuple(self[j] for j in range(*k.indices(len(self))))
        m = len(self)
        if k < 0:
            k += m
        if not 0 <= k < m:
            raise IndexError("level index out of range")
        points = tuple(self.flat[self.bounds[k]:self.bounds[k + 1]])
        r2 = self.known.get(k)
        if r2 is None:
            r2 = self.known[k] = self.level_radius(k, points[0])
        return Level(r2, points)


    def __reduce__(self):
        return (RationalLevels, (self.flat, self.bounds, self.known, self.radii, self.points,
                                 self.centre))

    def ranks(self, n: int) -> list[int] | None:
        """``rank[i]``: the index of point i's level, or None unless the levels hold each
        of the n points once."""
        if len(self.flat) != n:
            return None
        flat = np.asarray(self.flat, dtype=np.int64)
        rank = np.full(n, -1, dtype=np.int64)
        rank[flat] = np.repeat(np.arange(len(self)), np.diff(self.bounds))
        return None if (rank < 0).any() else rank.tolist()



class ScaledLevels(TupleView):
    """The levels ``base`` (a tuple of :class:`Level`) with every squared radius times
    ``k2`` (a similarity of scale sqrt(k2) maps the levels so), as a read-only sequence
    equal to that tuple, each :class:`Level` built when it is read; ``own``: levels given
    whole instead (by index: those whose robots the similarity put in another order).
    The audit's frames hold them (:mod:`exactsym.audit.frames`): the paper's procedure
    in a frame reads the levels of several robots only, and a level per robot was 100 MB
    on a million robots (issue 33)."""

    __slots__ = ("base", "k2", "own")

    def __init__(self, base: tuple, k2, own: dict):
        self.base, self.k2, self.own = base, k2, own

    def __len__(self) -> int:
        return len(self.base)

    def __getitem__(self, k):
        if isinstance(k, slice):
            return tuple(self[j] for j in range(*k.indices(len(self))))
        m = len(self.base)
        if k < 0:
            k += m
        if not 0 <= k < m:
            raise IndexError("level index out of range")
        found = self.own.get(k)
        if found is not None:
            return found
        level = self.base[k]
        return Level(level.radius_squared * self.k2, level.points)


class AlgebraicLevels(RationalLevels):
    """The levels of points with irrational coordinates (:mod:`exactsym.geometry.algebraic_filtered`),
    lazily as :class:`RationalLevels`: a level's exact squared radius
    ``D^2 |p - C|^2 / D^2`` is computed when the level is read (the truth reads none)."""

    __slots__ = ("enclosures", "_d2", "circle", "_cc")

    def __init__(self, flat: list, bounds: list, enclosures, circle: Circle | None = None):
        super().__init__(flat, bounds, {})
        self.enclosures = enclosures
        self._d2 = self._cc = None
        self.circle = circle

    def level_radius(self, k: int, i: int):
        """The squared radius of level ``k`` (point ``i``): in a large cyclotomic field a
        :class:`~exactsym.exact.level_radius.LevelRadius`, in a tower over the sparse Q(zeta_N) a
        :class:`~exactsym.exact.level_radius.TowerLevelRadius`, computed when first read exactly
        (most readers compare radii: balls, level indices, images in F_p)."""
        enc = self.enclosures
        if not enc.unit and self.circle is not None and self._d2 is None:
            lazy = lazy_level_radius(enc.homogeneous[2], lambda: self.radius_squared(i),
                                     enc.points[i], self.circle, self, k)
            if lazy is not None:
                return lazy
        return self.radius_squared(i)

    def radius_squared(self, i: int):
        enc = self.enclosures
        if enc.unit:
            return enc.scaled_r2(i)
        if self.circle is not None and self._d2 is None and \
                shares_inverse(enc.homogeneous[2]):
            # |p - C|^2 from the divided centre (one inverse, shared with every reader of
            # the SEC centre), as |p|^2 - 2 p.C + |C|^2 with |C|^2 once: C's coefficients
            # have thousands of bits and p's a few, so p.C costs a third of (p - C)^2
            cx, cy = self.circle.centre
            x, y = enc.points[i]
            if self._cc is None:
                self._cc = product_sum([(cx, cx), (cy, cy)])
            return product_sum([(x, x), (y, y)]) - 2 * product_sum(
                [(x, cx), (y, cy)]) + self._cc
        r = enc.scaled_r2(i)
        if self._d2 is None:               # 1 / D^2, one field inverse for all levels
            d = enc.homogeneous[2]
            self._d2 = 1 / (d * d)
        return r * self._d2

    def __reduce__(self):
        return (tuple, (tuple(self),))


def _group_rational_levels(n: int, radii_squared, order_level, approx=None, radius=None
                           ) -> RationalLevels | None:
    """:func:`_group_levels` for many rational squared radii (``radii_squared``, or computed
    from ``radius = (points, centre)`` when needed): ``float(fmpq)`` is correctly rounded
    (within a relative 2^-53), so floats with a relative slack of 2^-50 split the values
    into certainly ordered groups (``geometry.certified_groups``); equal values always
    share a group, and only groups of two or more are grouped and sorted exactly.
    ``approx``: ``(floats, errs)`` with each exact value within ``errs`` of its float (from
    the points' float differences, ``geometry.float_squared_norms``), saving the
    conversions."""
    if approx is not None:
        keys, errs = approx
    elif radii_squared is None:
        return None
    else:
        try:
            keys = np.fromiter((float(v) for v in radii_squared), dtype=float, count=n)
        except (OverflowError, ValueError):
            return None
        if not np.isfinite(keys).all():
            return None
        errs = np.abs(keys) * 2.0 ** -50 + 1e-300
    points, centre = radius if radius is not None else (None, None)
    levels = RationalLevels([], [], {}, radii_squared, points, centre)
    order, starts = certified_groups(keys, errs)
    flat = order.tolist()
    sizes = np.diff(np.append(starts, n))
    if len(starts) == n:                         # every level one point
        levels.flat, levels.bounds = flat, list(range(n + 1))
        return levels
    out_flat: list = []
    bounds: list = []
    done = 0                                     # flat[:done] is placed
    for g in np.flatnonzero(sizes > 1).tolist():
        a, b = int(starts[g]), int(starts[g] + sizes[g])
        bounds.extend(range(len(out_flat), len(out_flat) + a - done))     # one-point levels
        out_flat.extend(flat[done:a])
        groups: dict = {}
        for i in sorted(flat[a:b]):
            r2 = levels.radius_squared(i)
            groups.setdefault(exact_key(r2), [r2]).append(i)
        for group in sorted(groups.values(), key=lambda g: g[0]):
            levels.known[len(bounds)] = group[0]
            bounds.append(len(out_flat))
            out_flat.extend(order_level(group[1:]) if len(group) > 2 else group[1:])
        done = b
    bounds.extend(range(len(out_flat), len(out_flat) + n - done))
    out_flat.extend(flat[done:])
    bounds.append(n)
    levels.flat, levels.bounds = out_flat, bounds
    return levels


def mapped_levels(levels: Levels, points, sim, vectors: dict | None = None) -> Levels | None:
    """The levels of the configuration whose points are ``points``, the images of the
    points of ``levels`` under the exact similarity ``sim`` (a
    :class:`exactsym.geometry.configuration.Similarity` without ``turn``; robot indices kept), read
    from ``levels`` instead of recomputed (issue 9, design item 4: the audit's frames).

    A similarity maps the SEC onto the SEC (same support), keeps which points are at
    equal distance from the centre and the order of the distances, and multiplies each
    squared radius by ``scale^2``; only the counter-clockwise order inside each level, from
    the new frame's +x ray, is computed again (:meth:`Enclosures.sorted_by_direction`, as
    :func:`filtered_levels` does).  The homogeneous centre (X, Y, D) keeps its D, so no
    field product or inverse is made.  None unless ``levels`` came from the Arb-ball path
    (irrational coordinates, levels built) and ``sim`` has no ``turn``.  ``vectors``:
    ``{i: p_i - C}`` in the first frame, mapped by the similarity's linear part into
    ``Levels.vectors`` when that part is a reflection (a sign: where p - C in the new
    frame costs a subtraction of megabyte numbers; a rotation or a scale would cost as
    much as the subtraction)."""
    lv = levels.levels
    enc = levels.enclosures
    if levels.polar or enc is None or not isinstance(lv, tuple) or sim.turn is not None \
            or len(points) != len(enc.points):
        return None
    circle = levels.sec
    k2 = fmpq(sim.scale) ** 2

    def linear(x, y):
        if sim.reflect:
            y = -y
        if sim.rotation is not None:
            c, s = sim.rotation
            x, y = c * x - s * y, s * x + c * y
        if sim.scale != 1:
            x, y = sim.scale * x, sim.scale * y
        return x, y

    def image(p):
        x, y = linear(*p)
        if sim.shift is not None:
            x, y = x + sim.shift[0], y + sim.shift[1]
        return x, y

    x, y, d = circle.homogeneous
    x, y = linear(x, y)
    if sim.shift is not None:
        x, y = x + d * sim.shift[0], y + d * sim.shift[1]
    through = None
    if circle._through is not None:
        found = [i for i, p in enumerate(enc.points) if p is circle._through]
        if not found:
            return None
        through = points[found[0]]
    centre = image(circle._centre) if circle._centre is not None else None
    radius = circle._radius_squared * k2 if circle._radius_squared is not None and k2 != 1 \
        else circle._radius_squared
    sec = Circle(centre, radius, circle.support, (x, y, d), through)
    enc2 = Enclosures(points, sec.homogeneous)
    flat: list[int] = []
    bounds: list[int] = []
    mapped = AlgebraicLevels(flat, bounds, enc2, sec)
    for k, level in enumerate(lv):
        members = list(level.points)
        bounds.append(len(flat))
        if len(members) > 1:
            members = enc2.sorted_by_direction(members)[0]
        flat.extend(members)
        # (a product by 1 still rewrites a megabyte number in canonical form; a level's
        # radius not computed yet stays so)
        r2 = level.radius_squared
        mapped.known[k] = r2 if k2 == 1 else scaled_radius(r2, k2, mapped, k)
    bounds.append(len(points))
    moved_vectors = None
    if vectors and sim.rotation is None and sim.scale == 1:
        moved_vectors = (points, {i: linear(*v) for i, v in vectors.items()})
    return Levels(sec, mapped, False, enclosures=enc2, vectors=moved_vectors)
