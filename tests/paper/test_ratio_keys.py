"""Division-free keys of the paper layer (exactsym/paper/ratio_keys.py) against the divided
keys they replace, in Q(zeta_136) (degree 64), and the
Newton-lifted inverse against the xgcd inverse at degree hundreds."""

from __future__ import annotations

from math import isqrt

import pytest
from hypothesis import assume, given, settings, strategies as st

from flint import fmpq, fmpq_poly, fmpz_poly

from exactsym.exact.context import AnalysisContext
from exactsym.exact import exact_key, sign
from exactsym.exact.cyclotomic import cos_turn, cyclotomic_field, sin_turn
from exactsym.exact.inverse import inverse_mod
from exactsym.paper.circle_polygon import CirclePolygon
from exactsym.paper.keys import (LineKey, ccw_gap_key, gap_ids, hashable_key, line_key,
                                 ray_key)
from exactsym.exact.number import LARGE_DEGREE, RATIO_KEY_DEGREE
from exactsym.exact.ratio import rational_ratio
from exactsym.paper.ratio_keys import AngleKey, RatioKey, ball_at, ray_ratio_key

FIELD = cyclotomic_field(136)
assert FIELD.degree >= RATIO_KEY_DEGREE


def _real(coeffs):
    """sum c_k cos(2 pi k / 136): a real element of the field."""
    out = FIELD(0)
    for k, c in enumerate(coeffs):
        if c:
            out = out + c * cos_turn(FIELD, fmpq(k, 136))
    return out


def _old_ray_key(d):
    x, y = d
    xx = x * x
    return (sign(x), sign(y), exact_key(xx / (xx + y * y)))


elements = st.lists(st.integers(-3, 3), min_size=1, max_size=6).map(_real)
turns = st.integers(0, 135).map(lambda k: fmpq(k, 136))
scales = st.lists(st.integers(-2, 2), min_size=1, max_size=3).map(
    lambda cs: 1 + _real(cs) * _real(cs))           # positive: 1 + c^2


def _unit(t):
    return (cos_turn(FIELD, t), sin_turn(FIELD, t))


def _vectors(draw_turns, draw_scales, extra):
    """Vectors on a few rays (exact cos/sin of turns, 45 degree rays among them: rational
    x^2 / |d|^2), each ray several times at different positive scales."""
    out = []
    for t in draw_turns:
        u = _unit(t)
        for s in draw_scales:
            out.append((s * u[0], s * u[1]))
    out += [(e, e) for e in extra if e != 0] + [(e, -2 * e) for e in extra if e != 0]
    return out


@settings(max_examples=15, deadline=None)
@given(st.lists(turns, min_size=1, max_size=4), st.lists(scales, min_size=1, max_size=3),
       st.lists(elements, max_size=2))
def test_ray_keys_equal_iff_the_divided_keys_are_equal(ts, ss, extra):
    vectors = _vectors(ts + [fmpq(1, 8), fmpq(3, 8)], ss, extra)
    new = [ray_key(False, v) for v in vectors]
    old = [_old_ray_key(v) for v in vectors]
    for a in range(len(vectors)):
        # a rational value keeps its exact key, an irrational one is a RatioKey
        assert (new[a] == old[a]) == (not isinstance(new[a][2], RatioKey))
        for b in range(len(vectors)):
            assert (new[a] == new[b]) == (old[a] == old[b])
            if new[a] == new[b]:
                assert hash(new[a]) == hash(new[b])
    assert len(set(new)) == len(set(old))


@settings(max_examples=15, deadline=None)
@given(st.lists(turns, min_size=1, max_size=4), st.lists(scales, min_size=1, max_size=2))
def test_line_keys_undivided_agree_with_their_values(ts, ss):
    """Line keys made from vectors (no division) equal those made from their divided
    values (LineKey.of), and the cached value of a line is its divided value."""
    vectors = _vectors(ts + [fmpq(1, 17)], ss, [])
    for v in vectors:
        key = line_key(False, v)
        x, y = v
        doubled = (x * x - y * y, 2 * x * y)
        value = (sign(doubled[0]), doubled[1] / doubled[0]) if sign(doubled[0]) \
            else (0, sign(doubled[1]))
        assert key.value == value
        assert LineKey.of(value) == key and hash(LineKey.of(value)) == hash(key)
        assert key.text == LineKey.of(value).text
        # one key per vector object in an analysis (a lone vertex's mirror is the line of
        # its direction: equal without exact products); an equal vector made apart gets
        # an equal key
        with AnalysisContext().active():
            key = line_key(False, v)
            assert line_key(False, v) is key and line_key(False, (x * 1, y * 1)) == key


