"""The NumPy float filters of the large rational path decide as exact arithmetic does, on
adversarial near-ties (issue 9): points on common rays from the centre (collinear triples),
on common circles (Pythagorean directions: equal distances), orbits of rotations and
mirrors (equal angles between rays), and copies moved by 10^-30 (near-ties a float cannot
see).  The filtered symmetry group (``symmetry._filtered_rays``) must equal the exact one
point for point; the vectorised SEC must equal exact Welzl; the certified groups must
never separate equal values nor misorder unequal ones."""

from __future__ import annotations

import random

import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

import exactsym.truth.symmetry as symmetry
from exactsym.geometry.configuration import Configuration
from exactsym.exact import fmpq
from exactsym.geometry.predicates import certified_groups, float_differences, float_pseudo_angles
from exactsym.geometry.levels import levels_of
from exactsym.truth.rays_filtered import filtered_rays, level_ranks
from exactsym.geometry.sec import _circle, _welzl, smallest_enclosing_circle
from exactsym.truth.symmetry import pseudo_angle

TINY = fmpq(1, 10 ** 30)
CENTRE = (fmpq(1, 3), fmpq(-2, 7))
DIRECTIONS = [(5, 0), (3, 4), (4, 3), (0, 5), (1, 2), (2, 1), (1, 1), (7, 24), (24, 7)]
C4 = [lambda x, y: (x, y), lambda x, y: (-y, x), lambda x, y: (-x, -y), lambda x, y: (y, -x)]


def _configuration(seeds, mirror: bool, nudges) -> Configuration:
    points = set()
    for (a, b), k in seeds:
        for rot in C4:
            for x, y in ((a, b), (b, a)) if mirror else ((a, b),):
                px, py = rot(fmpq(k) * x, fmpq(k) * y)
                points.add((px + CENTRE[0], py + CENTRE[1]))
    points = sorted(points)
    for j, (sx, sy) in nudges:              # a copy of a point, moved by 10^-30
        x, y = points[j % len(points)]
        moved = (x + sx * TINY, y + sy * TINY)
        if moved not in points:
            points.append(moved)
    random.Random(len(points)).shuffle(points)
    return Configuration.from_points(points)


seed = st.tuples(st.sampled_from(DIRECTIONS), st.sampled_from([1, 2, 3, fmpq(5, 2)]))
nudge = st.tuples(st.integers(0, 500), st.sampled_from([(1, 0), (0, 1), (-1, 1), (1, 1)]))


def test_filtered_ordering_near_tie(monkeypatch):
    """Five points, one moved by 1e-30 (issue 9's defect, fixed): the float order put the
    moved point's ray after its neighbour's, the exact sort swapped the two rays, and the
    ray ids were read along the float order, not along the rays.  The filtered path must
    give the exact path's ordering, and the certificate checker must accept it."""
    import json
    from exactsym import checker
    from exactsym.certificates.certificate import make_certificate
    config = _configuration([((5, 0), 1)] * 8, False, [(0, (0, 1))])
    ring = levels_of(config)
    exact = symmetry.symmetry_group(config, ring)
    monkeypatch.setattr(symmetry, "_FILTER_MIN", 1)
    assert symmetry.symmetry_group(config, ring).ordering == exact.ordering == (0, 4, 3, 2, 1)
    cert = make_certificate(config)
    assert cert["claim"]["ordering"] == [0, 4, 3, 2, 1]
    assert checker.verify_certificate(json.loads(json.dumps(cert)))[0]


def test_default_path_certifies_the_near_tie():
    import json
    from exactsym import checker
    from exactsym.certificates.certificate import make_certificate
    config = _configuration([((5, 0), 1)] * 8, False, [(0, (0, 1))])
    cert = make_certificate(config)
    assert cert["claim"]["ordering"] == [0, 4, 3, 2, 1]
    assert checker.verify_certificate(json.loads(json.dumps(cert)))[0]


def _summary(group):
    return (group.name, group.orderable, group.ordering, group.leader, group.reference,
            [s.permutation for s in group.symmetries()])


