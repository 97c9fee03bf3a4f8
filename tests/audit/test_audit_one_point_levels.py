"""exactsym/audit/groups.py fact 4 (a union of one-point levels is orderable) against the
groups the truth computes for those unions."""

from __future__ import annotations

from fractions import Fraction
from itertools import combinations

from hypothesis import given, settings, strategies as st

from exactsym.audit.groups import SubGroups, group_about_centre
from exactsym.geometry.levels import levels_of
from exactsym.truth.symmetry import symmetry_group
from strategies import polar_configuration


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.integers(1, 9), st.integers(0, 11)), min_size=2, max_size=6),
       st.booleans())
def test_unions_of_one_point_levels_are_orderable_as_computed(points, ring):
    """audit_groups fact 4: every union of one-point levels is orderable, as the computed
    group of that union says (points on a line through C included: turns 0 and 6/12);
    with ``ring``, a square at radius 10 keeps C at the origin (else the SEC moves it)."""
    pts = list(dict.fromkeys((r, Fraction(t, 12)) for r, t in points))
    if ring:
        pts += [(10, Fraction(k, 4)) for k in range(4)]
    config = polar_configuration(pts)
    levels = levels_of(config)
    subs = SubGroups(config, levels, symmetry_group(config, levels))
    single = [k + 1 for k, level in enumerate(levels.levels) if len(level.points) == 1]
    for union in [(k,) for k in single] + list(combinations(single, 2)):
        robots = [i for k in union for i in levels.levels[k - 1].points]
        assert group_about_centre(config, levels, robots, union)[0].orderable
        assert subs.orderable(robots, union)