@settings(max_examples=15, deadline=None)
@given(st.lists(turns, min_size=3, max_size=7, unique=True), st.lists(scales, min_size=1,
                                                                       max_size=3))
def test_gap_ids_equal_the_divided_gap_keys(ts, ss):
    """Polygons whose vertices lie at different distances (the G_ij of the family layer):
    the AngleKey ids equal the ids of the divided gap keys; right angles and 45 degree
    gaps put the value on a hash-cell boundary (the exact sign decides the cell)."""
    ts = sorted(set(ts) | {fmpq(0), fmpq(1, 8), fmpq(1, 4), fmpq(1, 2)})
    dirs = []
    for i, t in enumerate(ts):
        s = ss[i % len(ss)]
        u = _unit(t)
        dirs.append((s * u[0], s * u[1]))
    poly = CirclePolygon(tuple(range(len(dirs))), tuple(dirs), False)
    n = len(dirs)
    ids: dict = {}
    old = [ids.setdefault(hashable_key(ccw_gap_key(False, dirs[i], dirs[(i + 1) % n])),
                          len(ids)) for i in range(n)]
    assert gap_ids(poly) == old


def test_angle_keys_compare_angles():
    a, b = _unit(fmpq(1, 136)), _unit(fmpq(9, 136))
    c, d = _unit(fmpq(50, 136)), _unit(fmpq(58, 136))
    two = FIELD(2) + cos_turn(FIELD, fmpq(1, 136))
    far = (two * d[0], two * d[1])
    ids = gap_ids(CirclePolygon((0, 1, 2, 3), (a, b, c, far), False))
    assert ids[0] == ids[2] and len(set(ids)) == 3   # a->b and c->far: 8/136 turn each
    key = ray_ratio_key(*a)
    assert isinstance(key, RatioKey) and not isinstance(key, AngleKey)


@settings(max_examples=20, deadline=None)
@given(elements, elements, st.integers(-5, 5))
def test_rational_ratio_is_the_quotient_when_rational(x, y, q):
    if y == 0:
        return
    assert rational_ratio(q * y, y) == fmpq(q)
    # a multiple except in one coefficient (the constant, or the leading one): not one
    moved = (q * y + 1) / y
    assert rational_ratio(q * y + 1, y) == (moved.to_fmpq() if moved.is_rational() else None)
    quotient = x / y
    expected = quotient.to_fmpq() if quotient.is_rational() else None
    assert rational_ratio(x, y) == expected


def test_ray_ratio_key_is_only_for_polynomial_fields():
    from exactsym.exact.multiquadratic import MQ
    small = cyclotomic_field(24)
    assert isinstance(ray_ratio_key(cos_turn(small, fmpq(1, 24)), sin_turn(small, fmpq(1, 24))),
                      RatioKey)
    assert ray_ratio_key(fmpq(1), fmpq(2)) is None
    root = MQ({2: fmpq(1)})
    assert ray_ratio_key(root, fmpq(1)) is None


def test_newton_inverse_equals_xgcd_inverse_at_degree_hundreds():
    """Q(zeta_641) (degree 640): the lifted inverse (from a 31-bit prime) equals the xgcd
    inverse over Q, times the input it is one, and the cache answers per minimal
    polynomial (an element of two fields has two inverses)."""
    phi = fmpq_poly(fmpz_poly.cyclotomic(641))
    a = fmpq_poly([(k * 7919) % 11 - 5 for k in range(40)] + [0] * 300 + [3, -1]) / 7
    u = inverse_mod(a, phi)
    assert (a * u) % phi == 1
    g, s, _ = a.xgcd(phi)
    assert u == s / g.coeffs()[0]
    assert inverse_mod(a, phi) == u
    other = fmpq_poly(fmpz_poly.cyclotomic(643))
    v = inverse_mod(a, other)
    assert (a * v) % other == 1 and v != u