@settings(max_examples=25, deadline=None)
@given(st.lists(seed, min_size=8, max_size=30), st.booleans(),
       st.lists(nudge, max_size=3))
def test_filtered_group_equals_exact(seeds, mirror, nudges):
    config = _configuration(seeds, mirror, nudges)
    ring = levels_of(config)
    filtered = symmetry.symmetry_group(config, ring) if config.n >= symmetry._FILTER_MIN \
        else None
    saved = symmetry._FILTER_MIN
    try:
        symmetry._FILTER_MIN = 10 ** 12
        exact = symmetry.symmetry_group(config, ring)
    finally:
        symmetry._FILTER_MIN = saved
    if filtered is not None:
        assert _summary(filtered) == _summary(exact)
    rank = level_ranks(ring, config.n)
    assert rank is not None and filtered_rays(config.points, ring.sec.centre,
                                                        rank) is not None
    symmetry._FILTER_MIN, low = 1, symmetry._FILTER_MIN
    try:                                     # the filter on small sets too
        assert _summary(symmetry.symmetry_group(config, ring)) == _summary(exact)
    finally:
        symmetry._FILTER_MIN = low


@settings(max_examples=25, deadline=None)
@given(st.lists(seed, min_size=1, max_size=12), st.booleans(), st.lists(nudge, max_size=3))
def test_vectorised_sec_equals_exact_welzl(seeds, mirror, nudges):
    points = list(_configuration(seeds, mirror, nudges).points)
    fast = smallest_enclosing_circle(points)
    order = list(range(len(points)))
    slow = _welzl(points, order, lambda c, i: c.contains(points[i]),
                  lambda support: _circle(points, support))
    assert fast.centre == slow.centre and fast.radius_squared == slow.radius_squared


@settings(max_examples=40, deadline=None)
@given(st.lists(seed, min_size=1, max_size=12), st.lists(nudge, max_size=4))
def test_certified_groups_order_exact_pseudo_angles(seeds, nudges):
    """Every group boundary the filter certifies is a strict exact inequality, ties stay
    in one group, and the exact fallback runs (the near-ties are never 'sure')."""
    points = list(_configuration(seeds, True, nudges).points)
    points = [p for p in points if p != CENTRE]
    dx, dy, ex, ey = float_differences(points, CENTRE)
    keys, errs, sure = float_pseudo_angles(dx, dy, ex, ey)
    exact = [pseudo_angle(x - CENTRE[0], y - CENTRE[1]) for x, y in points]
    for i in np.flatnonzero(~sure).tolist():
        keys[i], errs[i] = float(exact[i]), 2.0 ** -46
    for i in np.flatnonzero(sure).tolist():
        assert abs(keys[i] - float(exact[i])) <= errs[i]
    order, starts = certified_groups(keys, errs)
    group_of = np.empty(len(points), dtype=np.int64)
    group_of[order] = np.cumsum(np.isin(np.arange(len(points)), starts)) - 1
    for i in range(len(points)):
        for j in range(len(points)):
            if group_of[i] < group_of[j]:
                assert exact[i] < exact[j]
            if exact[i] == exact[j]:
                assert group_of[i] == group_of[j]


def test_exact_fallback_runs_on_near_ties():
    """Two points 10^-30 apart in angle: the float keys cannot separate them."""
    points = [(fmpq(1), fmpq(1)), (fmpq(1), fmpq(1) + TINY), (fmpq(-1), fmpq(0))]
    dx, dy, ex, ey = float_differences(points, (fmpq(0), fmpq(0)))
    keys, errs, sure = float_pseudo_angles(dx, dy, ex, ey)
    assert sure.tolist() == [True, True, False]     # (-1, 0): on an axis, decided exactly
    keys[2], errs[2] = 2.0, 2.0 ** -46
    order, starts = certified_groups(keys, errs)
    assert len(starts) == 2 and sorted(order[:2].tolist()) == [0, 1]


