"""Near symmetry as a hint: proposed by floats, stated only when proved exactly, and
never a change to the exact verdict."""

from __future__ import annotations

import doctest
import math
from fractions import Fraction

from hypothesis import given, settings, strategies as st

import exactsym.truth.near_symmetry as near
from exactsym.geometry.configuration import Configuration
from exactsym.exact import fmpq as Q
from exactsym.truth.near_symmetry import near_symmetry_hint
from exactsym.truth.symmetry import symmetry_group

from strategies import rational_group_points


def _decimal_polygon(k: int, digits: int = 6, radius: int = 1, shift=(0, 0), rotate=(1, 0)):
    """A regular k-gon typed with ``digits`` decimals, then moved by an exact similarity."""
    c, s = rotate
    pts = []
    for j in range(k):
        x = Fraction(round(radius * math.cos(2 * math.pi * j / k), digits)).limit_denominator(10 ** digits)
        y = Fraction(round(radius * math.sin(2 * math.pi * j / k), digits)).limit_denominator(10 ** digits)
        x, y = Q(x.numerator, x.denominator), Q(y.numerator, y.denominator)
        tx, ty = (Q(Fraction(v).numerator, Fraction(v).denominator) for v in shift)
        pts.append((c * x - s * y + tx, s * x + c * y + ty))
    return Configuration.from_points(pts)


def _proved(config, hint) -> bool:
    """Independent recheck: every robot within ``hint.bound`` of its place, exactly."""
    system = hint.candidate.system
    b2 = system.coerce(hint.bound * hint.bound)
    return all((system.coerce(x) - qx) ** 2 + (system.coerce(y) - qy) ** 2 <= b2
               for (x, y), (qx, qy) in zip(config.points, hint.candidate.points))


def test_decimal_hexagon_is_d2_within_a_millionth_of_d6():
    config = _decimal_polygon(6)
    hint = near_symmetry_hint(config)
    assert symmetry_group(config).name == "D2"            # the exact verdict
    assert (hint.exact_group, hint.candidate_group) == ("D2", "D6")
    assert hint.bound == Q(5, 10 ** 7) and _proved(config, hint)
    assert symmetry_group(hint.candidate).name == "D6"
    assert hint.text.startswith("exact group D2; within 5e-7 of D6")
    assert symmetry_group(config).name == "D2"            # unchanged by the hint


def test_the_bound_is_tight_enough_to_be_false_for_a_smaller_one():
    config = _decimal_polygon(6)
    hint = near_symmetry_hint(config)
    system = hint.candidate.system
    half = system.coerce((hint.bound / 2) ** 2)
    assert not all((system.coerce(x) - qx) ** 2 + (system.coerce(y) - qy) ** 2 <= half
                   for (x, y), (qx, qy) in zip(config.points, hint.candidate.points))


def test_the_shipped_decimal_hexagon_case():
    from pathlib import Path
    from exactsym.geometry.configuration import load
    config = load(Path(__file__).resolve().parents[2] / "cases/examples/decimal-hexagon.toml")
    hint = near_symmetry_hint(config)
    assert (hint.exact_group, hint.candidate_group, hint.bound) == ("D2", "D6", Q(5, 10 ** 7))
    assert _proved(config, hint)


def test_moved_pentagon_and_heptagon():
    """Metamorphic: an exact rotation (3/5, 4/5) and a translation keep the hint."""
    for k in (5, 7):
        config = _decimal_polygon(k, shift=(Fraction(1, 3), Fraction(-1, 2)),
                                  rotate=(Q(3, 5), Q(4, 5)))
        hint = near_symmetry_hint(config)
        assert hint is not None and hint.candidate_group == f"D{k}", k
        assert float(hint.bound) < 1e-5 and _proved(config, hint)


def test_decimal_chiral_nine_gon_is_near_c3_without_a_mirror():
    pts = []
    for r, t in [(4, 0), (4, 1 / 3), (4, 2 / 3), (3, 1 / 10), (3, 13 / 30), (3, 23 / 30),
                 (2, 1 / 4), (2, 7 / 12), (2, 11 / 12)]:
        x, y = (Fraction(round(r * f(2 * math.pi * t), 6)).limit_denominator(10 ** 6)
                for f in (math.cos, math.sin))
        pts.append((Q(x.numerator, x.denominator), Q(y.numerator, y.denominator)))
    config = Configuration.from_points(pts)
    hint = near_symmetry_hint(config)
    assert (hint.exact_group, hint.candidate_group) == ("C1", "C3")
    assert float(hint.bound) < 1e-6 and _proved(config, hint)


def test_no_hint_when_exactly_symmetric_or_far_from_symmetry():
    square = Configuration.from_points([(1, 0), (0, 1), (-1, 0), (0, -1)])
    assert near_symmetry_hint(square) is None
    scalene = Configuration.from_points([(0, 0), (4, 0), (1, 3), (-2, 1), (3, 5)])
    assert near_symmetry_hint(scalene) is None
    assert near_symmetry_hint(_decimal_polygon(6, digits=2)) is None   # 1e-3: not near


@settings(max_examples=15, deadline=None)
@given(st.sampled_from([("D4", 8), ("C4", 4)]).flatmap(
    lambda g: st.tuples(st.just(g[1]), rational_group_points(g[0], max_seeds=3))),
    st.integers(1, 50), st.data())
def test_a_nudged_symmetric_configuration_gets_a_proved_hint(order_points, nudge, data):
    order, points = order_points
    i = data.draw(st.integers(0, len(points) - 1))
    moved = list(points)
    x, y = moved[i]
    moved[i] = (x + Q(nudge, 10 ** 11), y)
    config = Configuration.from_points(moved)
    exact = symmetry_group(config)
    hint = near_symmetry_hint(config)
    assert hint is not None
    assert hint.exact_group == exact.name
    q = symmetry_group(hint.candidate)
    assert q.name == hint.candidate_group and q.rotations + q.mirrors >= order
    assert _proved(config, hint)


def test_docstring_examples_run():
    result = doctest.testmod(near)
    assert result.attempted >= 3 and result.failed == 0