@settings(max_examples=25, deadline=None)
@given(st.lists(turns, min_size=2, max_size=6, unique=True), st.lists(scales, min_size=1,
                                                                       max_size=2))
def test_lines_are_shown_in_the_order_of_their_divided_values(ts, ss):
    """``LineKey.display_key`` (no division) orders lines as their values (sign, slope)
    do, with the vertical doubled direction as (0, 0)."""
    lines = list({line_key(False, d) for d in _vectors(ts, ss, [])})

    def divided(k):
        s, v = k.value
        return (s, v if s else 0)
    assert sorted(lines, key=lambda k: k.display_key()) == sorted(lines, key=divided)


def test_a_slope_in_a_large_field_is_written_undivided_and_reads_back():
    from exactsym.io.expr import parse_expression
    from exactsym.exact import evaluate, number_system
    from exactsym.paper import keys
    field = cyclotomic_field(1024)                      # degree 512
    assert field.degree >= LARGE_DEGREE
    u = (cos_turn(field, fmpq(3, 1024)), sin_turn(field, fmpq(3, 1024)))
    key = line_key(False, (u[0] + 2, u[1]))
    text = key.text
    assert text.startswith("(1, (") and ")/(" in text
    slope = text[len("(1, "):-1]
    node = parse_expression(slope)
    value = evaluate(node, number_system([node]))
    assert value == key.value[1]                     # the same number as the division


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.integers(1, 29), st.integers(2, 12)), min_size=3, max_size=6,
                unique_by=lambda p: p[0]))
def test_ordered_chords_off_one_circle_agree_with_the_exact_keys(rows):
    """A polygon off one circle (a radial projection's) in a tower over the sparse
    Q(zeta_60): its strings' keys (ratio_keys.chord_key, from balls) are equal and ordered
    as the exact chord keys; v_i v_j and v_j v_i are equal without their products."""
    from exactsym.exact.evaluate import SparseKummerSystem
    from exactsym.paper.circle_polygon import polygon_from_directions
    from exactsym.paper.ratio_keys import chord_key
    system = SparseKummerSystem(60)
    dirs = []
    for t, k in rows:
        r = system.sqrt(fmpq(k))
        dirs.append((r * system.cos_turn(fmpq(t, 30)), r * system.sin_turn(fmpq(t, 30))))
    poly = polygon_from_directions(tuple(range(len(dirs))), dirs, False)
    n = poly.n
    pairs = [(i, j) for i in range(n) for j in range(n) if i != j]
    ordered = {p: chord_key(poly, *p) for p in pairs}
    assert ordered[(0, 1)] == ordered[(1, 0)]
    exact = {p: poly.chord_key(*p) for p in pairs}
    for p in pairs:
        for q in pairs:
            assert (ordered[p] == ordered[q]) == (exact[p] == exact[q])
            assert (ordered[p] < ordered[q]) == (exact[p] < exact[q])


@settings(max_examples=15, deadline=None)
@given(st.integers(2, 400), st.integers(1, 996), st.integers(2, 400), st.integers(1, 996))
def test_a_lazy_line_of_a_sparse_tower_is_shown_by_the_exact_slopes_decimal(k, s, m, t):
    """Square roots over the sparse Q(zeta_3988): the summary's text of a line whose
    doubled direction a b is not made is the decimal of the exact product's slope.  (Two
    square radii leave the tower without levels: the sparse field alone, whose lines are
    shown exactly.)"""
    assume(isqrt(k) ** 2 != k or isqrt(m) ** 2 != m)
    from exactsym.exact.evaluate import SparseKummerSystem
    from exactsym.paper.keys import _product_line, complex_product
    from exactsym.exact.text_numbers import quotient_decimal
    system = SparseKummerSystem(3988)

    def vector(q, turn):
        r = system.sqrt(fmpq(q))
        return (r * system.cos_turn(fmpq(turn, 997)), r * system.sin_turn(fmpq(turn, 997)))
    a, b = vector(k, s), vector(m, t)
    line = _product_line(a, b)
    shown = line._factor_decimal()
    if line._vector_ is not None:
        assert shown is None                 # made: the exact text is shown
        return
    x, y = complex_product(a, b)
    assert shown == f"({sign(x)}, ≈ {quotient_decimal(y, x)} (exact: in --json))"