@settings(max_examples=25, deadline=None)
@given(st.lists(seed, min_size=1, max_size=20), st.booleans(), st.lists(nudge, max_size=3))
def test_filtered_levels_equal_exact(seeds, mirror, nudges):
    """Levels ordered by one filtered pass (``geometry.angular_ranks``) equal levels
    ordered by the exact comparison sort (``geometry.angular_sort``)."""
    import exactsym.geometry.levels as levels
    config = _configuration(seeds, mirror, nudges)
    saved = levels._FILTER_MIN
    budget = levels._EXACT_SORT_BUDGET
    try:
        levels._FILTER_MIN = 1
        fast = levels.levels_of(config)
        levels._EXACT_SORT_BUDGET = 0               # every level through the filtered pass
        filtered = levels.levels_of(config)
        levels._FILTER_MIN = 10 ** 12
        slow = levels.levels_of(config)
    finally:
        levels._FILTER_MIN, levels._EXACT_SORT_BUDGET = saved, budget
    assert fast.levels == slow.levels and filtered.levels == slow.levels


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3), st.integers(0, 2)),
                min_size=64, max_size=120))
def test_filtered_coincidence_equals_dictionary_scan(raw):
    """Points 10^-30 apart have equal floats: the filtered duplicate search must still
    report exactly the first pair the exact dictionary scan reports."""
    from exactsym.geometry.configuration import _coincident
    from exactsym.exact import exact_key
    points = [(fmpq(a) + e * TINY, fmpq(b)) for a, b, e in raw]
    config = Configuration(points=points, system=None)
    seen, expected = {}, None
    for i, (x, y) in enumerate(points):
        j = seen.setdefault((exact_key(x), exact_key(y)), i)
        if j != i:
            expected = (j, i)
            break
    assert _coincident(config) == expected


# -- the filtered rays against the exact rays, symbol by symbol --------------------------

# orbits: the identity, the half turn, C4, a mirror, D4 (integer maps about CENTRE)
SUBGROUPS = [C4[:1], C4[::2], C4, [C4[0], lambda x, y: (y, x)],
             C4 + [lambda x, y: (y, x), lambda x, y: (-x, y), lambda x, y: (-y, -x),
                   lambda x, y: (x, -y)]]
# sizes of the moves: far below, near and above the floats' resolution
STEPS = [fmpq(1, 10 ** 30), fmpq(1, 2 ** 53), fmpq(3, 10 ** 16), fmpq(1, 10 ** 9)]


@st.composite
def near_ties(draw):
    """Rational points about CENTRE with many exact and near ties between symbols: orbits
    of a subgroup (equal gaps and radii), Pythagorean directions of one length (a common
    circle), several radii on one ray (collinear with the centre), copies moved by a tiny
    step along x, y or the ray (near-equal angles, near-equal radii), maybe the centre."""
    group = draw(st.sampled_from(SUBGROUPS))
    seeds = draw(st.lists(st.tuples(st.sampled_from(DIRECTIONS + [(-3, 4), (4, -3), (-5, -12)]),
                                    st.sampled_from([1, 2, fmpq(5, 2), 3])),
                          min_size=1, max_size=10))
    points = set()
    for (a, b), k in seeds:
        for g in group:
            x, y = g(fmpq(a) * k, fmpq(b) * k)
            points.add((x + CENTRE[0], y + CENTRE[1]))
    points = sorted(points)
    moves = draw(st.lists(st.tuples(st.integers(0, 10 ** 4), st.sampled_from(STEPS),
                                    st.sampled_from(["x", "y", "-y", "ray", "-ray"])),
                          max_size=6))
    for j, step, how in moves:
        x, y = points[j % len(points)]
        if how.endswith("ray"):          # the same direction, a radius a little different
            f = 1 + step if how == "ray" else 1 - step
            moved = (CENTRE[0] + (x - CENTRE[0]) * f, CENTRE[1] + (y - CENTRE[1]) * f)
        else:
            moved = (x + step, y) if how == "x" else (x, y + (step if how == "y" else -step))
        if moved not in points:
            points.append(moved)
    if draw(st.booleans()):
        points.append(CENTRE)
    points = list(dict.fromkeys(points))
    draw(st.randoms(use_true_random=False)).shuffle(points)
    return Configuration.from_points(points)


