"""Nested radicals over the sparse Q(zeta_N) for MakeAsym's radial move (issue 9).

A new level sqrt(x) of a tower over the sparse base is admitted only when Legendre
characters prove x no square of the top field (exact/sparse_nested.py): never for a square
(soundness, whatever the levels), and for the usual non-square.  The move itself: the root
squares to the ratio, the configuration's own tower keeps its levels, and the paper's run
completes where it stopped before.
"""

from __future__ import annotations

import pytest
from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym.analysis import analyse
from exactsym.geometry.configuration import load
from exactsym.errors import FieldTooLargeError
from exactsym.exact.adjoin_sqrt import adjoin_sqrt
from exactsym.exact.evaluate import SparseKummerSystem
from exactsym.exact.sparse_cyclotomic import cos_turn
from exactsym.exact.sparse_nested import new_level_proved
from exactsym.exact.tower import TowerElement

N = 4 * 999983


def system_with_levels(*rationals):
    """The sparse Kummer system of conductor N with sqrt(q) levels for ``rationals``."""
    system = SparseKummerSystem(N)
    roots = [system.sqrt(fmpq(q)) for q in rationals]
    return system, roots


def base(system, coefficients):
    """sum c_k cos(2 pi k / 999983) for (k, c) in ``coefficients``, plus 3 (positive)."""
    total = system.coerce(fmpq(3))
    for k, c in coefficients:
        total = total + system.coerce(cos_turn(system.context, fmpq(k, 999983))) * c
    return total


small = st.lists(st.tuples(st.integers(1, 499991), st.integers(-2, 2)), min_size=1, max_size=3)


@settings(max_examples=12, deadline=None)
@given(small, st.lists(st.booleans(), min_size=3, max_size=3), small)
def test_squares_are_never_proved_new(z_terms, subset, w_terms):
    """x = z^2 prod_T k_m, a square of the tower: never a new level (the proof would be
    false), whichever rational levels T it uses; x = z^2 w for a non-square w usually is."""
    system, roots = system_with_levels(2, 7, 11)
    z = base(system, z_terms) + roots[0] * base(system, w_terms)      # level 1 involved
    x = z * z
    for k, use in zip((2, 7, 11), subset):
        if use:
            x = x * k
    assert not new_level_proved(system.tower, x.v)
    with pytest.raises(FieldTooLargeError):
        system.extended(x)


@pytest.mark.parametrize("terms", [[(1, 1)], [(5, -2), (77, 1)], [(123456, 2)]])
def test_non_squares_are_proved_new(terms):
    system, roots = system_with_levels(2, 7, 11)
    w = base(system, terms)
    for x in (w, w * roots[1], w * 7, (w + roots[0]) * 11):
        assert new_level_proved(system.tower, x.v if isinstance(x, TowerElement) else x)


def test_extended_tower_holds_the_root_and_the_old_numbers():
    system, roots = system_with_levels(2, 7)
    x = base(system, [(10, 1), (20, -1)]) + roots[1]
    before = system.tower.levels
    bigger = system.extended(x)
    assert system.tower.levels == before                  # the configuration's tower unchanged
    assert bigger.tower.levels == before + 1
    y = bigger.tower.wrap((bigger.tower.levels, bigger.tower.zero, bigger.tower.one))
    moved = bigger.coerce(x)                              # an old number, rewritten
    assert y * y == moved and y.sign() > 0
    assert bigger.coerce(roots[0]) * bigger.coerce(roots[0]) == 2
    # a rational whose root needs a new level above the nested one is refused
    with pytest.raises(FieldTooLargeError):
        bigger.sqrt(fmpq(13))
    assert bigger.sqrt(fmpq(14)) == bigger.coerce(roots[0]) * bigger.coerce(roots[1])


def test_adjoin_sqrt_over_the_sparse_base():
    system, roots = system_with_levels(3)
    x = (base(system, [(4, 1)]) + roots[0]) / (base(system, [(9, 2)]) + 1)
    found = adjoin_sqrt(system, [], x)
    assert found is not None
    bigger, root = found
    assert root * root == bigger.coerce(x) and root.sign() > 0
    # a square is not adjoined (no root-finding in the sparse base): out of reach, None
    square = x * x
    assert adjoin_sqrt(system, [], square) is None


def test_makeasym_radial_move_completes(tmp_path):
    """Four robots at radii sqrt(k), turns j/999983: MakeAsym moves a robot radially to
    another circle, a nested radical over the sparse base (the run stopped there,
    incomplete)."""
    path = tmp_path / "robots.toml"
    path.write_text(
        "format = 1\npoints = [\n" +
        "".join(f'  {{ r = "sqrt({k})", turn = "{t}/999983" }},\n' for k, t in (
            (191, 7503), (244, 5125), (299, 536), (8, 7445))) + "]\n")
    result = analyse(load(path))
    paper = result.paper
    assert paper.complete and paper.orderable
    assert any(m["kind"] == "to-G_t-circle" for m in paper.moves)


def test_ring_maps_of_the_extended_tower_agree_with_the_original():
    """The F_p images of a tower's numbers are remembered by (number, p, w): the maps of an
    extended tower must send the original levels where the original's maps do."""
    from exactsym.exact.tower_proof import tower_maps
    system, roots = system_with_levels(2, 7, 11)
    x = base(system, [(10, 1), (20, -1)]) + roots[1]
    bigger = system.extended(x)
    p, *maps = tower_maps(system.tower)
    q, *extended = tower_maps(bigger.tower)
    assert p == q
    known = dict(maps)                   # w -> the roots of the rational levels under it
    for w, levels in extended:
        assert len(levels) == 4
        if w in known:
            assert levels[:3] == known[w]