@pytest.mark.parametrize("x, y", [(fmpq(10 ** 8) + fmpq(1, 3), fmpq(10 ** 8) + fmpq(2, 7)),
                                  (fmpq(10 ** 8) + fmpq(1, 3), fmpq(10 ** 8) + fmpq(1, 7)),
                                  (fmpq(-3 * 10 ** 9, 7), fmpq(10 ** 9) + fmpq(1, 11))])
def test_ratio_key_cells_of_large_values(x, y):
    """The cell floor(2^24 value) of a value beyond 10^16 from balls of numbers near 10^8
    (the first an integer: its cell is on a boundary): the balls' products and the floor
    are taken at the balls' precision (at 53 bits the radius stayed above 1 and the
    precision rose without end; a boundary read at 53 bits gave another cell)."""
    asked = []

    def value_ball(prec):
        asked.append(prec)
        assert prec <= 4096, "the ball never narrowed"
        return ball_at(x, prec) * ball_at(y, prec)
    key = RatioKey(lambda: (x * y, 1), value_ball, None)
    value = x * y * (1 << 24)
    assert hash(key) == hash(("ratio", int(value.p // value.q)))
    assert max(asked) <= 1024


def _cube_root_field():
    from flint import arb, ctx
    from exactsym.exact.field import NumberField

    def enclose(prec):
        with ctx.workprec(prec + 16):
            return arb(2).root(3)
    return NumberField(fmpq_poly([-2, 0, 0, 1]), enclose, "Q(2^(1/3))", "2^(1/3)")


@settings(max_examples=20, deadline=None)
@given(st.lists(st.tuples(*[st.integers(-4, 4)] * 6), min_size=2, max_size=3))
def test_strings_off_one_circle_in_a_general_field_need_no_inverse(rows):
    """Q(2^(1/3)), a field given by its minimal polynomial (as the gathering search's
    Q(gamma)): a polygon off one circle holds ordered keys undivided in its strings
    (strings._ordered_chords), equal and ordered as the exact divided keys, and building
    and comparing them takes no inverse.  Each vector also turned by a quarter turn:
    equal chords across the copies."""
    from exactsym.exact.field import PolyElement
    from exactsym.exact.number import general_field
    from exactsym.paper.circle_polygon import polygon_from_directions
    from exactsym.paper.polygon.strings import _ordered_chords, cw_string
    field = _cube_root_field()
    t = field.gen
    dirs = []
    for a, b, c, d, e, f in rows:
        u = (a + b * t + c * t * t, d + e * t + f * t * t)
        assume(u[0] != 0 or u[1] != 0)
        dirs += [u, (-u[1], u[0])]
    angles = {(sign(x), sign(y), exact_key(y / x) if x != 0 else None) for x, y in dirs}
    assume(len(angles) == len(dirs))                       # distinct directions
    poly = polygon_from_directions(tuple(range(len(dirs))), dirs, False)
    assume(not poly.one_circle)
    assert general_field(*poly.directions[0]) and _ordered_chords(poly)
    n = poly.n
    exact = {(i, j): poly.chord_key(i, j) for i in range(n) for j in range(n) if i != j}

    def refuse(self):
        raise AssertionError("an inverse was taken")
    original, PolyElement.inverse = PolyElement.inverse, refuse
    try:
        strings = [cw_string(poly, m) for m in range(n)]
        keys = {(m, (m - s) % n): strings[m][s - 1] for m in range(n) for s in range(1, n)}
        for p in keys:
            for q in keys:
                assert (keys[p] == keys[q]) == (exact[p] == exact[q])
                assert (keys[p] < keys[q]) == (exact[p] < exact[q])
    finally:
        PolyElement.inverse = original


def test_inverses_are_remembered_per_field_by_value():
    """PolyElement.inverse (the xgcd path): the same value asked again, another object,
    is read from the field's table; the answer is the inverse."""
    field = _cube_root_field()
    t = field.gen
    x = 3 + t - 2 * t * t
    first = x.inverse()
    assert first * x == 1
    assert len(field._inverses) == 1
    again = (3 + t - 2 * t * t).inverse()
    assert again == first and again.poly is first.poly
