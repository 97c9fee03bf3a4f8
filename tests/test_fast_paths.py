"""The shortcuts of the gathering benchmark's speed-up against the exact routines they
stand in for: the integer and Kronecker products of multiquadratic elements against the
term-by-term product in ``fmpq``, and the Arb filter for roots in (0, 1) against the
exact root isolation (a polynomial it clears has no exact root inside)."""

from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym.exact import multiquadratic as mqm
from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import polyroots as pr

# radicands over the primes of the n = 30 run's last events, and small ones
PRIMES = (3, 5, 7, 17, 53)
RADICANDS = sorted({1, 2, 6, 10, 15, 21, 35, 3 * 53, 5 * 7 * 17, 3 * 5 * 7 * 17 * 53,
                    17 * 53, 2 * 3301, 5953, 3301 * 220057} | set(PRIMES))
dens = st.sampled_from([1, 2, 3, 7, 12, 35, 2 ** 61 - 1, 3 ** 40, 10 ** 30 + 7])
rationals = st.builds(lambda n, d: fmpq(n, d),
                      st.integers(-(1 << 300), 1 << 300) | st.integers(-40, 40), dens)
terms = st.dictionaries(st.sampled_from(RADICANDS), rationals, max_size=24).map(
    lambda d: {m: c for m, c in d.items() if c != 0})


@settings(max_examples=300, deadline=None)
@given(terms, terms)
def test_integer_and_dense_products_equal_the_rational_one(a, b):
    want = mqm._rational_product(a, b)
    assert mqm._integer_product(MQ(a), MQ(b)) == want
    base = mqm._coprime_base_of(frozenset(a) | frozenset(b))
    if base:
        assert mqm._dense_product(a, b, base) == want
    assert (MQ(a) * MQ(b)).terms == want


small = st.fractions(min_value=-6, max_value=6, max_denominator=12).map(
    lambda f: MQ.rational(fmpq(f.numerator, f.denominator)))
coeffs = st.tuples(small, st.sampled_from([1, 2, 3, 6, 15])).map(
    lambda t: t[0] * sqrt_rational(t[1]))
roots = st.fractions(min_value=-1, max_value=2, max_denominator=16).map(
    lambda f: MQ.rational(fmpq(f.numerator, f.denominator)))
irr_roots = st.tuples(roots, st.sampled_from([2, 3, 5])).map(
    lambda t: t[0] + sqrt_rational(t[1]) * fmpq(1, 4))


def _from_roots(rs, lead):
    p = (lead,)
    for r in rs:
        p = pr.pmul(p, (-r, MQ.rational(1)))
    return p


@settings(max_examples=300, deadline=None)
@given(st.lists(coeffs, min_size=2, max_size=6))
def test_filter_clears_only_polynomials_without_roots_inside(p):
    p = pr.trim(p)
    if pr.surely_no_root_in_unit(p):
        assert _exact_roots(p) == []


@settings(max_examples=200, deadline=None)
@given(st.lists(roots | irr_roots, min_size=1, max_size=4), coeffs.filter(bool),
       st.lists(coeffs, max_size=3))
def test_filter_never_clears_a_root_inside(rs, lead, extra):
    # roots at 0 and 1 exactly are divided out by the filter: they are not inside
    p = _from_roots(rs, lead)
    if extra and any(extra):
        p = pr.pmul(p, pr.padd(tuple(extra), (MQ.rational(0),)))
    inside = [r for r in rs if r.sign() > 0 and (r - 1).sign() < 0]
    if inside:
        assert not pr.surely_no_root_in_unit(p)
    if pr.surely_no_root_in_unit(p):
        assert _exact_roots(p) == []


def _exact_roots(p):
    """roots_in_unit without the filter (the exact isolation alone)."""
    saved = pr.surely_no_root_in_unit
    pr.surely_no_root_in_unit = lambda q, *a, **k: False
    try:
        return pr.roots_in_unit(p)
    finally:
        pr.surely_no_root_in_unit = saved


def test_filter_examples():
    f = MQ.rational
    assert pr.surely_no_root_in_unit((f(1), f(1)))                 # 1 + t
    assert not pr.surely_no_root_in_unit((f(-1), f(3)))            # root 1/3
    assert pr.surely_no_root_in_unit((f(0), f(1)))                 # root 0 only
    assert pr.surely_no_root_in_unit((f(1), f(-1)))                # root 1 only
    assert pr.surely_no_root_in_unit(_from_roots([f(0), f(1), f(2)], f(1)))
    assert not pr.surely_no_root_in_unit(_from_roots([f(0), f(fmpq(1, 2))], f(1)))
    assert not pr.surely_no_root_in_unit(())                       # identically zero
    # a double root inside (no sign change): never cleared
    assert not pr.surely_no_root_in_unit(_from_roots([sqrt_rational(fmpq(1, 2))] * 2,
                                                     f(1)))
