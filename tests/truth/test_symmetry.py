"""Ground truth: the symmetry group, the canonical ordering and the leader (exactsym.truth.symmetry).

Laws: the group and orderability never change under an exact similarity and a shuffle of
the input; the ordering and the leader map along; the group agrees with a brute-force
oracle that shares no code with the module; every isometry reported is exact and real.
"""

from __future__ import annotations

import time
from fractions import Fraction
from itertools import islice
from pathlib import Path

import pytest
from hypothesis import event, given, settings, strategies as st

from exactsym.geometry.configuration import Configuration, load
from exactsym.exact import fmpq
from exactsym.report.check import check_report
from exactsym.truth.symbols import least_rotation
from exactsym.truth.symmetry import (SymmetryGroup, cyclic_period, occurrences, pseudo_angle,
                                     symmetry_group)

from strategies import (RATIONAL_GROUPS, brute_force_group, brute_force_polar_group,
                        near_symmetric_points, near_symmetric_polar_points, polar_configuration,
                        polar_group_points, polar_similarities, rational_group_points, rationals,
                        shuffled, similarities)

Q = fmpq
EXAMPLES = Path(__file__).resolve().parents[2] / "cases" / "examples"


def group_of(points) -> SymmetryGroup:
    return symmetry_group(Configuration.from_points(points))


def P(*coords):
    return [(Q(x), Q(y)) for x, y in coords]


def assert_isometries_exact(config: Configuration, group: SymmetryGroup) -> None:
    """Every symmetry maps each point i exactly onto point permutation[i]."""
    found = list(group.symmetries())
    expected = 1 if group.name == "O2" else group.rotations + group.mirrors
    assert len(found) == expected
    assert found[0].kind == "rotation" and found[0].permutation == tuple(range(config.n))
    assert len({(g.kind, g.permutation) for g in found}) == len(found)
    assert sum(g.kind == "reflection" for g in found) == group.mirrors
    for g in found:
        assert g.centre == group.centre
        if group.polar:
            assert g.matrix is None and g.turn is not None
            for i, (r2, t) in enumerate(config.polar):
                j = g.permutation[i]
                image = (t + g.turn) if g.kind == "rotation" else (2 * g.turn - t)
                assert config.polar[j][0] == r2
                if r2 != 0:
                    assert (image - config.polar[j][1]).q == 1      # equal modulo whole turns
        else:
            assert g.turn is None
            (a, b), (c, d) = g.matrix
            assert a * a + c * c == 1 and b * b + d * d == 1 and a * b + c * d == 0
            assert a * d - b * c == (1 if g.kind == "rotation" else -1)
            cx, cy = g.centre
            for i, (x, y) in enumerate(config.points):
                dx, dy = x - cx, y - cy
                assert (cx + a * dx + b * dy, cy + c * dx + d * dy) == \
                    config.points[g.permutation[i]]
    if group.rotation_generator is not None:
        assert group.rotation_generator == found[1]
        if group.polar:
            assert group.rotation_generator.turn == Q(1, group.rotations)
    if group.mirror is not None:
        assert group.mirror == found[group.rotations]


def assert_leader_rule(group: SymmetryGroup, n: int) -> None:
    perms = [g.permutation for g in group.symmetries()]
    fixed_by_all = [i for i in range(n) if all(p[i] == i for p in perms)]
    assert group.orderable == (len(fixed_by_all) == n)
    if group.orderable:
        assert sorted(group.ordering) == list(range(n))
        assert group.leader == group.ordering[0]
    else:
        assert group.ordering is None
    assert (group.leader is None) == (not fixed_by_all)
    if group.leader is not None:
        assert group.leader in fixed_by_all


# ---------------------------------------------------------------- hand-made cases