def _order_isomorphic(ids, values) -> None:
    """``ids[a] < ids[b]`` iff ``values[a] < values[b]``, and equal iff equal, for all a, b."""
    order = sorted(range(len(values)), key=values.__getitem__)
    for a, b in zip(order, order[1:]):
        if values[a] == values[b]:
            assert ids[a] == ids[b]
        else:
            assert values[a] < values[b] and ids[a] < ids[b]


@settings(max_examples=150, deadline=None)
@given(near_ties())
def test_filtered_rays_equal_exact_rays(config):
    """The filtered path's rays, ray ids and gap ids against the exact path's rays, radii
    and gaps across all rays (ids order-isomorphic to the exact symbols), and the whole
    group (ordering, leader, reference, symmetries) with the threshold forced low."""
    ring = levels_of(config)
    centre = ring.sec.centre
    rank = level_ranks(ring, config.n)
    centre_index, rays, ray_ids, gaps, gap_ids = filtered_rays(config.points, centre, rank)
    exact_centre, exact_rays, radii, exact_gaps = symmetry._cartesian_rays(config.points, centre)
    assert centre_index == exact_centre and [tuple(r) for r in rays] == exact_rays
    _order_isomorphic(ray_ids.tolist(), radii)
    _order_isomorphic(gap_ids, exact_gaps)
    assert [gaps[a] for a in range(len(rays))] == exact_gaps
    saved = symmetry._FILTER_MIN
    try:
        symmetry._FILTER_MIN = 1
        fast = symmetry.symmetry_group(config, ring)
        symmetry._FILTER_MIN = 10 ** 12
        slow = symmetry.symmetry_group(config, ring)
    finally:
        symmetry._FILTER_MIN = saved
    assert _summary(fast) == _summary(slow)


@pytest.mark.parametrize("with_centre", [False, True])
def test_symmetries_map_points_as_their_permutations_say(with_centre):
    """A D4 set of 25 orbits (200 points, one per ray: the vectorised permutations): each
    symmetry's exact matrix carries point i onto point ``permutation[i]``."""
    rnd = random.Random(5)
    seeds = set()
    while len(seeds) < 25:
        a, b = rnd.randint(1, 10 ** 4), rnd.randint(1, 10 ** 4)
        if a != b:
            seeds.add((fmpq(a, rnd.randint(1, 50)), fmpq(b, rnd.randint(1, 50))))
    maps = SUBGROUPS[-1]
    points = [(CENTRE[0] + x, CENTRE[1] + y) for a, b in sorted(seeds) for g in maps
              for x, y in [g(a, b)]] + ([CENTRE] if with_centre else [])
    random.Random(6).shuffle(points)
    config = Configuration.from_points(points)
    group = symmetry.symmetry_group(config)
    assert group.name == "D4" and config.n >= symmetry._FILTER_MIN
    for iso in group.symmetries():
        (a, b), (c, d) = iso.matrix
        for i, (x, y) in enumerate(points):
            u, v = x - CENTRE[0], y - CENTRE[1]
            assert points[iso.permutation[i]] == (CENTRE[0] + a * u + b * v,
                                                  CENTRE[1] + c * u + d * v)


@settings(max_examples=20, deadline=None)
@given(near_ties())
def test_rational_levels_behave_as_their_tuple(config):
    """The lazily built levels (``levels.RationalLevels``) equal the exact path's tuple of
    levels, element by element, as a whole, hashed, sliced, pickled; their ranks are the
    level index of each point; each squared radius is the exact one."""
    import pickle
    import exactsym.geometry.levels as levels
    from exactsym.geometry.predicates import squared_distance
    saved = levels._FILTER_MIN
    try:
        levels._FILTER_MIN = 1
        fast = levels.levels_of(config)
        levels._FILTER_MIN = 10 ** 12
        slow = levels.levels_of(config)
    finally:
        levels._FILTER_MIN = saved
    lazy, exact = fast.levels, slow.levels
    assert isinstance(lazy, levels.RationalLevels) and isinstance(exact, tuple)
    assert len(lazy) == len(exact) and list(lazy) == list(exact)
    assert lazy == exact and exact == lazy and hash(lazy) == hash(exact) and fast == slow
    assert lazy[-1] == exact[-1] and lazy[1:3] == exact[1:3] and lazy[::-2] == exact[::-2]
    assert pickle.loads(pickle.dumps(lazy)) == exact
    rank = lazy.ranks(config.n)
    for k, level in enumerate(exact):
        for i in level.points:
            assert rank[i] == k
            assert squared_distance(fast.sec.centre, config.points[i]) == level.radius_squared
    with pytest.raises(IndexError):
        lazy[len(exact)]


