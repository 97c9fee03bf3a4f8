"""The rays of many rational points about the SEC centre, by certified float filters.

The ground truth (:mod:`exactsym.truth.symmetry`) reads the rays counter-clockwise with the
angle between consecutive rays; from ``symmetry._FILTER_MIN`` rational points on, this
module computes the same rays, ray classes and gap classes with NumPy: floats with proven
error bounds (``geometry.float_pseudo_angles``, ``geometry.certified_groups``; proofs in
``docs/numbers.md``) order and separate whatever they can, and exact integer arithmetic
decides only inside the groups they cannot split (ties and near-ties).  Floats never
decide: two values in different certified groups are exactly different and in that order.
"""

from __future__ import annotations

import numpy as np

from ..exact import fmpq
from ..geometry.predicates import FILTER_EPS, certified_groups, float_differences, float_pseudo_angles
from ..geometry.levels import Levels, RationalLevels, TupleView


def integer_pseudo_angle(x, y) -> fmpq:
    """:func:`exactsym.truth.symmetry.pseudo_angle` of a non-zero vector of integers (``int`` or ``fmpz``), with
    one ``fmpq`` construction: the same exact number."""
    if y >= 0:
        return fmpq(y, x + y) if x > 0 else fmpq(2 * x - y, x - y)
    return fmpq(2 * x + 3 * y, x + y) if x < 0 else fmpq(4 * x - 3 * y, x - y)



class SingletonRays(TupleView):
    """Rays of one point each, counter-clockwise, as a read-only sequence equal to the
    tuple ``((i,), (j,), ...)`` of them: the points in one NumPy integer array
    (``first``), each ray's tuple made when it is read.  The symmetry group keeps its
    rays (:class:`exactsym.truth.isometries.Layout`); on a million random points the
    tuples and their integers were 90 MB (issue 33)."""

    __slots__ = ("first",)

    def __init__(self, first: np.ndarray):
        self.first = first

    def __len__(self) -> int:
        return len(self.first)

    def __getitem__(self, k):
        if isinstance(k, slice):
            return tuple((i,) for i in self.first[k].tolist())
        return (int(self.first[k]),)

    def __iter__(self):
        return ((i,) for i in self.first.tolist())



def firsts(rays) -> np.ndarray:
    """The first point of each ray, as a NumPy integer array."""
    if isinstance(rays, SingletonRays):
        return rays.first
    return np.fromiter((ray[0] for ray in rays), dtype=np.int64, count=len(rays))


def level_ranks(ring: Levels, n: int):
    """``rank[i]``: the index of point i's level (nearest first, so ranks order as the
    squared radii), or None unless the levels hold every point once."""
    if isinstance(ring.levels, RationalLevels):
        return ring.levels.ranks(n)
    members = [level.points for level in ring.levels]
    flat = np.fromiter((i for points in members for i in points), dtype=np.int64)
    if len(flat) != n or (n and (flat.min() < 0 or flat.max() >= n)):
        return None
    rank = np.full(n, -1, dtype=np.int64)
    rank[flat] = np.repeat(np.arange(len(members)), [len(points) for points in members])
    if (rank < 0).any():                 # a point listed twice (then another is missing)
        return None
    return rank.tolist()


class LazyGaps:
    """The exact angle from ray a to ray a + 1 (an ``fmpq`` pseudo-angle), computed from the
    rays' integer vectors on first use: the float filter interned the gaps, so only the
    few comparisons of the canonical labelling need values."""

    __slots__ = ("rays", "vector", "vectors", "cache")

    def __init__(self, rays, vector, vectors):
        self.rays, self.vector, self.vectors, self.cache = rays, vector, vectors, {}

    def __len__(self) -> int:
        return len(self.rays)

    def exact_products(self, gaps):
        """``(dot, cross)``: object arrays of Python integers, ``u . v`` and ``u x v`` for
        the integer vectors u, v of the rays at and after each gap in ``gaps``."""
        m = len(self.rays)
        need = np.zeros(m, dtype=bool)                 # the rays whose vectors are needed
        need[gaps] = True
        need[(gaps + 1) % m] = True
        rays = np.flatnonzero(need)                    # each vector once
        position = np.cumsum(need) - 1                 # of each needed ray in `rays`
        vx, vy = self.vectors([self.rays[r][0] for r in rays.tolist()])
        at, after = position[gaps], position[(gaps + 1) % m]
        ux, uy, wx, wy = vx[at], vy[at], vx[after], vy[after]
        return ux * wx + uy * wy, ux * wy - uy * wx

    def __getitem__(self, a: int):
        m = len(self.rays)
        if not -m <= a < m:
            raise IndexError(a)
        a %= m
        gap = self.cache.get(a)
        if gap is None:
            (ux, uy), (vx, vy) = self.vector(self.rays[a][0]), \
                self.vector(self.rays[(a + 1) % m][0])
            gap = self.cache[a] = integer_pseudo_angle(ux * vx + uy * vy, ux * vy - uy * vx)
        return gap