@pytest.mark.parametrize("points, name, orderable, leader", [
    (P((0, 0), (1, 0), (1, 1), (0, 1)), "D4", False, None),                 # square
    (P((0, 0), (1, 0), (1, 1), (0, 1), (Q(1, 2), Q(1, 2))), "D4", False, 4),  # + its centre
    (P((0, 0), (2, 0), (2, 1), (0, 1)), "D2", False, None),                 # rectangle
    (P((0, 0), (4, 0), (2, 3)), "D1", False, 2),                            # isosceles: apex
    (P((0, 0), (6, 0), (1, 3)), "C1", True, None),                          # scalene
    (P((0, 0), (1, 0), (3, 0)), "D1", True, 1),                             # collinear
    (P((0, 0), (1, 0), (3, 0), (4, 0)), "D2", False, None),                 # collinear, even
    (P((0, 0), (1, 0), (2, 0)), "D2", False, 1),                            # ... with centre
    (P((0, 0), (1, 0)), "D2", False, None),                                 # two points
    (P((5, 7)), "O2", True, 0),                                             # one point
    (P((2, 1), (-1, 2), (-2, -1), (1, -2)), "D4", False, None),             # tilted square
    (P((3, 1), (-1, 3), (-3, -1), (1, -3), (2, 2), (-2, 2), (-2, -2), (2, -2)), "C4", False,
     None),                                                                 # pinwheel C4
    (P((0, 0), (4, 0), (5, 3), (2, 5), (-1, 3)), "D1", False, 3),           # rational pentagon
])
def test_hand_made_cases(points, name, orderable, leader):
    config = Configuration.from_points(points)
    group = symmetry_group(config)
    assert group.name == name
    assert group.orderable is orderable
    if leader is not None or not orderable:
        assert group.leader == leader
    assert_isometries_exact(config, group)
    assert_leader_rule(group, config.n)


def test_collinear_ordering_is_from_the_nearer_side():
    group = group_of(P((0, 0), (1, 0), (3, 0)))     # centre 3/2: rays {1, 0} and {2}
    assert group.ordering == (1, 0, 2)
    assert group.mirror.permutation == (0, 1, 2)    # the line itself moves nothing


def test_one_point():
    group = group_of(P((5, 7)))
    assert (group.name, group.rotations, group.mirrors, group.reference) == ("O2", 0, 0, None)
    assert group.centre == (5, 7)
    assert [g.permutation for g in group.symmetries()] == [(0,)]


def test_group_about_a_given_centre():
    """Rings with another centre: the symmetries that fix it (used for sub-configurations)."""
    from exactsym.geometry.levels import Level, Levels, levels_of
    whole = levels_of(Configuration.from_points(P((0, 0), (4, 0), (4, 4), (0, 4), (1, 2))))
    one = Configuration.from_points(P((1, 2)))
    group = symmetry_group(one, Levels(whole.sec, (Level(Q(1), (0,)),), False))
    assert (group.name, group.orderable, group.leader) == ("D1", True, 0)
    assert group.mirror.matrix == ((1, 0), (0, -1))
    pair = Configuration.from_points(P((0, 0), (4, 0)))
    group = symmetry_group(pair, Levels(whole.sec, (Level(Q(8), (0, 1)),), False))
    assert (group.name, group.orderable, group.leader, group.centre) == ("D1", False, None, (2, 2))
    assert_isometries_exact(pair, group)


def test_chiral_pinwheel_c3_polar():
    config = load(EXAMPLES / "chiral-nine-gon.toml")
    group = symmetry_group(config)
    assert (group.name, group.polar, group.mirror, group.leader) == ("C3", True, None, None)
    assert group.rotation_generator.turn == Q(1, 3)
    assert group.rotation_generator.permutation == (1, 2, 0, 4, 5, 3, 7, 8, 6)
    assert group.reference in (6, 7, 8)          # the sparsest level: first on a tie, nearest
    assert_isometries_exact(config, group)


def test_chiral_pinwheel_c3_cartesian_in_a_number_field():
    polar = load(EXAMPLES / "chiral-nine-gon.toml")
    shift = (Q(1, 3), Q(-2))
    config = Configuration.from_points([(x + shift[0], y + shift[1]) for x, y in polar.points],
                                       system=polar.system)
    group = symmetry_group(config)
    assert (group.name, group.polar) == ("C3", False)
    (cos, msin), (sin, _) = group.rotation_generator.matrix
    assert cos == Q(-1, 2) and sin * sin == Q(3, 4) and sin > 0
    assert group.centre == shift
    assert_isometries_exact(config, group)