@pytest.mark.parametrize("with_centre", [False, True])
def test_large_orderings_pass_the_checker(with_centre):
    """200 random rational points (the filtered rays, one point per ray, the vectorised
    labelling) and copies moved by 10^-30: the independent certificate checker accepts the
    ordering and leader, and rejects the ordering with two neighbours swapped."""
    import copy
    import json
    from exactsym import checker
    from exactsym.certificates.certificate import make_certificate
    rnd = random.Random(11)
    points = {(fmpq(rnd.randint(-10 ** 4, 10 ** 4), rnd.randint(1, 30)),
               fmpq(rnd.randint(-10 ** 4, 10 ** 4), rnd.randint(1, 30))) for _ in range(200)}
    points = sorted(points)
    points += [(x + TINY, y) for x, y in points[:3]] + [(x, y - TINY) for x, y in points[3:6]]
    config = Configuration.from_points(points)
    if with_centre:
        config = Configuration.from_points(points + [levels_of(config).sec.centre])
    assert config.n >= symmetry._FILTER_MIN
    cert = json.loads(json.dumps(make_certificate(config)))
    assert cert["claim"]["orderable"] and checker.verify_certificate(copy.deepcopy(cert))[0]
    order = cert["claim"]["ordering"]
    assert order[0] == cert["claim"]["leader"]
    assert (order[0] == config.n - 1) == with_centre
    bad = copy.deepcopy(cert)
    bad["claim"]["ordering"][5], bad["claim"]["ordering"][6] = order[6], order[5]
    ok, message = checker.verify_certificate(bad)
    assert not ok and "ordering" in message


@settings(max_examples=10, deadline=None)
@given(st.integers(0, 10 ** 6), st.integers(70, 200), st.booleans())
def test_rays_of_one_point_each_are_held_compactly(seed_value, n, centre):
    """Random rational points (one per ray), more than 64 and some with a robot at C:
    the filtered path keeps its rays as :class:`exactsym.truth.rays_filtered.SingletonRays`
    (one integer array), equal to the exact path's tuple of rays, with the same group,
    ordering and symmetries (their permutations are built from the array)."""
    import random
    from exactsym.truth.rays_filtered import SingletonRays
    rnd = random.Random(seed_value)
    pts = {(rnd.randint(-10 ** 4, 10 ** 4), rnd.randint(-10 ** 4, 10 ** 4)) for _ in range(n)}
    pts |= {(2 * 10 ** 4, 0), (-2 * 10 ** 4, 0)}        # the SEC about the origin
    if centre:
        pts.add((0, 0))
    config = Configuration.from_points(sorted(pts))
    ring = levels_of(config)
    filtered = symmetry.symmetry_group(config, ring)
    saved = symmetry._FILTER_MIN
    try:
        symmetry._FILTER_MIN = 10 ** 12
        exact = symmetry.symmetry_group(config, ring)
    finally:
        symmetry._FILTER_MIN = saved
    assert _summary(filtered) == _summary(exact)
    rays = filtered._layout.rays
    assume(all(len(ray) == 1 for ray in exact._layout.rays))    # no two points on a ray
    assert isinstance(rays, SingletonRays)
    assert rays == exact._layout.rays and tuple(rays) == tuple(exact._layout.rays)
    assert rays[-1] == exact._layout.rays[-1] and rays[2:5] == exact._layout.rays[2:5]
    assert hash(rays) == hash(tuple(exact._layout.rays))