def filtered_rays(points, centre, rank, floats=None):
    """:func:`exactsym.truth.symmetry._cartesian_rays` for many rational points, as certified float filters over
    NumPy arrays (``geometry.float_pseudo_angles``, ``certified_groups``): directions and
    the angles between consecutive rays are grouped by floats with proven error bounds,
    and exact integer keys are computed only inside groups the bound cannot split (ties
    and near-ties).  ``radii`` are tuples of level ranks (same order as the squared
    radii); returns ``(centre_index, rays, radii, gaps, gap_ids)`` or None when the floats
    overflow.  ``floats``: the points' ``geometry.float_coordinates``, if known."""
    diffs = float_differences(points, centre, floats)
    if diffs is None:
        return None
    dx, dy, ex, ey = diffs
    cx, cy = centre
    den = cx.q * cy.q // cx.q.gcd(cy.q)
    a0, b0 = cx.p * (den // cx.q), cy.p * (den // cy.q)
    vectors: dict = {}

    def vector(i):
        v = vectors.get(i)
        if v is None:
            x, y = points[i]
            v = vectors[i] = ((x.p * den - a0 * x.q) * y.q, (y.p * den - b0 * y.q) * x.q)
        return v

    def vectors_of(indices):
        """The same integer vectors for many points, as object arrays of Python ints."""
        vx, vy = [0] * len(indices), [0] * len(indices)
        for k, i in enumerate(indices):          # one pass: the cost is in .p, .q, int()
            x, y = points[i]
            xp, xq, yp, yq = int(x.p), int(x.q), int(y.p), int(y.q)
            vx[k], vy[k] = (xp * iden - ia0 * xq) * yq, (yp * iden - ib0 * yq) * xq
        ax, ay = np.empty(len(indices), dtype=object), np.empty(len(indices), dtype=object)
        ax[:], ay[:] = vx, vy
        return ax, ay

    iden, ia0, ib0 = int(den), int(a0), int(b0)
    keys, errs, sure = float_pseudo_angles(dx, dy, ex, ey)
    exact: dict = {}
    centre_index = None
    for i in np.flatnonzero(~sure).tolist():
        vx, vy = vector(i)
        if not vx and not vy:
            centre_index = i
            continue
        exact[i] = k = integer_pseudo_angle(vx, vy)
        keys[i], errs[i] = float(k), 2.0 ** -46
    idx = np.arange(len(points))
    if centre_index is not None:
        idx = np.delete(idx, centre_index)
    if not len(idx):                     # one point, at the centre
        return centre_index, [], np.zeros(0, dtype=np.int64), LazyGaps([], vector, vectors_of), []
    order, starts = certified_groups(keys[idx], errs[idx])
    sorted_array = idx[order]
    sorted_idx = sorted_array.tolist()
    rays: list = []
    if len(starts) == len(sorted_idx):
        rays = SingletonRays(sorted_array.astype(np.int64, copy=False))
    else:
        bounds = starts.tolist() + [len(sorted_idx)]
        for g in range(len(bounds) - 1):
            members = sorted_idx[bounds[g]:bounds[g + 1]]
            if len(members) == 1:
                rays.append((members[0],))
                continue
            for i in members:
                if i not in exact:
                    exact[i] = integer_pseudo_angle(*vector(i))
            members.sort(key=lambda i: (exact[i], rank[i]))
            ray = [members[0]]
            for i in members[1:]:
                if exact[i] == exact[ray[0]]:
                    ray.append(i)
                else:
                    rays.append(tuple(ray))
                    ray = [i]
            rays.append(tuple(ray))
    if len(rays) == len(sorted_idx):     # one point per ray: ids are the ranks of its level
        # taken along `rays`, not along the float order: inside a group the exact sort
        # may have reordered the rays (the near-tie defect of issue 9)
        first = firsts(rays)
        ray_ids = np.unique(np.asarray(rank)[first], return_inverse=True)[1]
    else:                                # ids ranked by value: they order as the radii do
        radii = [tuple([rank[i] for i in ray]) for ray in rays]
        rank_of = {r: k for k, r in enumerate(sorted(set(radii)))}
        ray_ids = np.array([rank_of[r] for r in radii], dtype=np.int64)
    gaps = LazyGaps(rays, vector, vectors_of)
    return centre_index, rays, ray_ids, gaps, filtered_gap_ids(rays, gaps, dx, dy, ex, ey)


def filtered_gap_ids(rays, gaps, dx, dy, ex, ey) -> list[int]:
    """Small integers, equal iff the exact gaps are equal and ordered as they are (ranks):
    float gaps (the pseudo-angle of
    ``(u . v, u x v)``) with a proven bound group them; exact values split the groups.
    Bound on a dot or cross product of vectors known within Eu, Ev (componentwise), with
    float sums Su, Sv of absolute components: ``(Su + 2 Eu) Ev + Eu Sv + 2^-50 Su Sv``."""
    m = len(rays)
    first = np.fromiter((ray[0] for ray in rays), dtype=np.int64, count=m)
    ux, uy = dx[first], dy[first]
    vx, vy = np.roll(ux, -1), np.roll(uy, -1)
    eu = np.maximum(ex[first], ey[first])
    ev = np.roll(eu, -1)
    with np.errstate(all="ignore"):
        su, sv = np.abs(ux) + np.abs(uy), np.abs(vx) + np.abs(vy)
        bound = ((su + 2 * eu) * ev + eu * sv + FILTER_EPS * su * sv) * 1.01 + 1e-290
        keys, errs, sure = float_pseudo_angles(ux * vx + uy * vy, ux * vy - uy * vx,
                                               bound, bound)
    for a in np.flatnonzero(~sure).tolist():
        keys[a], errs[a] = float(gaps[a]), 2.0 ** -46
    order, starts = certified_groups(keys, errs)
    sizes = np.diff(np.append(starts, m))
    if len(starts) == m:
        ids = np.empty(m, dtype=np.int64)
        ids[order] = np.arange(m)
        return ids.tolist()
    # exact (dot, cross) of every gap in a group of two or more, in Python integers over
    # object arrays; a group whose members all point as its first one is one class
    groups = len(starts)
    pos = np.flatnonzero(np.repeat(sizes > 1, sizes))
    members = order[pos]
    dot, crs = gaps.exact_products(members)
    head = np.repeat(np.arange(groups), sizes)[pos]          # group of each member
    firsts = np.flatnonzero(np.concatenate(([True], head[1:] != head[:-1])))
    h = np.repeat(firsts, np.diff(np.append(firsts, len(pos))))    # its group's first
    same = np.asarray(dot * crs[h] - crs * dot[h] == 0, dtype=bool) \
        & (np.asarray(dot > 0, dtype=bool) == np.asarray(dot[h] > 0, dtype=bool)) \
        & (np.asarray(dot < 0, dtype=bool) == np.asarray(dot[h] < 0, dtype=bool)) \
        & (np.asarray(crs > 0, dtype=bool) == np.asarray(crs[h] > 0, dtype=bool)) \
        & (np.asarray(crs < 0, dtype=bool) == np.asarray(crs[h] < 0, dtype=bool))
    # ids in sorted position: the classes of the groups before, plus the class inside the
    # group (0 unless the exact values split it, which only the few split groups compute)
    classes = np.ones(groups, dtype=np.int64)
    inside = np.zeros(m, dtype=np.int64)
    for g in np.unique(head[~same]).tolist():
        a0, a1 = int(starts[g]), int(starts[g] + sizes[g])
        values = [gaps[a] for a in order[a0:a1].tolist()]
        distinct = sorted({(v.p, v.q): v for v in values}.values())
        rank_of = {(v.p, v.q): k for k, v in enumerate(distinct)}
        inside[a0:a1] = [rank_of[(v.p, v.q)] for v in values]
        classes[g] = len(distinct)
    base = np.cumsum(classes) - classes
    ids = np.empty(m, dtype=np.int64)
    ids[order] = np.repeat(base, sizes) + inside
    return ids.tolist()
