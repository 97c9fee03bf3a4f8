"""The shortcuts for configurations in cyclotomic fields of degree thousands (issue 9's
off-centre polar files) against the exact computations they replace, on near ties.

* :func:`exactsym.exact.cyclotomic_text.cyclotomic_text` writes the same string as
  ``number_text``;
* :mod:`exactsym.exact.cyclotomic_modular` proves irrationality only of irrational
  numbers (rational ratios, equal values, values 10^-30 apart);
* the lazily keyed lines (:func:`exactsym.paper.keys.lazy_line_canon`) equal, hash and
  compare as the keys of the exact doubled directions;
* the Cartesian symmetries' matrices (:class:`exactsym.truth.isometries.LazyMatrix`) are those
  computed eagerly; CirclePolygon.one_circle and the remembered point vectors of
  exactsym.truth.symmetry give the exact answers.
"""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from flint import fmpq, fmpq_poly

from exactsym.geometry.configuration import load
from exactsym.exact import sign
from exactsym.exact.cyclotomic import cos_turn, cyclotomic_field, sin_turn
from exactsym.exact.cyclotomic_modular import product_ratio_irrational, ratio_irrational
from exactsym.exact.cyclotomic_text import cyclotomic_text, fast_number_text
from exactsym.exact.text import number_text
from exactsym.truth.isometries import LazyMatrix
from exactsym.paper.circle_polygon import CirclePolygon
from exactsym.exact.number import LARGE_DEGREE
from exactsym.paper.keys import (bisector_key, complex_product, lazy_line_canon, line_canon,
                                 line_key)
from exactsym.exact.ratio import rational_ratio
from exactsym.truth.symmetry import _directions, symmetry_group

M = 2520                                    # degree 576 >= LARGE_DEGREE
BIG = cyclotomic_field(M)
SMALL = cyclotomic_field(60)                # a subfield (60 | 2520), degree 16
assert BIG.degree >= LARGE_DEGREE
TINY = fmpq(1, 10 ** 30)

turns = st.integers(0, M - 1).map(lambda k: fmpq(k, M))
small_ints = st.integers(-4, 4)


def _unit(t):
    return (cos_turn(BIG, t), sin_turn(BIG, t))


@st.composite
def reals(draw, field=BIG):
    """Real elements: small integer combinations of cosines of multiples of 2 pi / M,
    sometimes plus a rational."""
    m = field.conductor
    out = field(draw(st.integers(-3, 3)))
    for _ in range(draw(st.integers(0, 3))):
        out = out + draw(small_ints) * cos_turn(field, fmpq(draw(st.integers(0, m - 1)), m))
    return out


@st.composite
def vectors(draw):
    """Non-zero vectors: scaled units (some at turns with rational cos^2: 1/8, 1/12...),
    units moved by 10^-30, or two random reals."""
    kind = draw(st.integers(0, 3))
    if kind == 0:
        t = fmpq(draw(st.sampled_from([0, 1, 2, 3, 5, 7])), 24)
        s = draw(st.integers(1, 5))
        u = _unit(t)
        return (s * u[0], s * u[1])
    if kind == 1:
        u = _unit(draw(turns))
        return (u[0] + TINY, u[1]) if draw(st.booleans()) else (u[0], u[1] - TINY)
    if kind == 2:
        u = _unit(draw(turns))
        return u
    x, y = draw(reals()), draw(reals())
    if x == 0 and y == 0:
        x = BIG(1)
    return (x, y)


# ---------------------------------------------------------------- texts

@settings(max_examples=60, deadline=None)
@given(st.sampled_from([5, 12, 60, 136, 2520]), st.data())
def test_cyclotomic_text_is_number_text(m, data):
    field = cyclotomic_field(m)
    coeffs = data.draw(st.lists(st.fractions(max_denominator=10 ** 12).filter(
        lambda q: abs(q) < 10 ** 30), max_size=field.degree))
    x = field.element(fmpq_poly([fmpq(q.numerator, q.denominator) for q in coeffs]))
    assert fast_number_text(x) == number_text(x)
    if not x.is_rational():
        assert cyclotomic_text(x) == number_text(x)


