"""Moves and frames on Configuration (exact numbers, never expressions): ``moved``,
``with_positions``, ``transformed``; an impossible move raises MoveImpossible."""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given, settings, strategies as st

from exactsym.geometry.configuration import Configuration, Polar, Similarity, load
from exactsym.errors import InputError, MoveImpossible
from exactsym.exact import fmpq, number_text
from exactsym.geometry.levels import levels_of
from exactsym.truth.symmetry import symmetry_group
from strategies import polar_configuration

Q = fmpq


def _texts(points):
    return [(number_text(x), number_text(y)) for x, y in points]


def test_polar_move_stays_polar_and_exact():
    config = polar_configuration([(1, 0), (1, Fraction(1, 3)), (2, Fraction(2, 3))])
    moved = config.moved(2, Polar(config.radius(0), Q(5, 6)))
    assert moved.polar[2] == (Q(1), Q(5, 6)) and moved.radii[2] == 1
    assert moved.polar[:2] == config.polar[:2] and config.polar[2] == (Q(4), Q(2, 3))
    # the same positions read from a file give the same configuration, Cartesian too
    again = polar_configuration([(1, 0), (1, Fraction(1, 3)), (1, Fraction(5, 6))])
    assert moved.polar == again.polar
    assert _texts(moved.points) == _texts(again.points)    # fields: two objects, one field


def test_impossible_moves_are_not_input_errors():
    config = polar_configuration([(1, 0), (1, Fraction(1, 2)), (2, Fraction(1, 4))])
    with pytest.raises(MoveImpossible, match="robots 0 and 2 would coincide"):
        config.moved(2, Polar(Q(1), Q(1)))
    assert not issubclass(MoveImpossible, InputError)
    with pytest.raises(MoveImpossible, match="negative radius"):
        config.moved(0, Polar(Q(-1), Q(0)))
    cart = Configuration.from_points([(0, 0), (3, 0)], model="fat")
    assert cart.moved(1, (Q(2), Q(0))).points[1] == (2, 0)      # touching is allowed
    with pytest.raises(MoveImpossible, match="overlap"):
        cart.moved(1, (Q(1), Q(1)))


def test_the_robot_at_the_centre_has_turn_zero():
    config = polar_configuration([(1, 0), (1, Fraction(1, 2)), (2, Fraction(1, 4))])
    assert config.moved(2, Polar(Q(0), Q(1, 3))).polar[2] == (Q(0), Q(0))


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.integers(1, 5), st.integers(0, 11)), min_size=2, max_size=7,
                unique=True),
       st.booleans(), st.integers(0, 11), st.integers(1, 3))
def test_polar_similarity_is_the_same_file_in_another_frame(pts, reflect, k, scale):
    """transformed(Similarity(reflect, turn, scale)) equals the configuration read from
    the transformed polar file, and keeps the symmetry group (metamorphic)."""
    config = polar_configuration([(r, Fraction(t, 12)) for r, t in pts])
    sim = Similarity(reflect=reflect, turn=Q(k, 12), scale=scale)
    image = config.transformed(sim)
    want = polar_configuration([(r * scale, (Fraction(-t if reflect else t, 12)
                                             + Fraction(k, 12)) % 1) for r, t in pts])
    assert image.polar == want.polar
    assert symmetry_group(image, levels_of(image)).name == \
        symmetry_group(config, levels_of(config)).name


def test_cartesian_similarity_is_exact():
    config = Configuration.from_points([(0, 0), (4, 0), (2, 3)])
    sim = Similarity(reflect=True, rotation=(Q(3, 5), Q(4, 5)), scale=2,
                     shift=(Q(1, 3), Q(-1, 2)))
    image = config.transformed(sim)
    # (x, y) -> (x, -y) -> rotate (3/5, 4/5) -> 2x -> + (1/3, -1/2)
    assert image.points[2] == (2 * (Q(6, 5) + Q(12, 5)) + Q(1, 3),
                               2 * (Q(8, 5) - Q(9, 5)) - Q(1, 2))
    assert symmetry_group(image, levels_of(image)).name == "D1"


def test_a_polar_file_made_cartesian_keeps_its_points():
    config = load("cases/examples/chiral-nine-gon.toml")
    cart = config.cartesian()
    assert cart.polar is None and cart.points == config.points and cart.n == config.n


def test_a_polar_copy_with_irrational_radii_is_built_from_its_expressions():
    """Issue 32: radii written as square roots (sqrt(1499), sqrt(1511)) at sevenths of a
    turn: the reflected, turned and scaled copy has Cartesian points (they used to raise
    NotImplementedError), each at twice its radius, and the same levels and group."""
    from pathlib import Path

    from exactsym.exact import fmpq as q
    from exactsym.geometry.configuration import Similarity, load
    from exactsym.truth.symmetry import symmetry_group
    path = Path(__file__).resolve().parents[2] / "cases/examples/square-roots-over-turns-7.toml"
    config = load(path)
    copy = config.transformed(Similarity(reflect=True, turn=q(1, 7), scale=2))
    for (x, y), r2 in zip(copy.points, (1499, 1511, 4)):
        assert x * x + y * y == 4 * r2
    assert [t for _, t in copy.polar] == [q(0), q(5, 7), q(2, 7)]   # -t + 1/7, mod 1
    assert symmetry_group(copy).name == symmetry_group(config).name == "C1"