def test_regular_heptagon_polar_d7():
    config = polar_configuration([(3, Fraction(j, 7)) for j in range(7)])
    group = symmetry_group(config)
    assert (group.name, group.rotations, group.mirrors, group.polar) == ("D7", 7, 7, True)
    assert group.rotation_generator.turn == Q(1, 7)
    assert sorted(g.turn for g in group.symmetries() if g.kind == "reflection") == \
        [Q(j, 14) for j in range(7)]
    assert group.leader is None and group.ordering is None
    assert_isometries_exact(config, group)


def test_regular_heptagon_cartesian_d7(tmp_path):
    text = "".join(f"cos({2 * j}*pi/7) + 1/2, sin({2 * j}*pi/7)\n" for j in range(7))
    path = tmp_path / "heptagon.txt"
    path.write_text(text)
    config = load(path)
    group = symmetry_group(config)
    assert (group.name, group.polar) == ("D7", False)
    assert_isometries_exact(config, group)


def test_regular_hexagon_with_square_roots_and_centre(tmp_path):
    text = "0 0\n1 0\n1/2 sqrt(3)/2\n-1/2 sqrt(3)/2\n-1 0\n-1/2 -sqrt(3)/2\n1/2 -sqrt(3)/2\n"
    path = tmp_path / "hexagon.txt"
    path.write_text(text)
    config = load(path)
    group = symmetry_group(config)
    assert (group.name, group.leader) == ("D6", 0)
    assert_isometries_exact(config, group)
    assert_leader_rule(group, config.n)


def test_polar_and_cartesian_forms_give_one_ordering():
    """An asymmetric set with SEC centre at the origin: the polar path (turns) and the
    Cartesian path (pseudo-angles, in Q(zeta)) order it identically, translated or not."""
    pts = [(4, 0), (4, Fraction(1, 3)), (4, Fraction(2, 3)), (2, Fraction(1, 10)),
           (1, Fraction(1, 4)), (3, Fraction(7, 12))]
    polar = polar_configuration(pts)
    g_polar = symmetry_group(polar)
    assert g_polar.polar and g_polar.name == "C1" and g_polar.orderable
    moved = Configuration.from_points([(x + Q(1, 3), y - 5) for x, y in polar.points],
                                      system=polar.system)
    g_cart = symmetry_group(moved)
    assert not g_cart.polar
    assert g_cart.ordering == g_polar.ordering


def test_polar_radii_in_a_number_field(tmp_path):
    """r = sqrt(2) and r = 1 + sqrt(2): squared radii are field elements."""
    text = "".join(f"polar sqrt(2) {j}/5\npolar 1+sqrt(2) {4 * j + 1}/20\n" for j in range(5))
    path = tmp_path / "field.txt"
    path.write_text(text)
    config = load(path)
    group = symmetry_group(config)
    assert group.polar
    assert_isometries_exact(config, group)
    assert_leader_rule(group, config.n)
    assert (group.name, group.leader) == ("C5", None)


def test_regular_10000_gon_is_fast_and_lazy():
    config = polar_configuration([(5, Fraction(j, 10_000)) for j in range(10_000)])
    start = time.perf_counter()
    group = symmetry_group(config)
    assert time.perf_counter() - start < 5
    assert (group.name, group.rotations, group.mirrors) == ("D10000", 10_000, 10_000)
    first = list(islice(group.symmetries(), 3))
    assert [g.turn for g in first] == [0, Q(1, 10_000), Q(2, 10_000)]
    assert first[1].permutation[:3] == (1, 2, 3)


