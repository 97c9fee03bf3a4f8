"""Verdicts shared per combinatorial shape (exactsym.paper.polygon_shape): a shared verdict
is the verdict computed on the polygon itself, the integer key is the exact key, and
polygons of different exact shape do share (the memo is not an exact-gap memo)."""

from __future__ import annotations

from fractions import Fraction

from hypothesis import given, settings
from hypothesis import strategies as st

from exactsym.exact import fmpq
from exactsym.paper import polygon_report
from exactsym.paper import polygon as P
from exactsym.paper.circle_polygon import CirclePolygon, polygon_from_directions
from exactsym.paper.polygon_shape import _exact_key, combinatorial_key

D4 = [((1, 0), (0, 1)), ((0, -1), (1, 0)), ((-1, 0), (0, -1)), ((0, 1), (-1, 0)),
      ((1, 0), (0, -1)), ((0, 1), (1, 0)), ((-1, 0), (0, 1)), ((0, -1), (-1, 0))]


def _unit(t: Fraction):
    """The rational point of the unit circle of Pythagorean parameter t."""
    d = 1 + t * t
    return ((1 - t * t) / d, 2 * t / d)


def _polygon(points, labels=None):
    labels = range(len(points)) if labels is None else labels
    return polygon_from_directions(labels, [(fmpq(x.numerator, x.denominator),
                                             fmpq(y.numerator, y.denominator))
                                            for x, y in points], False)


def _orbit(x, y, group):
    return [(a * x + b * y, c * x + d * y) for (a, b), (c, d) in group]


def test_d4_orbits_share_few_verdicts_and_each_is_its_own():
    """Generic D4 orbits (octagons of many exact shapes) fall into a few combinatorial
    shapes; every shared verdict equals the one computed on the polygon."""
    memo = polygon_report.VerdictMemo()
    polys = []
    for k, (x, y) in enumerate([(3, 1), (5, 2), (7, 1), (4, 3), (9, 5), (11, 2), (8, 7),
                                (13, 6), (1, 2), (2, 7)]):
        polys.append(_polygon(_orbit(Fraction(x), Fraction(y), D4),
                              [100 * k + j for j in range(8)]))
    for poly in polys:
        assert memo.verdicts(poly) == polygon_report.level_verdicts(poly)
    exact = {polygon_report.shape_key(p) for p in polys}
    assert len(memo.memo) < len(exact) == len(polys)


def test_integer_key_is_the_exact_key():
    for ts in ([Fraction(k, 7) for k in (0, 1, 2, 3, 5, 9, -4)],
               [Fraction(1, 3), Fraction(-1, 3), Fraction(3), Fraction(-3)],
               [Fraction(0), Fraction(1), Fraction(-1), Fraction(1, 2), Fraction(2)]):
        pts = [_unit(t) for t in ts] + [(-x, -y) for x, y in (_unit(ts[0]),)]
        poly = _polygon(sorted(set(pts)))
        assert combinatorial_key(poly) == _exact_key(poly)


_params = st.lists(st.fractions(min_value=-6, max_value=6, max_denominator=12),
                   min_size=4, max_size=12, unique=True)


@settings(max_examples=40, deadline=None)
@given(st.lists(_params, min_size=2, max_size=5),
       st.fractions(min_value=Fraction(1, 3), max_value=5, max_denominator=7))
def test_shared_verdict_is_the_computed_one_cartesian(params, scale):
    """Rational polygons of one circle (and their half-turned and reflected copies):
    wherever the memo shares a verdict it is the verdict of the polygon itself, and the
    integer key agrees with the exact key."""
    memo = polygon_report.VerdictMemo()
    for k, ts in enumerate(params):
        pts = {_unit(t) for t in ts}
        for copy in (pts, {(-x, -y) for x, y in pts}, {(x, -y) for x, y in pts},
                     pts | {(-x, -y) for x, y in pts}):
            if len(copy) < 4:
                continue
            poly = _polygon([(scale * x, scale * y) for x, y in sorted(copy)],
                            [1000 * k + j for j in range(len(copy))])
            assert combinatorial_key(poly) == _exact_key(poly)
            assert memo.verdicts(poly) == polygon_report.level_verdicts(poly)
            # the division-free lines of one circle are the lines of the general path
            # (vertex 0 moved along its ray: the same rays, not one circle any more)
            d0 = poly.directions[0]
            off = CirclePolygon(poly.labels, ((2 * d0[0], 2 * d0[1]),) + poly.directions[1:],
                                False)
            assert not off.one_circle and poly.one_circle
            assert P.straight_lines(off) == P.straight_lines(poly)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.lists(st.fractions(min_value=0, max_value=1, max_denominator=24),
                         min_size=4, max_size=12, unique=True), min_size=2, max_size=6))
def test_shared_verdict_is_the_computed_one_polar(turn_sets):
    memo = polygon_report.VerdictMemo()
    for k, turns in enumerate(turn_sets):
        turns = sorted({t % 1 for t in turns})
        if len(turns) < 4:
            continue
        poly = polygon_from_directions([100 * k + j for j in range(len(turns))],
                                       [fmpq(t.numerator, t.denominator) for t in turns],
                                       True)
        assert memo.verdicts(poly) == polygon_report.level_verdicts(poly)
