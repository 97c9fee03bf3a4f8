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

from dataclasses import dataclass, field

import numpy as np

from .configuration import Configuration, no_cycle_collection
from .exact import exact_key, exact_sorted, fmpq
from .geometry import (PseudoAngle, angular_ranks, angular_sort, certified_groups,
                       float_coordinates, float_differences, float_squared_norms,
                       sorted_by_value, squared_distance)
from .sec import Circle, smallest_enclosing_circle

_FILTER_MIN = 64    # from this many rational points, levels are ordered by certified floats


@dataclass(frozen=True)
class Level:
    radius_squared: object
    points: tuple[int, ...]


@dataclass(frozen=True)
class Levels:
    """The SEC and the levels G1..Gt; ``polar`` is True when both were computed from
    ``(r^2, turn)`` about the origin (then ``turns`` gives each point's turn)."""
    sec: Circle
    levels: tuple[Level, ...]
    polar: bool
    # (points, fx, fy): the configuration's point sequence itself and the float arrays of
    # its coordinates, when the rational filters computed them (reused by the rays)
    floats: tuple | None = field(default=None, repr=False, compare=False)


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
    floats = float_coordinates(points) if len(points) >= _FILTER_MIN \
        and isinstance(points[0][0], fmpq) else None
    circle = smallest_enclosing_circle(points, floats)
    x, y, d = circle.homogeneous
    if isinstance(d, fmpq) and d == 1:
        centre = circle.centre
        cx, cy = centre
        diffs = None
        if floats is not None and isinstance(cx, fmpq) and isinstance(cy, fmpq):
            diffs = float_differences(points, centre, floats)
        if diffs is None:
            def order_level(members):
                return angular_sort(centre, points, members)
            return Levels(circle, _group_levels([squared_distance(centre, p) for p in points],
                                                order_level), False)
        ranks: list = []

        def order_level(members):      # one filtered pass over all points, when first needed
            if not ranks:
                ranks.append(angular_ranks(points, centre, diffs))
            return sorted(members, key=ranks[0].__getitem__)

        radii_squared = [(px - cx) ** 2 + (py - cy) ** 2 for px, py in points]
        return Levels(circle, _group_levels(radii_squared, order_level,
                                            float_squared_norms(*diffs)),
                      False, (config.points, *floats))
    # centre X/D kept homogeneous: group by D^2 r^2 and sort by the directions D p - (X, Y),
    # which point as p - centre does (D > 0); divide by D^2 once per level
    vectors = [(d * p[0] - x, d * p[1] - y) for p in points]
    scaled = [vx * vx + vy * vy for vx, vy in vectors]
    d2 = d * d
    levels = _group_levels(scaled, lambda members: _angular_order(vectors, members))
    return Levels(circle, tuple(Level(level.radius_squared / d2, level.points)
                                for level in levels), False)


def _angular_order(vectors, members: list[int]) -> list[int]:
    """``members`` counter-clockwise from the +x ray (as :func:`angular_sort`), the vector
    zero first; vectors of one direction keep their order."""
    at_centre = [i for i in members if vectors[i][0] == 0 and vectors[i][1] == 0]
    rest = [i for i in members if i not in at_centre]
    keys = {i: PseudoAngle(*vectors[i]) for i in rest}
    return at_centre + sorted_by_value(rest, keys)


def _group_levels(radii_squared: list, order_level, approx=None) -> tuple[Level, ...]:
    """Levels from each point's squared radius; ``order_level`` sorts one level's indices.
    ``approx``: ``(floats, errs)`` enclosing the squared radii, if known."""
    if len(radii_squared) >= _FILTER_MIN and isinstance(radii_squared[0], fmpq):
        levels = _group_rational_levels(radii_squared, order_level, approx)
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


def _group_rational_levels(radii_squared: list, order_level, approx=None
                           ) -> tuple[Level, ...] | None:
    """:func:`_group_levels` for many ``fmpq``: ``float(fmpq)`` is correctly rounded (within
    a relative 2^-53), so floats with a relative slack of 2^-50 split the values into
    certainly ordered groups (``geometry.certified_groups``); equal values always share a
    group, and only groups of two or more are grouped and sorted exactly.  ``approx``:
    ``(floats, errs)`` with each exact value within ``errs`` of its float (from the
    points' float differences, ``geometry.float_squared_norms``), saving the conversions."""
    if approx is not None:
        keys, errs = approx
    else:
        try:
            keys = np.fromiter((float(v) for v in radii_squared), dtype=float,
                               count=len(radii_squared))
        except (OverflowError, ValueError):
            return None
        if not np.isfinite(keys).all():
            return None
        errs = np.abs(keys) * 2.0 ** -50 + 1e-300
    order, starts = certified_groups(keys, errs)
    flat = order.tolist()
    levels = []
    if len(starts) == len(flat):
        return tuple([Level(radii_squared[i], (i,)) for i in flat])
    bounds = starts.tolist() + [len(flat)]
    for g in range(len(bounds) - 1):
        a, b = bounds[g], bounds[g + 1]
        if b - a == 1:
            i = flat[a]
            levels.append(Level(radii_squared[i], (i,)))
            continue
        groups: dict = {}
        for i in sorted(flat[a:b]):
            groups.setdefault(exact_key(radii_squared[i]), [radii_squared[i]]).append(i)
        for group in sorted(groups.values(), key=lambda g: g[0]):
            levels.append(Level(group[0], tuple(order_level(group[1:]) if len(group) > 2
                                                else group[1:])))
    return tuple(levels)
