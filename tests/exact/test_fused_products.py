"""exactsym.exact.fused (sums of products reduced once in a large field) against the plain
operators, in Q(zeta_240) (degree 64: fused) and Q(zeta_12) (degree 4: plain), with
parallel vectors (a zero cross product) and vectors 10^-30 from parallel."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from flint import fmpq

from exactsym.exact.cyclotomic import cos_turn, cyclotomic_field
from exactsym.exact.fused import FUSE_DEGREE, complex_product, cross_is_zero, product_sum

BIG, SMALL = cyclotomic_field(240), cyclotomic_field(12)
assert BIG.degree >= FUSE_DEGREE > SMALL.degree
TINY = fmpq(1, 10 ** 30)


@st.composite
def reals(draw, field):
    m = field.conductor
    out = field(draw(st.integers(-3, 3)))
    for _ in range(draw(st.integers(1, 3))):
        out = out + draw(st.integers(-4, 4)) * cos_turn(field, fmpq(draw(st.integers(0, m - 1)), m))
    return out


@st.composite
def vector_pairs(draw):
    field = draw(st.sampled_from([BIG, SMALL]))
    u = (draw(reals(field)), draw(reals(field)))
    kind = draw(st.sampled_from(["free", "parallel", "near"]))
    if kind == "free":
        v = (draw(reals(field)), draw(reals(field)))
    else:
        k = draw(reals(field))
        v = (k * u[0], k * u[1])
        if kind == "near":
            v = (v[0] + TINY, v[1])
    return u, v


@settings(max_examples=120, deadline=None)
@given(vector_pairs())
def test_fused_products_equal_the_plain_ones(pair):
    (ux, uy), (vx, vy) = u, v = pair
    assert product_sum([(ux, vx), (uy, vy)]) == ux * vx + uy * vy
    assert product_sum([(ux, ux)]) == ux * ux
    assert complex_product(u, v) == (ux * vx - uy * vy, ux * vy + uy * vx)
    assert complex_product((ux, -uy), v) == (ux * vx + uy * vy, ux * vy - uy * vx)
    assert cross_is_zero(u, v) == (ux * vy - uy * vx == 0)


@settings(max_examples=80, deadline=None)
@given(st.sampled_from([BIG, SMALL]).flatmap(lambda f: st.tuples(reals(f), reals(f))),
       st.booleans())
def test_point_keys_are_equal_iff_the_numbers_are(pair, same):
    """paper.polygon.definitions._number_key (integer coefficients read at once) keys as
    exact_key does: equal iff equal, rational field elements as their rationals."""
    from exactsym.paper.polygon.definitions import _number_key
    x, y = pair
    if same:
        y = x + 0
    assert (_number_key(x) == _number_key(y)) == (x == y)
    if x.is_rational():
        assert _number_key(x) == _number_key(x.to_fmpq())


LARGE = cyclotomic_field(2520)              # degree 576 >= symmetry._KEY_DEGREE


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(reals(LARGE), st.booleans()), min_size=1, max_size=6), st.data())
def test_radii_interned_by_value_key_as_by_hash(values, data):
    """symbols.intern_symbols in a field of large degree (value_key) gives the ids the hash of
    the elements gives: equal ids iff equal radii (single radii and tuples of radii,
    rational elements among them, repeated values)."""
    from exactsym.exact.number import LARGE_DEGREE
    from exactsym.truth.symbols import intern_symbols
    assert LARGE.degree >= LARGE_DEGREE
    xs = [x if irrational else LARGE(data.draw(st.integers(0, 2))) for x, irrational in values]
    xs += [x + 0 for x in xs[: data.draw(st.integers(0, len(xs)))]]    # equal, other objects
    order = data.draw(st.permutations(range(len(xs))))
    xs = [xs[i] for i in order]
    singles = intern_symbols(xs, False)
    for i in range(len(xs)):
        for j in range(len(xs)):
            assert (singles[i] == singles[j]) == (xs[i] == xs[j])
    pairs = [(xs[i], xs[(i + 1) % len(xs)]) for i in range(len(xs))]
    ids = intern_symbols(pairs, True)
    for i in range(len(pairs)):
        for j in range(len(pairs)):
            assert (ids[i] == ids[j]) == (pairs[i] == pairs[j])
