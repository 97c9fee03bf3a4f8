"""The fast number arithmetic equals the plain one: multiquadratic products (pair cache,
Kronecker dense product) against a slow reference kept here, term for term and in the same
canonical form (squarefree radicands, non-zero rational coefficients)."""

from math import gcd

from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym.exact.multiquadratic import MQ
from exactsym.exact.mq_products import _coprime_base_of, _dense_product

# pairwise products of these give radicands with shared and coprime factors
PRIMES = [2, 3, 5, 7, 11, 13]


def _squarefree_products(primes):
    out = [1]
    for p in primes:
        out += [m * p for m in out]
    return out


RADICANDS = _squarefree_products(PRIMES)          # 64 radicands: dense products possible
rationals = st.fractions(min_value=-10**6, max_value=10**6, max_denominator=10**4).map(
    lambda f: fmpq(f.numerator, f.denominator)).filter(lambda q: q != 0)
elements = st.dictionaries(st.sampled_from(RADICANDS), rationals, max_size=40).map(MQ)


def reference_product(a: dict, b: dict) -> dict:
    """Schoolbook product in fmpq with sqrt(m1) sqrt(m2) = g sqrt(m1 m2 / g^2)."""
    out: dict = {}
    for m1, c1 in a.items():
        for m2, c2 in b.items():
            g = gcd(m1, m2)
            m = (m1 // g) * (m2 // g)
            out[m] = out.get(m, fmpq(0)) + c1 * c2 * g
    return {m: c for m, c in out.items() if c != 0}


def _canonical(x: MQ) -> bool:
    return all(c != 0 and isinstance(c, fmpq) for c in x.terms.values())


@settings(max_examples=200, deadline=None)
@given(elements, elements)
def test_product_equals_reference(a, b):
    got = a * b
    assert got.terms == reference_product(a.terms, b.terms)
    assert _canonical(got)
    assert (b * a).terms == got.terms


@settings(max_examples=100, deadline=None)
@given(elements, elements)
def test_dense_product_equals_reference(a, b):
    """The Kronecker product directly, whatever the size heuristic picks."""
    if not a.terms or not b.terms:
        return
    base = _coprime_base_of(frozenset(a.terms) | frozenset(b.terms))
    dense = _dense_product(a.terms, b.terms, base)
    assert dense == reference_product(a.terms, b.terms)
    assert all(c != 0 for c in dense.values())


def test_dense_product_of_full_elements():
    """64-term elements (all radicands over six primes): the dense path is taken."""
    a = MQ({m: fmpq(m % 7 - 3 or 1, m % 5 + 1) for m in RADICANDS})
    b = MQ({m: fmpq(m % 11 - 5 or 2, m % 3 + 2) for m in RADICANDS})
    assert (a * b).terms == reference_product(a.terms, b.terms)
    assert a * a.inverse() == 1


# -- tower products: scaled to integer coefficients, then divided back ----------------------
from exactsym.exact import evaluate_all  # noqa: E402
from exactsym.exact.tower import TowerElement  # noqa: E402
from exactsym.io.expr import parse_expression  # noqa: E402

TOWER_GENERATORS = ["sqrt(2+sqrt(3+sqrt(5)))", "sqrt(7-sqrt(2+sqrt(3)))", "sqrt(5-sqrt(2))"]


def _tower_elements(data, values):
    out = []
    for _ in range(3):
        x = MQ.rational(fmpq(data.draw(st.integers(-9, 9)), data.draw(st.integers(1, 9))))
        for g in values:
            x = x + fmpq(data.draw(st.integers(-9, 9)), data.draw(st.integers(1, 50))) * g
        out.append(x)
    if out[1] != 0:
        out.append(out[0] / out[1])            # big common denominators, as inverses give
    return out


def _structure(v):
    """A raw tower value with every MQ's terms as a list (so term order counts too)."""
    if type(v) is tuple:
        return (v[0], _structure(v[1]), _structure(v[2]))
    return list(v.terms.items())


@settings(max_examples=10, deadline=None)
@given(st.data())
def test_tower_product_equals_unscaled_recursion(data):
    system, values = evaluate_all([parse_expression(t) for t in TOWER_GENERATORS])
    tower = system.tower
    xs = _tower_elements(data, values)
    for x in xs:
        for y in xs:
            rx = x.v if isinstance(x, TowerElement) else x
            ry = y.v if isinstance(y, TowerElement) else y
            assert _structure(tower.mul(rx, ry)) == _structure(tower._mul(rx, ry))


# -- large cyclotomic fields: Barrett remainders, Newton-lifted inverses ---------------------
from flint import fmpq_poly, fmpz_poly  # noqa: E402

from exactsym.exact.inverse import _inverse_multimodular, inverse_mod, remainder_function  # noqa: E402,E501

PHI = fmpz_poly.cyclotomic(1001)          # degree 720: above the Barrett threshold


def _poly(data, degree, bits):
    coeffs = data.draw(st.lists(st.integers(-2**bits, 2**bits), min_size=1, max_size=degree + 1))
    return fmpz_poly(coeffs)


@settings(max_examples=25, deadline=None)
@given(st.data())
def test_barrett_remainder_equals_division(data):
    rem = remainder_function(PHI)
    n = PHI.degree()
    x = _poly(data, 2 * n - 2, 200) * fmpz_poly([0] * data.draw(st.integers(0, n)) + [1])
    if x.degree() > 2 * n - 2:
        x = fmpz_poly(x.coeffs()[:2 * n - 1])
    assert rem(x) == x % PHI


@settings(max_examples=10, deadline=None)
@given(st.data())
def test_lifted_inverse_equals_multimodular(data):
    """In Q(zeta_143) (degree 120), elements with a few small coefficients."""
    step = data.draw(st.integers(1, 9))          # spread the terms over the degree
    spread = fmpz_poly(_poly(data, 12, 8)).inflate(step)
    a = fmpq_poly(spread) / data.draw(st.integers(1, 10**6))
    minpoly = fmpq_poly(fmpz_poly.cyclotomic(143))
    if (a % minpoly).is_zero():
        return
    u = inverse_mod(a, minpoly)
    assert (a * u) % minpoly == 1
    assert u == _inverse_multimodular(a, minpoly)


def test_field_products_reduce_like_division():
    from exactsym.exact.field import NumberField
    field = NumberField(fmpq_poly(PHI), lambda prec: None, "Q(zeta_1001)")
    x = fmpq_poly([fmpq(k % 17 - 8, k % 5 + 1) for k in range(720)])
    y = fmpq_poly([fmpq(k % 13 - 6, k % 7 + 2) for k in range(700)])
    assert field.reduce(x * y) == (x * y) % field.minpoly