def test_report_section():
    from exactsym.analysis import analyse
    from exactsym.report.check import report_text
    report = check_report(Configuration.from_points(P((0, 0), (4, 0), (2, 3))))
    assert (report["group"], report["orderable"], report["ordering"], report["leader"]) == \
        ("D1", False, None, 2)
    assert report["symmetries"] == {"rotations": 1, "mirrors": 1}
    text = report_text(analyse(Configuration.from_points(P((0, 0), (4, 0), (2, 3)))))
    assert "symmetry   D1: no rotation but the identity, 1 mirror line through C" in text
    single = check_report(Configuration.from_points(P((1, 1))))
    assert single["symmetries"] == {"rotations": None, "mirrors": None}
    assert single["ordering"] == [0] and single["leader"] == 0


# ---------------------------------------------------------------- string tools

def test_string_tools():
    assert cyclic_period([1, 2, 1, 2]) == 2 and cyclic_period([1, 2, 1]) == 3
    assert cyclic_period([7]) == 1
    assert occurrences([2, 1, 2, 1], [1, 2, 1, 2]) == [1, 3]
    assert occurrences([1, 1, 2], [1, 2, 3]) == []
    word = [3, 1, 2, 1, 1, 2]
    assert least_rotation(word, word) == 3          # 1 1 2 3 1 2


@given(st.lists(st.integers(0, 2), min_size=1, max_size=12))
@settings(max_examples=150, deadline=None)
def test_least_rotation_against_brute_force(word):
    rotations = [word[j:] + word[:j] for j in range(len(word))]
    best = min(rotations)
    assert least_rotation(word, word) == rotations.index(best)
    assert cyclic_period(word) == next(p for p in range(1, len(word) + 1)
                                       if rotations[p % len(word)] == word)


@given(st.tuples(rationals(nonzero=True), rationals()), st.tuples(rationals(), rationals()))
@settings(max_examples=150, deadline=None)
def test_pseudo_angle_orders_like_the_angle(u, v):
    import math
    fu = math.atan2(float(u[1]), float(u[0])) % (2 * math.pi)    # test oracle only
    fv = math.atan2(float(v[1]), float(v[0])) % (2 * math.pi)
    if v == (0, 0) or abs(fu - fv) < 1e-9:
        return
    assert (pseudo_angle(*u) < pseudo_angle(*v)) == (fu < fv)
    assert pseudo_angle(*u) == pseudo_angle(3 * u[0], 3 * u[1])


def test_sort_by_exact_keys_is_decided_exactly():
    """Keys whose floats collide or are in the wrong order: the exact sort decides."""
    from exactsym.truth.symmetry import sort_by_exact_keys
    tiny = Q(1, 10**30)
    keys = [Q(1, 3) + j * tiny for j in range(100, 0, -1)] + [Q(1, 3) - tiny, Q(1, 3)]
    idx = list(range(len(keys)))
    sort_by_exact_keys(idx, keys)
    assert [keys[i] for i in idx] == sorted(keys)
    assert len({float(k) for k in keys}) == 1      # all one float: the filter saw no order


@given(st.lists(st.tuples(rationals(50, 9), rationals(50, 9)), min_size=2, max_size=30,
                unique=True))
@settings(max_examples=60, deadline=None)
def test_integer_and_generic_ray_arithmetic_agree(points):
    """The integer fast path for rational points gives exactly the generic result."""
    from exactsym.geometry.levels import levels_of
    from exactsym.truth.symmetry import _cartesian_rays
    centre = levels_of(Configuration.from_points(points)).sec.centre
    assert _cartesian_rays(points, centre, True) == _cartesian_rays(points, centre, False)


# ---------------------------------------------------------------- laws

def _group_and_points():
    return st.sampled_from(sorted(RATIONAL_GROUPS)).flatmap(
        lambda name: st.tuples(st.just(name), rational_group_points(name)))


@given(_group_and_points(), similarities(), st.data())
@settings(max_examples=150, deadline=None)
def test_rational_group_is_invariant_and_ordering_maps_along(case, similarity, data):
    name, points = case
    base = symmetry_group(Configuration.from_points(points))
    assert base.name == name
    assert base.orderable == (name == "C1")
    permuted, perm = data.draw(shuffled(points))
    moved_config = Configuration.from_points([similarity(p) for p in permuted])
    moved = symmetry_group(moved_config)
    _assert_maps_along(base, moved, perm)
    assert_isometries_exact(moved_config, moved)
    assert_leader_rule(moved, moved_config.n)


