"""exactsym.exact.cyclotomic_reduce (remainders modulo Phi_M through Phi_r(x^s), products of
deflated operands) and inverse.remainder_function (Barrett) against the plain
``poly % Phi_M``: random polynomials, polynomials in x^g (subfield elements, the deflated
path), rational coefficients and signs, for M with s > 1 (27720, 72, 360, 8, 9) and
squarefree M (2310, 30: s = 1); radicals p and 2p (124, 279, 97, 3988: the binomial fold)."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from flint import fmpq_poly, fmpz_poly

from exactsym.exact.cyclotomic import cyclotomic_field
from exactsym.exact.cyclotomic_reduce import binomial_remainder, cyclotomic_arithmetic
from exactsym.exact.inverse import remainder_function

ORDERS = [27720, 72, 360, 2310, 30, 8, 9, 124, 279, 97, 3988]
PHI = {m: fmpz_poly.cyclotomic(m) for m in ORDERS}


def _poly(draw, length: int, step: int, bits: int) -> list:
    """Integer coefficients at the exponents divisible by ``step`` (a polynomial in x^step),
    some long runs of zeros, sizes up to 2^bits."""
    out = [0] * length
    for k in range(0, length, step):
        if draw(st.integers(0, 3)):
            out[k] = draw(st.integers(-(1 << bits), 1 << bits))
    return out


@st.composite
def remainder_cases(draw):
    m = draw(st.sampled_from(ORDERS))
    n = PHI[m].degree()
    step = draw(st.sampled_from([1, 1, 2, 3, 4, 6, 12]))
    length = draw(st.integers(0, 2 * n - 1))      # degree <= 2n - 2
    bits = draw(st.sampled_from([2, 64, 200]))
    if m in (27720, 3988):   # keep the big cases light: a random dense tail
        import random
        rnd = random.Random(draw(st.integers(0, 10 ** 6)))
        coeffs = [rnd.randrange(-(1 << bits), 1 << bits) if k % step == 0 else 0
                  for k in range(length)]
    else:
        coeffs = _poly(draw, length, step, bits)
    return m, fmpz_poly(coeffs)


@settings(max_examples=60, deadline=None)
@given(remainder_cases())
def test_remainder_is_the_plain_remainder(case):
    m, x = case
    expected = x % PHI[m]
    assert cyclotomic_arithmetic(m).remainder(x) == expected
    assert remainder_function(PHI[m])(x) == expected


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(ORDERS), st.integers(0, 10 ** 6))
def test_barrett_takes_degree_2n_minus_1(m, seed):
    import random
    rnd = random.Random(seed)
    n = PHI[m].degree()
    x = fmpz_poly([rnd.randrange(-10 ** 30, 10 ** 30) for _ in range(2 * n)])  # degree 2n - 1
    assert remainder_function(PHI[m])(x) == x % PHI[m]


@st.composite
def product_cases(draw):
    m = draw(st.sampled_from([m for m in ORDERS if m not in (27720, 3988)]))
    n = PHI[m].degree()
    terms = []
    for _ in range(draw(st.integers(1, 3))):
        pair = []
        for _ in range(2):
            step = draw(st.sampled_from([1, 2, 3, 4, 6, n + 1]))   # n + 1: a constant
            if draw(st.integers(0, 3)) == 0:    # a few terms at high exponents (sparse path)
                coeffs = [0] * n
                for _ in range(draw(st.integers(1, 9))):
                    e = draw(st.integers(0, (n - 1) // step)) * step
                    coeffs[e] = draw(st.integers(-(1 << 80), 1 << 80))
            else:
                coeffs = _poly(draw, draw(st.integers(0, n)), step,
                               draw(st.sampled_from([3, 80])))
            pair.append(fmpq_poly(coeffs, draw(st.integers(1, 10 ** 6))))
        terms.append((pair[0], pair[1], draw(st.sampled_from([1, -1]))))
    return m, terms


@settings(max_examples=80, deadline=None)
@given(product_cases())
def test_product_sum_is_the_plain_reduced_sum(case):
    m, terms = case
    arithmetic = cyclotomic_arithmetic(m)
    expected = fmpq_poly()
    for a, b, sign in terms:
        expected += sign * a * b
    expected = expected % fmpq_poly(PHI[m])
    prepared = [(arithmetic.prepared(a), arithmetic.prepared(b), sign) for a, b, sign in terms]
    assert arithmetic.product_sum(prepared) == expected


def test_field_products_in_the_large_field():
    """Q(zeta_27720) (degree 5760) multiplies through the split: the products of cosines
    and the field's reduce agree with the plain remainder."""
    from flint import fmpq
    from exactsym.exact.cyclotomic import cos_turn, sin_turn
    field = cyclotomic_field(27720)
    assert field.arithmetic() is not None
    minpoly = field.minpoly
    values = [cos_turn(field, fmpq(1, 11)), sin_turn(field, fmpq(3, 8)) * 2 + 1,
              cos_turn(field, fmpq(5, 12)) / 3, cos_turn(field, fmpq(7, 10)) + fmpq(1, 7)]
    for a in values:
        for b in values:
            assert (a * b).poly == (a.poly * b.poly) % minpoly
    square = values[0] * values[0]
    assert square == (1 + cos_turn(field, fmpq(2, 11))) / 2