# ---------------------------------------------------------------- irrationality in F_p

@settings(max_examples=60, deadline=None)
@given(vectors())
def test_ratio_proved_irrational_only_when_irrational(d):
    x, y = d
    exact = rational_ratio(x * x, x * x + y * y)
    if ratio_irrational(x, y):
        assert exact is None
    # rational ratios (turns of denominator 24 have cos^2 in Q(sqrt 2, sqrt 3): only
    # multiples of 1/8 and 1/12 give rationals) are never called irrational
    if exact is not None:
        assert not ratio_irrational(x, y)


@settings(max_examples=40, deadline=None)
@given(vectors(), vectors())
def test_product_ratio_is_the_ratio_of_the_product(a, b):
    assert product_ratio_irrational(a, b) == ratio_irrational(*complex_product(a, b))


def test_rational_ratios_at_near_ties():
    u = _unit(fmpq(1, 8))                   # cos^2 = 1/2, exactly
    assert not ratio_irrational(*u)
    assert rational_ratio(u[0] * u[0], u[0] * u[0] + u[1] * u[1]) == fmpq(1, 2)
    moved = (u[0] + TINY, u[1])             # 10^-30 away: irrational, and proved so
    assert ratio_irrational(*moved)
    assert not ratio_irrational(BIG(3), BIG(4))         # 9/25
    assert not ratio_irrational(fmpq(3), fmpq(4))
    s = SMALL(1) + cos_turn(SMALL, fmpq(1, 60))         # a subfield element, scaled
    assert not ratio_irrational(3 * s, 4 * BIG(s))


def test_complex_product_is_the_product():
    a, b = _unit(fmpq(7, M)), (_unit(fmpq(11, M))[0] * 3, _unit(fmpq(11, M))[1] * 3)
    x = a[0] * b[0] - a[1] * b[1]
    y = a[0] * b[1] + a[1] * b[0]
    assert complex_product(a, b) == (x, y)
    assert complex_product(a, a) == (a[0] * a[0] - a[1] * a[1], 2 * a[0] * a[1])


# ---------------------------------------------------------------- lazy line keys

def _exact_line(a, b):
    return line_canon(complex_product(a, b))


@settings(max_examples=40, deadline=None)
@given(vectors(), vectors(), st.integers(1, 3), st.integers(1, 3))
def test_lazy_line_keys_equal_the_exact_ones(a, b, s, t):
    lazy = lazy_line_canon(a, b, lambda: complex_product(a, b))
    exact = _exact_line(a, b)
    if lazy is not None:
        assert lazy == exact and exact == lazy and hash(lazy) == hash(exact)
    # the same line from scaled vectors (equal keys, a near tie of nothing), and the
    # line moved by 10^-30 (a near tie of two different lines)
    a2, b2 = (s * a[0], s * a[1]), (t * b[0], t * b[1])
    same = bisector_key(False, a2, b2)
    assert same == bisector_key(False, a, b)
    assert hash(same) == hash(bisector_key(False, a, b))
    moved = (b[0] + TINY, b[1])
    if moved[0] != 0 or moved[1] != 0:
        k1, k2 = bisector_key(False, a, b), bisector_key(False, a, moved)
        assert (k1 == k2) == (_exact_line(a, b) == _exact_line(a, moved))


@settings(max_examples=20, deadline=None)
@given(vectors())
def test_line_key_along_a_vector(d):
    k = line_key(False, d)
    assert k == bisector_key(False, d, d)
    assert k.canon == _exact_line(d, d)
    x, y = k._vector
    assert (x, y) == complex_product(d, d)


def test_equal_lines_from_different_products_are_equal():
    a, b = _unit(fmpq(13, M)), _unit(fmpq(101, M))
    c, d = _unit(fmpq(50, M)), _unit(fmpq(64, M))          # 13 + 101 == 50 + 64
    k1, k2 = bisector_key(False, a, b), bisector_key(False, c, d)
    assert k1 == k2 and hash(k1) == hash(k2)
    e = (d[0], d[1] + TINY)
    assert bisector_key(False, c, e) != k1


# ---------------------------------------------------------------- symmetries, polygons