@given(st.lists(rationals(), min_size=2, max_size=7, unique=True), st.booleans(),
       similarities(), st.data())
@settings(max_examples=40, deadline=None)
def test_collinear_sets_are_orderable_unless_symmetric(xs, symmetric, similarity, data):
    if symmetric:
        xs = sorted(set(xs) | {-x for x in xs})
    points = [(x, 2 * x + 1) for x in xs]
    group = group_of(points)
    assert group.name == brute_force_group(points)[0]
    event(group.name)
    assert group.name == "D2" or (group.name == "D1" and not symmetric)
    assert group.orderable == (group.name == "D1")
    assert_leader_rule(group, len(points))
    permuted, perm = data.draw(shuffled(points))
    _assert_maps_along(group, group_of([similarity(p) for p in permuted]), perm)


@given(st.integers(2, 12), st.booleans(), st.data(), polar_similarities())
@settings(max_examples=100, deadline=None)
def test_polar_groups_up_to_12(k, dihedral, data, similarity):
    pts = data.draw(polar_group_points(k, dihedral))
    config = polar_configuration(pts)
    group = symmetry_group(config)
    assert group.polar
    assert group.name == f"{'D' if dihedral else 'C'}{k}"
    assert_isometries_exact(config, group)
    assert_leader_rule(group, config.n)
    moved, perm = data.draw(shuffled([similarity(p) for p in pts]))
    _assert_maps_along(group, symmetry_group(polar_configuration(moved)), perm)


@given(st.one_of(near_symmetric_points(),
                 st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3)), min_size=1,
                          max_size=9, unique=True).map(lambda cs: P(*cs))))
@settings(max_examples=500, deadline=None)
def test_agrees_with_brute_force_on_small_sets(points):
    config = Configuration.from_points(points)
    group = symmetry_group(config)
    name, perms = brute_force_group(points)
    event(f"group {name}, orderable {group.orderable}, leader {group.leader is not None}")
    assert group.name == name
    if name != "O2":
        assert {g.permutation for g in group.symmetries()} == set(perms)
    assert_isometries_exact(config, group)
    assert_leader_rule(group, config.n)


@given(near_symmetric_polar_points())
@settings(max_examples=300, deadline=None)
def test_agrees_with_brute_force_on_small_polar_sets(pts):
    config = polar_configuration(pts)
    group = symmetry_group(config)
    if not group.polar:     # the SEC centre is not the origin: the Cartesian path, in Q(zeta_12)
        event("Cartesian path")
        name, perms = brute_force_group(config.points)
        assert group.name == name
        assert {g.permutation for g in group.symmetries()} == set(perms)
        assert_leader_rule(group, config.n)
        return
    # on the polar path the origin is the SEC centre, fixed by every symmetry: the
    # oracle about the origin sees the whole group
    name, perms = brute_force_polar_group(config.polar)
    event(f"group {name}, leader {group.leader is not None}")
    assert group.name == name
    assert {g.permutation for g in group.symmetries()} == set(perms)
    assert_isometries_exact(config, group)
    assert_leader_rule(group, config.n)


# ---------------------------------------------------------------- helpers

def _inverse(perm):
    inv = [0] * len(perm)
    for new, old in enumerate(perm):
        inv[old] = new
    return inv


def _assert_maps_along(original: SymmetryGroup, moved: SymmetryGroup, perm) -> None:
    """``moved`` lists (the image of) point ``perm[j]`` of ``original`` as point j."""
    inv = _inverse(perm)
    assert (moved.name, moved.orderable) == (original.name, original.orderable)
    if original.ordering is not None:
        assert moved.ordering == tuple(inv[i] for i in original.ordering)
    assert (moved.leader is None) == (original.leader is None)
    if original.leader is not None:
        assert moved.leader == inv[original.leader]
