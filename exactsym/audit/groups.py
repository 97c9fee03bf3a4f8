"""The true symmetry groups of sub-configurations made of whole levels, for the audit.

The audit compares ``lem-asym-ord`` (one level) and the pair statements
(``lem-sym-notord``, ``lem-asym-pair-ord``: two levels) with the truth: whether the
sub-configuration is orderable, as :func:`exactsym.truth.symmetry.symmetry_group` decides it
about the SEC centre C of the whole configuration (:func:`exactsym.audit.statements.group_about_centre`).
Computing that group for each of hundreds of pairs repeated the same exact work;
:class:`SubGroups` decides orderability from facts that settle it, and computes the group
of the sub-configuration only when none does (or when a failure is listed with its group):

1. A symmetry of the whole configuration fixes C and keeps distances to C, so it maps
   every level onto itself: it is a symmetry of every union of levels.  If the whole group
   has a rotation (``rotations > 1``, which moves every point but C) and the union has a
   point off C, or its only mirror moves a point of the union, the union is not
   orderable (a symmetry moves one of its points).
2. A symmetry of a union of levels about C maps each of its levels onto itself.  If one
   level's own group is trivial (one rotation, no mirror: no isometry fixing C maps it
   onto itself but the identity), every symmetry of the union is the identity: the union
   is orderable (group C1).
3. The rotations about C mapping level L onto itself form C_{k_L}; those of the union
   form a subgroup of every C_{k_L}, and C_a and C_b (about one centre) meet in
   C_gcd(a, b): if the gcd of the levels' rotation counts exceeds 1, the union has a
   rotation and a point off C (a level of rotation count > 1 is not the point C), so it
   is not orderable.
4. If every level of the union holds one point, a symmetry of the union about C maps
   each of these points onto itself (fact 2's argument): no symmetry moves a point, so
   the union is orderable, whatever its group (a mirror through all its points, or the
   point C alone).  Five points in four levels of a field of degree 5,760 spent a
   second on these groups (issue 9).

Each level's group is computed once (a level alone: small).  Proofs 1-3 use only that
the truth's groups are the groups of isometries fixing C and mapping the point set onto
itself, and that ``orderable`` means no symmetry moves a point (``symmetry.SymmetryGroup``).
"""

from __future__ import annotations

from math import gcd

from ..geometry.algebraic_filtered import Enclosures
from ..geometry.configuration import Configuration
from ..geometry.levels import Level, Levels
from ..truth.symmetry import SymmetryGroup, symmetry_group


def group_about_centre(config: Configuration, ring_data: Levels, robots,
                       levels=None) -> tuple:
    """``(group, robots)``: the symmetry group, about the SEC centre C of the whole
    configuration, of the sub-configuration ``robots`` (sorted); its indices are
    positions in ``robots``.  ``levels``: the 1-based numbers of the levels holding
    ``robots``, when known (then only those levels are looked at: O(|robots|), not O(t))."""
    robots = sorted(robots)
    where = {r: k for k, r in enumerate(robots)}
    if ring_data.polar:
        sub = Configuration(polar=[config.polar[i] for i in robots],
                            polar_system=config.polar_system, source=config.source)
    else:
        sub = Configuration(points=[config.points[i] for i in robots], system=config.system,
                            source=config.source)
    chosen = ring_data.levels if levels is None else \
        [ring_data.levels[k - 1] for k in sorted(set(levels))]
    out = []
    for level in chosen:
        pts = tuple(where[i] for i in level.points if i in where)
        if pts:
            out.append(Level(level.radius_squared, pts))
    enc = ring_data.enclosures
    sub_enc = None
    if enc is not None and not ring_data.polar and getattr(enc, "balls", None) is not None:
        # the sub-configuration's balls about C, read from the whole one's: the truth
        # then certifies C1 by balls (symmetry._certified_c1) with no exact product
        xs, ys = enc.balls
        sub_enc = Enclosures(sub.points, enc.homogeneous,
                             ([xs[i] for i in robots], [ys[i] for i in robots]))
    return symmetry_group(sub, Levels(ring_data.sec, tuple(out), ring_data.polar,
                                      enclosures=sub_enc)), robots


class SubGroups:
    """Orderability (and, on demand, the group) of unions of whole levels of ``config``
    about C, ``group`` being the true group of the whole configuration (module
    docstring).  Levels are numbered from 1, as :class:`exactsym.paper.family.Ring`
    numbers them."""

    def __init__(self, config: Configuration, ring_data: Levels, group: SymmetryGroup):
        self.config, self.ring_data, self.whole = config, ring_data, group
        self._levels: dict = {}
        self._unions: dict = {}
        mirror = group.mirror
        self._moved = frozenset(i for i, j in enumerate(mirror.permutation) if i != j) \
            if group.rotations == 1 and group.mirrors == 1 and mirror is not None else None

    def group(self, robots, levels) -> tuple:
        """``(group, robots)`` of :func:`group_about_centre` (computed once per union)."""
        key = tuple(sorted(set(levels)))
        hit = self._unions.get(key)
        if hit is None:
            hit = self._unions[key] = group_about_centre(self.config, self.ring_data, robots,
                                                         levels)
        return hit

    def _level(self, k: int) -> SymmetryGroup:
        got = self._levels.get(k)
        if got is None:
            level = self.ring_data.levels[k - 1]
            got = self._levels[k] = self.group(level.points, (k,))[0]
        return got

    def orderable(self, robots, levels) -> bool:
        """Whether the union of ``levels`` (holding ``robots``) is orderable about C:
        ``self.group(robots, levels)[0].orderable``, settled without that group when
        facts 1-3 of the module docstring do."""
        levels = tuple(sorted(set(levels)))
        off_centre = any(self.ring_data.levels[k - 1].radius_squared != 0 for k in levels)
        whole = self.whole
        if whole.rotations > 1 and off_centre:                             # fact 1
            return False
        if self._moved is not None and any(r in self._moved for r in robots):
            return False
        levels_of = self.ring_data.levels
        if all(len(levels_of[k - 1].points) == 1 for k in levels):         # fact 4
            return True
        if len(levels) > 1:
            counts = []
            for k in levels:
                level = levels_of[k - 1]
                if len(level.points) == 1 and level.radius_squared != 0:
                    # one point P off C: its group about C is D1 (the mirror CP), which
                    # neither fact 2 nor fact 3 uses, and computing it took exact squared
                    # lengths (100 robots on radii sqrt(k): a second)
                    counts.append(1)
                    continue
                g = self._level(k)
                if g.rotations == 1 and g.mirrors == 0:                     # fact 2
                    return True
                counts.append(g.rotations)
            if all(c >= 1 for c in counts):
                common = 0
                for c in counts:
                    common = gcd(common, c)
                if common > 1:                                              # fact 3
                    return False
        return self.group(robots, levels)[0].orderable


__all__ = ["SubGroups", "group_about_centre"]