def test_lazy_matrix_is_the_eager_matrix():
    made = []

    def make():
        made.append(1)
        return ((fmpq(0), fmpq(-1)), (fmpq(1), fmpq(0)))
    m = LazyMatrix(make)
    assert not made
    (c, s), (s2, c2) = m
    assert (c, s, s2, c2) == (0, -1, 1, 0) and made == [1]
    assert m == ((0, -1), (1, 0)) and ((0, -1), (1, 0)) == m
    assert hash(m) == hash(((fmpq(0), fmpq(-1)), (fmpq(1), fmpq(0))))
    assert len(made) == 1


def test_symmetry_matrices_are_orthogonal_and_map_points(tmp_path):
    # a kite in polar form whose SEC centre is off the origin: the Cartesian path
    path = tmp_path / "kite.toml"
    path.write_text('format = 1\npoints = [\n  { r = "1", turn = "1/7" },\n'
                    '  { r = "1", turn = "6/7" },\n  { r = "3", turn = "0" },\n'
                    '  { r = "2", turn = "1/2" },\n]\n')
    config = load(path)
    group = symmetry_group(config)
    assert group.name == "D1" and group.mirror is not None
    assert isinstance(group.mirror.matrix, LazyMatrix)
    cx, cy = group.centre
    assert cx != 0
    for g in group.symmetries():
        (a, b), (c, d) = g.matrix
        assert a * a + c * c == 1 and a * b + c * d == 0 and b * b + d * d == 1
        for i, (x, y) in enumerate(config.points):
            u, v = x - cx, y - cy
            img = config.points[g.permutation[i]]
            assert cx + a * u + b * v == img[0] and cy + c * u + d * v == img[1]


def test_one_circle_on_near_ties():
    u, v = _unit(fmpq(3, M)), _unit(fmpq(700, M))
    assert CirclePolygon((0, 1), (u, v), False).one_circle
    assert not CirclePolygon((0, 1), (u, (v[0] + TINY, v[1])), False).one_circle
    assert CirclePolygon((0,), (u,), False).one_circle


def test_point_vectors_follow_the_centre():
    pts = [_unit(fmpq(k, 7)) for k in range(3)]
    first = _directions(pts, (BIG(0), BIG(0)), False, None)
    other = (fmpq(1, 2), BIG(0))
    second = _directions(pts, other, False, None)
    fresh = _directions([tuple(p) for p in pts], other, False, None)
    assert second[3] == fresh[3] and second[2] == fresh[2]
    assert first[3] != second[3]
    assert sign(first[3][0] - 1) == 0


@settings(max_examples=30, deadline=None)
@given(st.sampled_from([1, 4, 9, 12, 72, 125, 2520, 27720]), st.integers(-10 ** 6, 10 ** 6))
def test_root_of_unity_is_the_reduced_power(m, k):
    from exactsym.exact.cyclotomic import root_of_unity
    field = cyclotomic_field(m)
    assert root_of_unity(field, k).poly == fmpq_poly([0] * (k % m) + [1]) % field.minpoly


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 4), st.lists(st.booleans(), max_size=9))
def test_failure_texts_made_only_when_listed(examples, insides):
    """claims._Record.fail with functions for the detail and the witness lists the same
    entries as with the values, and calls them only for the failures it lists."""
    from exactsym.paper.family.claims import _Record
    eager, lazy, calls = _Record([], examples), _Record([], examples), []
    for k, inside in enumerate(insides):
        witness = {"k": k, "within_hypotheses": inside}
        eager.fail("s", ["G1"], f"failure {k}", witness)
        lazy.fail("s", ["G1"], lambda k=k: calls.append(k) or f"failure {k}",
                  lambda w=witness: w, within=inside)
    eager.summaries()
    lazy.summaries()
    assert eager.out == lazy.out and eager.trace == lazy.trace
    assert eager.within == lazy.within and eager.failures == lazy.failures
    assert calls == list(range(min(examples, len(insides))))


