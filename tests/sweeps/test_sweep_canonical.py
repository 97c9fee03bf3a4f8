"""Canonical enumeration of the sweep's families against brute force and Burnside's lemma.

Brute force: every k-subset of the cells, reduced to the least image under the group;
the generators must produce exactly one member of each orbit, each the least of its
orbit, and as many as Burnside's lemma counts.
"""

from fractions import Fraction
from itertools import combinations, islice

import pytest
from hypothesis import given, settings, strategies as st

from exactsym.sweeps.canonical import (bracelets, burnside_count, dihedral_permutations,
                                      gap_bracelets, gaps_to_positions, orderly_subsets,
                                      square_permutations)
from exactsym.sweeps.families import (FamilyError, family_items, family_size, parse_family)


def _least_image(perms, cells):
    return min(tuple(sorted(g[c] for c in cells)) for g in perms)


def _orbits(perms, ncells, k):
    return {_least_image(perms, s) for s in combinations(range(ncells), k)}


def _bead_cells(beads, m, rings):
    return tuple(sorted(r * m + j for j, b in enumerate(beads) for r in range(rings)
                        if b >> r & 1))


@pytest.mark.parametrize("m", [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 12])
def test_one_ring_bracelets_are_the_dihedral_orbits(m):
    perms = dihedral_permutations(m)
    for k in range(0, min(m, 7) + 1):
        orbits = _orbits(perms, m, k)
        assert burnside_count(perms, k) == len(orbits)
        by_beads = [_bead_cells(b, m, 1) for b in bracelets(m, k)]
        assert len(by_beads) == len(orbits)
        assert {_least_image(perms, c) for c in by_beads} == orbits
        if k:
            gaps = list(gap_bracelets(m, k))
            assert len(gaps) == len(orbits)
            assert {_least_image(perms, gaps_to_positions(g)) for g in gaps} == orbits
            assert all(sum(g) == m - k for g in gaps)


@pytest.mark.parametrize("m,rings", [(3, 2), (4, 2), (5, 2), (6, 2), (3, 3), (4, 3)])
def test_multi_ring_bracelets_are_the_dihedral_orbits(m, rings):
    perms = dihedral_permutations(m, rings)
    for k in range(0, min(m * rings, 6) + 1):
        orbits = _orbits(perms, m * rings, k)
        found = list(bracelets(m, k, 1 << rings))
        assert len(found) == len(orbits) == burnside_count(perms, k)
        cells = [_bead_cells(b, m, rings) for b in found]
        # each bracelet is the least of its orbit as a bead sequence, and orbits differ
        assert {_least_image(perms, c) for c in cells} == orbits
        assert found == sorted(found)


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_grid_orderly_generation_gives_the_square_orbits(n):
    perms = square_permutations(n)
    for k in range(1, min(n * n, 5) + 1):
        orbits = _orbits(perms, n * n, k)
        found = list(orderly_subsets(n * n, k, perms))
        assert set(found) == orbits              # each is the least of its own orbit
        assert len(found) == len(orbits) == burnside_count(perms, k)


def test_burnside_known_values():
    # binary bracelets with 12 beads, 6 black: 50 (OEIS A052307); 2-colour bracelets of
    # length 10: 78 (A000029)
    assert burnside_count(dihedral_permutations(12), 6) == 50
    assert sum(burnside_count(dihedral_permutations(10), k) for k in range(11)) == 78


@settings(max_examples=30, deadline=None)
@given(st.integers(3, 14), st.integers(1, 6), st.integers(0, 50))
def test_enumerators_resume_after_any_form(m, k, cut):
    k = min(k, m)
    full = list(gap_bracelets(m, k))
    if full:
        i = cut % len(full)
        assert list(gap_bracelets(m, k, start_after=full[i])) == full[i + 1:]
    beads = list(bracelets(m, k, 4))
    if beads:
        i = cut % len(beads)
        assert list(bracelets(m, k, 4, start_after=beads[i])) == beads[i + 1:]
    perms = square_permutations(4)
    grid = list(orderly_subsets(16, min(k, 4), perms))
    i = cut % len(grid)
    assert list(orderly_subsets(16, min(k, 4), perms, start_after=grid[i])) == grid[i + 1:]


@pytest.mark.parametrize("text", ["roots:12:<=6", "roots:7:2..4:2", "roots:6:3:1,3/2",
                                  "grid:3:<=4", "grid:4:3"])
def test_family_size_is_the_number_of_items_and_keys_are_distinct(text):
    family = parse_family(text)
    items = list(family_items(family))
    assert len(items) == family_size(family)
    assert len({i.key for i in items}) == len(items)
    for item in items:
        assert len(item.points) == item.n == len(set(item.points))


def test_roots_items_are_on_the_roots_and_first_robot_at_turn_zero():
    family = parse_family("roots:12:<=6:2")
    for item in family_items(family):
        assert item.points[0][2] == "0"
        den = 1
        for kind, r, turn in item.points:
            assert kind == "polar" and r in ("1", "2")
            t = Fraction(turn)
            assert 0 <= t < 1 and (t * 12).denominator == 1
            den = max(den, t.denominator)
        assert item.denominator % den == 0 and 12 % item.denominator == 0


def test_roots_counts_known_values():
    # the binary bracelets of 12 beads with 1..6 black ones: 1, 6, 12, 29, 38, 50
    assert family_size(parse_family("roots:12:<=6")) == 1 + 6 + 12 + 29 + 38 + 50


def test_random_family_is_deterministic_and_exact():
    a = list(family_items(parse_family("random:2..5:seed:40")))
    b = list(family_items(parse_family("random:2..5:seed:40")))
    c = list(family_items(parse_family("random:2..5:other:40")))
    assert a == b and a != c
    assert [i.n for i in a[:4]] == [2, 3, 4, 5]
    for item in a:
        for _, x, y in item.points:
            assert abs(Fraction(x)) <= 8 and Fraction(y).denominator <= 4


def test_perturb_family_moves_each_coordinate_by_at_most_eps():
    base = (("xy", "0", "0"), ("xy", "4", "0"), ("xy", "5", "3"))
    family = parse_family("perturb:any.txt:1/100:20", lambda path: base)
    items = list(family_items(family))
    assert len(items) == 20
    for item in items:
        xs = sorted((Fraction(x), Fraction(y)) for _, x, y in item.points)
        for (x, y), (_, bx, by) in zip(xs, base):
            assert abs(x - Fraction(bx)) <= Fraction(1, 100)
            assert abs(y - Fraction(by)) <= Fraction(1, 100)


@pytest.mark.parametrize("text", ["roots:12", "roots:x:3", "roots:12:0", "grid:3:5..2",
                                  "random:3:s:x", "perturb:f:-1:3", "tiles:3:3",
                                  "roots:6:2:0,1"])
def test_bad_family_texts_are_refused(text):
    with pytest.raises(FamilyError):
        parse_family(text, lambda path: (("xy", "0", "0"),))


def test_gap_bracelets_stream_without_materialising():
    # a family far too large to list starts at once (roots:60 with 10 robots)
    first = list(islice(gap_bracelets(60, 10), 3))
    assert len(first) == 3 and all(sum(g) == 50 for g in first)


@pytest.mark.parametrize("text", ["roots:12:<=6", "roots:6:2..5:2", "grid:4:<=4"])
def test_families_start_after_any_key(text):
    family = parse_family(text)
    items = list(family_items(family))
    for i in range(0, len(items), max(1, len(items) // 17)):
        assert list(family_items(family, after=items[i].key)) == items[i + 1:]
