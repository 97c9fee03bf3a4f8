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
