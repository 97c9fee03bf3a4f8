"""The products of cosine forms of :mod:`exactsym.exact.sparse_terms`: the dense product
(one fmpq_poly product of palindromes, for long forms of a moderate conductor) gives the same dictionary
as the product term by term, and both match cos e cos f = (cos(e + f) + cos(e - f))/2."""

from __future__ import annotations

from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym.exact import sparse_terms
from exactsym.exact.sparse_terms import _mul_cosines_dense, cosines_zero, mul_cosines


def _term_by_term(a: dict, b: dict, n: int) -> dict:
    """The product cos e cos f = (cos(e + f) + cos(e - f))/2 summed over all pairs."""
    out: dict = {}
    for e, c in a.items():
        for f, d in b.items():
            for t in (e + f, abs(e - f)):
                t = min(t, n - t)
                out[t] = out.get(t, 0) + c * d / 2
    return {t: c for t, c in out.items() if c != 0}


@st.composite
def _forms(draw):
    n = draw(st.sampled_from([2, 3, 4, 5, 14, 15, 16, 17, 60, 61, 1404]))
    h = n // 2

    def form():
        exps = draw(st.lists(st.integers(0, h), max_size=40, unique=True))
        coeffs = [fmpq(draw(st.integers(-9, 9)), draw(st.integers(1, 5))) for _ in exps]
        return {e: c for e, c in zip(exps, coeffs) if c != 0}
    return form(), form(), n


@settings(max_examples=300, deadline=None)
@given(_forms())
def test_dense_product_is_the_product_term_by_term(forms):
    a, b, n = forms
    want = _term_by_term(a, b, n)
    assert _mul_cosines_dense(a, b, n) == want
    assert _mul_cosines_dense(b, a, n) == want
    assert mul_cosines(a, b, n) == want


def test_products_by_hand():
    # cos^2 x = (1 + cos 2x)/2 at x = 2 pi/7; cos(2 pi/4) = 0 kills any product
    assert _mul_cosines_dense({1: fmpq(1)}, {1: fmpq(1)}, 7) == {0: fmpq(1, 2), 2: fmpq(1, 2)}
    # e + f = n/2 and e - f = 0 at n = 8: cos(pi/2) cos(pi/2) = (cos(pi) + 1)/2 = 0
    assert _mul_cosines_dense({2: fmpq(1)}, {2: fmpq(1)}, 8) == {4: fmpq(1, 2), 0: fmpq(1, 2)}
    assert cosines_zero(_mul_cosines_dense({2: fmpq(1)}, {2: fmpq(1)}, 8), 8)
    # a rational factor (f = 0) scales
    assert _mul_cosines_dense({0: fmpq(3)}, {5: fmpq(2), 1: fmpq(-1)}, 13) == \
        {5: fmpq(6), 1: fmpq(-3)}


def test_long_forms_take_the_dense_product(monkeypatch):
    """Forms of 100 terms at N = 1404 go through the dense product (the term loop is not
    called), and give the term-by-term answer."""
    calls = []
    monkeypatch.setattr(sparse_terms, "_mul_cosines_dense",
                        lambda a, b, n: calls.append(n) or _term_by_term(a, b, n))
    a = {e: fmpq(e + 1, 3) for e in range(0, 700, 7)}
    b = {e: fmpq(1 - e, 2) for e in range(1, 700, 7)}
    assert mul_cosines(a, b, 1404) == _term_by_term(a, b, 1404) and calls == [1404]
    # coefficients over many denominators (their common one is huge): term by term
    c = {e: fmpq(1, 2 ** 61 - 1 + 2 * e) for e in range(0, 700, 7)}
    assert mul_cosines(c, b, 1404) == _term_by_term(c, b, 1404) and calls == [1404]
    # a huge conductor with short forms: term by term
    assert mul_cosines({1: fmpq(1)}, {2: fmpq(1)}, 4 * 999983) == \
        {3: fmpq(1, 2), 1: fmpq(1, 2)} and calls == [1404]
