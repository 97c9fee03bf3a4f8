"""Exact predicates, the smallest enclosing circle and the levels G1..Gt."""

import pytest
from hypothesis import given, settings, strategies as st

from exactsym.geometry.configuration import Configuration
from exactsym.exact import fmpq
from exactsym.geometry.predicates import (Turn, angular_sort, circumcentre, compare_directions,
                               compare_distance, midpoint, orientation, squared_distance)
from exactsym.geometry.levels import levels_of
from exactsym.geometry.sec import sec_by_brute_force, smallest_enclosing_circle

Q = fmpq


def P(x, y):
    return (Q(x), Q(y))


def test_orientation():
    assert orientation(P(0, 0), P(1, 0), P(0, 1)) is Turn.LEFT
    assert orientation(P(0, 0), P(0, 1), P(1, 0)) is Turn.RIGHT
    assert orientation(P(0, 0), P(1, 1), P(3, 3)) is Turn.COLLINEAR


def test_distances_and_constructions():
    assert squared_distance(P(1, 2), P(4, 6)) == 25
    assert compare_distance(P(0, 0), P(3, 4), P(5, 0)) == 0
    assert compare_distance(P(0, 0), P(1, 0), P(0, 2)) == -1
    assert midpoint(P(0, 0), P(3, 1)) == (Q(3, 2), Q(1, 2))
    assert circumcentre(P(0, 0), P(2, 0), P(0, 2)) == (Q(1), Q(1))
    with pytest.raises(ValueError):
        circumcentre(P(0, 0), P(1, 1), P(2, 2))


def test_angular_order_starts_on_the_positive_x_ray():
    pts = [P(1, 0), P(0, 1), P(-1, 0), P(0, -1), P(1, -1), P(1, 1)]
    assert angular_sort(P(0, 0), pts, list(range(6))) == [0, 5, 1, 2, 3, 4]
    assert compare_directions(P(1, 0), P(2, 0)) == 0


coords = st.integers(-30, 30)
point_sets = st.lists(st.tuples(coords, coords), min_size=1, max_size=9, unique=True)


@settings(max_examples=80, deadline=None)
@given(point_sets)
def test_sec_contains_everything_and_matches_brute_force(raw):
    pts = [P(x, y) for x, y in raw]
    circle = smallest_enclosing_circle(pts)
    assert all(circle.contains(p) for p in pts)
    assert all(squared_distance(circle.centre, pts[i]) == circle.radius_squared
               for i in circle.support)
    brute = sec_by_brute_force(pts)
    assert (circle.centre, circle.radius_squared) == (brute.centre, brute.radius_squared)


def _rotation(t):
    """Rational rotation from the Pythagorean parameter t: (cos, sin) = ((1-t^2), 2t)/(1+t^2)."""
    t = Q(t)
    return (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)


similarities = st.tuples(st.fractions(-3, 3, max_denominator=5), st.booleans(),
                         st.fractions(1, 4, max_denominator=3).filter(lambda s: s > 0),
                         st.tuples(st.fractions(-9, 9, max_denominator=4),
                                   st.fractions(-9, 9, max_denominator=4)))


def apply(similarity, p):
    t, mirror, scale, (dx, dy) = similarity
    c, s = _rotation(Q(t.numerator, t.denominator))
    x, y = p
    if mirror:
        y = -y
    k = Q(scale.numerator, scale.denominator)
    return (k * (c * x - s * y) + Q(dx.numerator, dx.denominator),
            k * (s * x + c * y) + Q(dy.numerator, dy.denominator))


@settings(max_examples=60, deadline=None)
@given(point_sets, similarities, st.randoms(use_true_random=False))
def test_sec_and_levels_map_along_under_similarities(raw, similarity, rnd):
    pts = [P(x, y) for x, y in raw]
    base = levels_of(Configuration.from_points(pts))
    order = list(range(len(pts)))
    rnd.shuffle(order)                      # moved[k] is the image of point order[k]
    moved = [apply(similarity, pts[i]) for i in order]
    ring = levels_of(Configuration.from_points(moved))
    assert ring.sec.centre == apply(similarity, base.sec.centre)
    k = Q(similarity[2].numerator, similarity[2].denominator)
    assert ring.sec.radius_squared == base.sec.radius_squared * k * k
    assert len(ring.levels) == len(base.levels)
    for old, new in zip(base.levels, ring.levels):
        assert new.radius_squared == old.radius_squared * k * k
        assert sorted(order[j] for j in new.points) == sorted(old.points)
        # counter-clockwise order is kept up to rotation (reversed by a mirror)
        mapped = [order[j] for j in new.points]
        cyc = list(old.points) if not similarity[1] else list(reversed(old.points))
        start = cyc.index(mapped[0])
        assert mapped == cyc[start:] + cyc[:start]


def test_levels_of_a_polar_polygon_use_turns():
    from exactsym.io.fileformat import parse_config_text
    from exactsym.geometry.configuration import from_file
    text = "\n".join(f"polar 1 {k}/7" for k in range(7)) + "\npolar 1/2 1/14\n"
    config = from_file(parse_config_text(text, "<test>", "txt"))
    ring = levels_of(config)
    assert ring.polar and ring.sec.radius_squared == 1
    assert [lv.points for lv in ring.levels] == [(7,), tuple(range(7))]
    # the same points in Cartesian form give the same SEC and levels
    cart = Configuration.from_points(config.points, system=config.system)
    cring = levels_of(cart)
    assert not cring.polar and cring.sec.radius_squared == 1
    assert [lv.points for lv in cring.levels] == [lv.points for lv in ring.levels]


def test_polar_configuration_off_centre_falls_back_to_cartesian():
    from exactsym.io.fileformat import parse_config_text
    from exactsym.geometry.configuration import from_file
    config = from_file(parse_config_text("polar 1 0\npolar 1 1/5\npolar 1 1/10\n", "<t>", "txt"))
    ring = levels_of(config)
    assert not ring.polar
    assert ring.sec.radius_squared < 1


def test_a_rational_centre_of_a_tower_is_proved_rational():
    """sec._rational_centre: (X/D, Y/D) rational only when X = q D exactly; a quotient within
    10^-40 of a rational (whose ball holds it) stays homogeneous, and so does a centre of a
    multiquadratic field (no determinant to carry)."""
    from exactsym.exact import evaluate_all
    from exactsym.io.expr import parse_expression
    from exactsym.geometry.sec import _rational_centre
    _, (d, e) = evaluate_all([parse_expression("2 + sqrt(1+sqrt(2))"),
                              parse_expression("10^-40*sqrt(1+sqrt(2))")])
    assert _rational_centre((d * fmpq(1, 7), d * fmpq(-3, 5), d)) == (fmpq(1, 7), fmpq(-3, 5))
    assert _rational_centre((d * 0, d, d)) == (0, 1)
    assert _rational_centre((d * fmpq(1, 7) + e, d, d)) is None
    assert _rational_centre((fmpq(1), fmpq(2), fmpq(3))) is None