def test_fused_complex_product_in_the_large_field():
    """fused.complex_product takes four deflated products in Q(zeta_27720) when every
    coordinate lies in a subfield (polynomials in x^2), Gauss's three otherwise: both
    give the plainly reduced coordinates."""
    from flint import fmpq
    from exactsym.exact.cyclotomic import cos_turn, sin_turn
    from exactsym.exact.fused import complex_product
    field = cyclotomic_field(27720)
    minpoly = field.minpoly

    def plain(a, b):
        (ax, ay), (bx, by) = a, b
        return ((ax.poly * bx.poly - ay.poly * by.poly) % minpoly,
                (ax.poly * by.poly + ay.poly * bx.poly) % minpoly)

    even = (cos_turn(field, fmpq(2, 77)) * 3, sin_turn(field, fmpq(5, 84)) + fmpq(1, 2))
    odd = (cos_turn(field, fmpq(3, 8)), sin_turn(field, fmpq(1, 9)) / 5)
    assert field.arithmetic().prepared(even[0].poly)[1] % 2 == 0
    for a, b in ((even, even), (even, odd), (odd, even)):
        x, y = complex_product(a, b)
        assert (x.poly, y.poly) == plain(a, b)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.fractions(min_value=-50, max_value=50, max_denominator=30),
                min_size=1, max_size=12),
       st.fractions(min_value=-5, max_value=5, max_denominator=7).filter(bool))
def test_equal_field_elements_hash_alike(coeffs, shift):
    """FieldElement.__hash__ (numerator's integers and denominator): an element reached
    two ways hashes alike, and a rational hashes as the fmpq it equals."""
    from flint import fmpq
    field = cyclotomic_field(28)
    x = field(fmpq(0))
    c = field(fmpq(1))
    from exactsym.exact.cyclotomic import cos_turn
    cosine = cos_turn(field, fmpq(1, 28))
    for q in coeffs:
        x = x + c * fmpq(q.numerator, q.denominator)
        c = c * cosine
    s = fmpq(shift.numerator, shift.denominator)
    y = (x * s + s) / s - 1
    assert x == y and hash(x) == hash(y)
    r = field(fmpq(3, 7))
    assert hash(r) == hash(fmpq(3, 7))


@settings(max_examples=60, deadline=None)
@given(st.sampled_from([3, 5, 6, 7, 10, 14, 62, 997, 1994]), st.integers(0, 10 ** 6),
       st.integers(0, 3))
def test_binomial_remainder_is_the_plain_remainder(r, seed, extra):
    """The fold for radicals p and 2p, on degrees up to (2 + extra) deg Phi_r (beyond the
    split's bound too: the fold repeats)."""
    import random
    rnd = random.Random(seed)
    phi = fmpz_poly.cyclotomic(r)
    x = fmpz_poly([rnd.randrange(-10 ** 40, 10 ** 40)
                   for _ in range(rnd.randint(0, (2 + extra) * phi.degree()))])
    assert binomial_remainder(r)(x) == x % phi


def test_binomial_remainder_only_for_p_and_2p():
    assert [r for r in range(2, 40) if binomial_remainder(r) is not None] == \
        [3, 5, 6, 7, 10, 11, 13, 14, 17, 19, 22, 23, 26, 29, 31, 34, 37, 38]
