"""The multi-modular inverse equals the xgcd inverse (exactsym/exact/inverse.py)."""

from __future__ import annotations

import random

from hypothesis import given, settings, strategies as st

from flint import fmpq, fmpq_poly, fmpz_poly

from exactsym.exact.inverse import inverse_mod

coefficients = st.lists(st.builds(fmpq, st.integers(-10**40, 10**40), st.integers(1, 10**30)),
                        min_size=1, max_size=12)


@settings(max_examples=30, deadline=None)
@given(coefficients, st.sampled_from([5, 12, 15, 21, 28]))
def test_inverse_mod_is_the_inverse(coeffs, m):
    phi = fmpq_poly(fmpz_poly.cyclotomic(m))
    a = fmpq_poly(coeffs) % phi
    if a.is_zero():
        return
    u = inverse_mod(a, phi)
    assert (a * u) % phi == 1
    g, s, _ = a.xgcd(phi)
    assert u == s / g.coeffs()[0]


def test_inverse_of_large_element_in_large_field():
    # an element with 3,000-bit coefficients in Q(zeta_2520), degree 576: was minutes by xgcd
    phi = fmpq_poly(fmpz_poly.cyclotomic(2520))
    draw = random.Random(1)
    a = fmpq_poly([draw.randint(-3, 3) for _ in range(576)])
    b = fmpq_poly([draw.randint(-3, 3) for _ in range(576)])
    quotient = (a * inverse_mod(b, phi)) % phi
    assert quotient.numer().height_bits() > 1000
    inv = inverse_mod(quotient, phi)
    assert (inv * quotient) % phi == 1
    assert inv == (b * inverse_mod(a, phi)) % phi


@settings(max_examples=15, deadline=None)
@given(st.sampled_from([28, 44, 124, 508]), st.integers(0, 10 ** 6))
def test_inverse_with_the_cyclotomic_remainder(m, seed):
    """The lift reduced by the field's remainder (the binomial fold for radicals p and
    2p, .cyclotomic_reduce) gives the inverse (unique: a u = 1 proves it)."""
    from exactsym.exact.cyclotomic_reduce import cyclotomic_arithmetic
    phi = fmpq_poly(fmpz_poly.cyclotomic(m))
    n = phi.degree()
    draw = random.Random(seed)
    a = fmpq_poly([draw.randint(-10 ** 6, 10 ** 6) for _ in range(draw.randint(2, n))],
                  draw.randint(1, 1000))
    if a.degree() <= 0:
        return
    calls = []

    def remainder(y):
        calls.append(y.degree())
        return cyclotomic_arithmetic(m).remainder(y)
    from exactsym.exact import inverse
    inverse._INVERSES.clear()                   # answers are remembered by value
    u = inverse_mod(a, phi, remainder)
    assert calls and (a * u) % phi == 1


# -- the dense (Karatsuba) product of multiquadratic elements equals the term-by-term one --

from exactsym.exact import multiquadratic as mqm, mq_products as mqp  # noqa: E402

mq_terms = st.dictionaries(st.sampled_from([1, 2, 3, 5, 6, 7, 10, 14, 15, 21, 30, 35, 42, 70,
                                            105, 210, 11, 22, 33]),
                           st.builds(fmpq, st.integers(-9, 9).filter(bool), st.integers(1, 4)),
                           min_size=1, max_size=19)


@settings(max_examples=40, deadline=None)
@given(mq_terms, mq_terms)
def test_dense_product_equals_term_product(a, b):
    saved = mqp._DENSE_PRODUCT
    try:
        mqp._DENSE_PRODUCT = 10 ** 9
        slow = mqm.MQ(dict(a)) * mqm.MQ(dict(b))
        fast = mqm.MQ(mqp._dense_product(
            dict(a), dict(b), sorted(mqp.coprime_base([m for m in set(a) | set(b) if m != 1]))))
    finally:
        mqp._DENSE_PRODUCT = saved
    assert fast == slow and fast.terms == slow.terms
