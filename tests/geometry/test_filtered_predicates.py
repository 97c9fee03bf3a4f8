"""Filtered predicates equal exact ones, on adversarial near-ties (issue 9).

``PseudoAngle`` (division-free diamond angle) against the exact ``pseudo_angle`` that
divides; ``sorted_by_value`` and ``intern_by_value`` (Arb balls propose, exact decides)
against exact sorting and equality.  Vectors are drawn so that many are parallel, nearly
parallel (1e-30 apart) or exactly opposite, in Q and in a multiquadratic and a cyclotomic
field."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from exactsym.exact import evaluate_all, fmpq
from exactsym.io.expr import parse_expression
from exactsym.geometry.predicates import PseudoAngle, intern_by_value, sorted_by_value
from exactsym.truth.symmetry import pseudo_angle

_, (R2, C7) = evaluate_all([parse_expression("sqrt(2)"), parse_expression("sqrt(3)")])
_, (Z,) = evaluate_all([parse_expression("cos(2*pi/7)")])
TINY = fmpq(1, 10 ** 30)
units = {"rational": fmpq(1), "sqrt": R2 + C7, "cyclotomic": Z}


def vectors(unit):
    base = st.tuples(st.integers(-3, 3), st.integers(-3, 3)).filter(lambda v: v != (0, 0))
    nudge = st.sampled_from([0, 0, 1, -1])
    scale = st.sampled_from([1, 2, 3])
    return st.builds(lambda v, e, k: (k * v[0] * unit + e * TINY, k * v[1] * unit),
                     base, nudge, scale)


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(sorted(units)).flatmap(
    lambda kind: st.lists(vectors(units[kind]), min_size=1, max_size=10)))
def test_pseudo_angles_filtered_equal_exact(vecs):
    exact = [pseudo_angle(x, y) for x, y in vecs]
    lazy = [PseudoAngle(x, y) for x, y in vecs]
    n = len(vecs)
    for i in range(n):
        for j in range(n):
            assert (lazy[i] == lazy[j]) == (exact[i] == exact[j])
            assert (lazy[i] < lazy[j]) == (exact[i] < exact[j])
        for k in (0, 1, 2, 3, 4):
            assert (lazy[i] == k) == (exact[i] == k)
    order = sorted_by_value(list(range(n)), lazy)
    assert [exact[i] for i in order] == sorted(exact)
    ids = intern_by_value(lazy)
    for i in range(n):
        for j in range(n):
            assert (ids[i] == ids[j]) == (exact[i] == exact[j])


# -- the SEC with a homogeneous centre, against brute force, on cocircular near-ties ------

from exactsym.geometry.sec import sec_by_brute_force, smallest_enclosing_circle  # noqa: E402
from exactsym.geometry.predicates import squared_distance  # noqa: E402

S2, S3 = R2, C7


def algebraic_points():
    coordinate = st.builds(lambda a, b, c: a + b * S2 + c * S3, st.integers(-3, 3),
                           st.integers(-2, 2), st.integers(-2, 2))
    point = st.tuples(coordinate, coordinate)
    # a point nudged by 1e-30 off another's position makes near-ties on the circle
    return st.lists(point, min_size=2, max_size=6, unique_by=lambda p: (str(p[0]), str(p[1]))
                    ).flatmap(lambda pts: st.sampled_from([pts, pts + [(pts[0][0] + TINY,
                                                                        pts[0][1])]]))


@settings(max_examples=30, deadline=None)
@given(algebraic_points())
def test_homogeneous_sec_equals_brute_force(points):
    if len({(str(x), str(y)) for x, y in points}) < len(points):
        return
    circle = smallest_enclosing_circle(points)
    brute = sec_by_brute_force(points)
    assert circle.centre == brute.centre and circle.radius_squared == brute.radius_squared
    assert all(circle.contains(p) for p in points)
    assert all(squared_distance(circle.centre, points[i]) == circle.radius_squared
               for i in circle.support)


# ------------------------------------------- gaps on one circle, with reflections (strings)
from exactsym.paper.filtered import circle_gap_tokens  # noqa: E402

_S2 = None


def _scale():
    """1 + sqrt(2), an algebraic factor (the tokens' ball path)."""
    global _S2
    if _S2 is None:
        _, (_S2,) = evaluate_all([parse_expression("1 + sqrt(2)")])
    return _S2


def _unit(t):
    t = fmpq(t)
    return ((1 - t * t) / (1 + t * t), 2 * t / (1 + t * t))


def _times(u, v):
    return (u[0] * v[0] - u[1] * v[1], u[0] * v[1] + u[1] * v[0])


def _angle(u, v):
    """The exact angle from unit vector u to unit vector v as (cross sign, dot)."""
    c = u[0] * v[1] - u[1] * v[0]
    return (0 if c == 0 else (1 if c > 0 else -1), u[0] * v[0] + u[1] * v[1])


@settings(max_examples=40, deadline=None)
@given(st.lists(st.integers(-6, 6).map(lambda k: fmpq(k, 3)), min_size=2, max_size=6,
                unique=True),
       st.lists(st.tuples(st.integers(0, 5), st.integers(0, 5), st.integers(0, 5),
                          st.booleans()), min_size=1, max_size=8))
def test_circle_gap_tokens_with_reflections(params, picks):
    """Gaps between points of one circle of squared radius L (scale L) and gaps to
    reflections u^2 conj(w), of length L^(3/2) (scale 1), in one call: tokens equal iff
    the exact angles are (string_classes compares a string's patched gaps so)."""
    units = [_unit(t) for t in params]
    s = _scale()
    vec = [(s * x, s * y) for x, y in units]
    length = vec[0][0] * vec[0][0] + vec[0][1] * vec[0][1]
    pairs, angles = [], []
    n = len(units)
    for i in range(n):
        pairs.append((vec[i], vec[(i + 1) % n], length))
        angles.append(_angle(units[i], units[(i + 1) % n]))
    for i, k, m, first in picks:
        i, k, m = i % n, k % n, m % n
        u, w = vec[k], vec[m]
        flipped = _times(_times(u, u), (w[0], -w[1]))
        unit = _times(_times(units[k], units[k]), (units[m][0], -units[m][1]))
        pair = (vec[i], flipped, None) if first else (flipped, vec[i], None)
        pairs.append(pair)
        angles.append(_angle(units[i], unit) if first else _angle(unit, units[i]))
    tokens = circle_gap_tokens(pairs)
    for x in range(len(pairs)):
        for y in range(x):
            assert (tokens[x] == tokens[y]) == (angles[x] == angles[y])