def test_cyclotomic_text_of_coefficients_beyond_python_digit_limit():
    """Coefficients of 20,000 bits (beyond Python's 4,300-digit conversion): written by
    FLINT, the same string as number_text."""
    x = BIG.element(fmpq_poly([3 ** 12_700 + 1, 0, -(5 ** 8_700), 7], 2 ** 20_000 + 1))
    assert not x.is_rational()
    assert cyclotomic_text(x) == fast_number_text(x) == number_text(x)


@settings(max_examples=30, deadline=None)
@given(vectors(), vectors())
def test_line_keys_of_the_same_factors_are_equal_without_a_product(a, b):
    """Two keys made from the same direction objects (a 1-gon's mirror and the line through
    its vertex) are equal with no complex product made; keys of different factors still
    compare as their exact doubled directions."""
    import exactsym.paper.keys as keys
    pairs = [(bisector_key(False, a, b), bisector_key(False, b, a)),
             (line_key(False, a), line_key(False, a))]
    lazy = [(k, h) for k, h in pairs if isinstance(k.canon[3], keys._DirectionKey)]
    made = keys.complex_product
    keys.complex_product = None         # any product made now raises TypeError
    try:
        assert all(k == h for k, h in lazy)
    finally:
        keys.complex_product = made
    assert (bisector_key(False, a, b) == line_key(False, a)) == \
        (line_canon(complex_product(a, b)) == line_canon(complex_product(a, a)))


@settings(max_examples=60, deadline=None)
@given(reals(), reals(), st.integers(-5, 5).filter(bool))
def test_quotient_proved_irrational_only_when_irrational(x, y, q):
    """quotient_irrational never calls a rational quotient irrational (x = q y, x/x, 0/y),
    and when it proves one irrational the exact quotient is not rational."""
    from exactsym.exact.cyclotomic_modular import quotient_irrational
    if y == 0:
        return
    assert not quotient_irrational(q * y, y) and not quotient_irrational(y, y)
    assert not quotient_irrational(0 * y, y)
    if quotient_irrational(x, y):
        assert not (x / y).is_rational()


@settings(max_examples=25, deadline=None)
@given(st.lists(turns, min_size=3, max_size=6, unique=True), st.integers(1, 3),
       st.booleans(), st.sampled_from([1, -1]))
def test_ordered_chord_keys_compare_as_the_exact_ones(ts, scale, near, orientation):
    """The strings of a polygon on one circle in a huge field hold ordered chord keys
    (balls, exact only for touching balls): equal, ordered and hashed as the exact keys
    -u.v, so Theorem 1 and Elect_Leader_Asym decide as with the exact strings (vertices
    at turns of 1/M, sometimes two of them 10^-30 apart in angle: a near tie)."""
    from exactsym.paper import polygon as P
    from exactsym.paper.circle_polygon import polygon_from_directions
    from exactsym.paper.polygon import strings as S
    dirs = [tuple(scale * c for c in _unit(t)) for t in ts]
    if near:          # a Pythagorean turn of 10^-30-ish: the same circle, a near tie
        a, b = fmpq(1 - 10 ** 60, 1 + 10 ** 60), fmpq(2 * 10 ** 30, 1 + 10 ** 60)
        x, y = dirs[0]
        dirs.append((a * x - b * y, b * x + a * y))
    poly = polygon_from_directions(list(range(len(dirs))), dirs, False)
    assert poly.one_circle and S._ordered_chords(poly)
    n = poly.n
    lazy = [k for m in range(n) for k in S.cw_string(poly, m, orientation)]
    exact = [poly.chord_key(m, (m - orientation * s) % n) for m in range(n) for s in range(1, n)]
    for a, ea in zip(lazy, exact):
        for b, eb in zip(lazy, exact):
            assert (a == b) == (ea == eb) and (a < b) == (ea < eb) and (a >= b) == (ea >= eb)
            if a == b:
                assert hash(a) == hash(b)
    plain = polygon_from_directions(list(range(len(dirs))), dirs, False)
    plain.__dict__["_ordered_chords"] = False        # the exact strings
    assert P.theorem1_asymmetric(poly, orientation) == P.theorem1_asymmetric(plain, orientation)
    for reading in ("literal", "unordered"):
        assert P.elect_leader_asym(poly, orientation, reading) == \
            P.elect_leader_asym(plain, orientation, reading)
