"""Products and signs of the terms ``{radicand: coefficient}`` of a multiquadratic number
(:class:`.multiquadratic.MQ`): term by term in ``fmpq``, over integers with one gcd per
term of the result, or through the Kronecker product over a coprime base; signs by floats
with a proven error bound, then by Arb balls.  The functions take plain dictionaries (or
an element's cached integers), so they need not know the class.

Public names: :func:`rational_product`, :func:`integer_terms`, :func:`product_integers`,
:func:`canonical_terms`, :func:`integer_product`, :func:`coprime_base`, :func:`sqrt_arb`,
:func:`float_sign`, :func:`arb_sign`.
"""

from __future__ import annotations

from functools import lru_cache
from math import gcd, lcm

from flint import arb, ctx, fmpq, fmpz, fmpz_poly


_ULP = 2.0 ** -52
_MAX_PREC = 1 << 16

#: term pairs above which a product may go through the dense Kronecker product (3^k steps)
_DENSE_PRODUCT = 64

#: (m1, m2) -> (m, g) with sqrt(m1) sqrt(m2) = g sqrt(m), for squarefree m1, m2
_PAIRS: dict = {}
_PAIRS_MAX = 1 << 20


#: ... when the pairs are at least this many times 3^k (the Kronecker product's slots):
#: its conversions and reduction cost more per slot than a pair of the integer product
_DENSE_RATIO = 4

#: term pairs from which the product runs over integers (:func:`product_integers`)
INTEGER_PRODUCT = 16


def rational_product(a: dict, b: dict) -> dict:
    """The product term by term: in ``fmpq`` each product and sum is made canonical (two
    gcds), cheap for small rationals only (the reference the other products are tested
    against); in ``fmpz`` (:func:`product_integers`) the sums stay integers."""
    out: dict = {}
    pairs = _PAIRS
    for m1, c1 in a.items():
        for m2, c2 in b.items():
            # sqrt(m1) sqrt(m2) = g sqrt(m), cached: the same radicands meet again and again
            mg = pairs.get((m1, m2))
            if mg is None:
                mg = _radicand_product(m1, m2)
            m, g = mg
            c = c1 * c2 if g == 1 else c1 * c2 * g
            v = out.get(m)
            out[m] = c if v is None else v + c
    return {m: c for m, c in out.items() if c != 0}


def integer_terms(terms: dict, force: bool = False) -> tuple:
    """``({m: fmpz numerator}, den)``: the terms over their least common denominator;
    ``(None, den)`` when that denominator is much longer than the longest one (unrelated
    denominators: the numerators would grow by all of them), unless ``force``."""
    den, top = 1, 1
    for c in terms.values():
        q = int(c.q)
        if q != 1:
            den = lcm(den, q)
            top = max(top, q)
    if not force and den.bit_length() > 2 * top.bit_length() + 64:
        return None, den
    return {m: fmpz(c.p) * (den // int(c.q)) if c.q != 1 else fmpz(c.p) * den
            for m, c in terms.items()}, den


def _integers_of(x) -> tuple:
    """:func:`integer_terms` of an element, kept on it (an element is never changed, and the
    same coordinate meets many products: a robot's distances to all the others)."""
    if x._ints is None:
        x._ints = integer_terms(x.terms)
    return x._ints


def product_integers(x, y):
    """``({m: fmpz}, den)`` with ``x y = sum v / den sqrt(m)`` (zero sums may be kept), or
    None when a factor's denominators are unrelated (:func:`integer_terms`).  Each factor is
    scaled to integers over its common denominator, and the term products are summed as
    integers: no gcd until the caller makes each sum canonical once
    (:func:`canonical_terms`), where the term-by-term product pays two gcds per pair -- on
    the coefficients of thousands of bits of the critical instants, 5 to 10 times less.
    A square (``y is x``) takes each unordered pair once; many pairs over few primes go
    through the Kronecker product (:func:`_dense_integers`).  The same value, radicand
    by radicand, as :func:`rational_product`."""
    A, da = _integers_of(x)
    if A is None:
        return None
    square = y is x or y.terms is x.terms
    if square:
        B, db = A, da
    else:
        B, db = _integers_of(y)
        if B is None:
            return None
    la, lb = len(A), len(B)
    if la * lb > _DENSE_PRODUCT:
        base = _coprime_base_of(frozenset(A) | frozenset(B))
        if 3 ** len(base) * _DENSE_RATIO <= la * lb:
            return _dense_integers(A, B, base), da * db
    out: dict = {}
    pairs = _PAIRS
    if square:                  # c_i c_j sqrt(m_i m_j) twice for i < j, once for i = j
        items = list(A.items())
        for i, (m1, c1) in enumerate(items):
            c = c1 * c1 * m1 if m1 != 1 else c1 * c1
            v = out.get(1)
            out[1] = c if v is None else v + c
            c1 = c1 * 2
            for m2, c2 in items[i + 1:]:
                mg = pairs.get((m1, m2))
                if mg is None:
                    mg = _radicand_product(m1, m2)
                m, g = mg
                c = c1 * c2 if g == 1 else c1 * c2 * g
                v = out.get(m)
                out[m] = c if v is None else v + c
        return out, da * da
    return rational_product(A, B), da * db


def canonical_terms(out: dict, den: int) -> dict:
    """``{m: v / den}`` for the non-zero sums ``v`` (each reduced once: one gcd)."""
    if den == 1:
        return {m: fmpq(v) for m, v in out.items() if v}
    den = fmpz(den)
    return {m: fmpq(v, den) for m, v in out.items() if v}


def integer_product(x, y) -> dict:
    """``x y`` over integers (:func:`product_integers`), term by term when it declines."""
    r = product_integers(x, y)
    return rational_product(x.terms, y.terms) if r is None else canonical_terms(*r)


def _radicand_product(m1: int, m2: int) -> tuple[int, int]:
    if m1 == m2:
        mg = (1, m1)
    else:
        g = gcd(m1, m2)
        mg = ((m1 // g) * (m2 // g), g)
    if len(_PAIRS) >= _PAIRS_MAX:
        _PAIRS.clear()
    _PAIRS[(m1, m2)] = mg
    return mg


@lru_cache(maxsize=1024)
def _coprime_base_of(radicands: frozenset) -> tuple[int, ...]:
    return tuple(sorted(coprime_base([m for m in radicands if m != 1])))


@lru_cache(maxsize=1024)
def _mask_radicands(base: tuple) -> tuple:
    """The radicand of each mask over ``base`` (bit i: ``base[i]`` divides it)."""
    out = []
    for mask in range(2 ** len(base)):
        m = 1
        for i, p in enumerate(base):
            if mask >> i & 1:
                m *= p
        out.append(m)
    return tuple(out)


def _dense_product(a: dict, b: dict, base) -> dict:
    """The product by Kronecker substitution (:func:`_dense_integers`), canonical."""
    A, da = integer_terms(a, force=True)
    B, db = integer_terms(b, force=True)
    return canonical_terms(_dense_integers(A, B, base), da * db)


def _dense_integers(A: dict, B: dict, base) -> dict:
    """The product of two elements with many terms, integer coefficients ``A``, ``B``, by
    Kronecker substitution.  Over a coprime base b_1..b_k of their radicands the field is
    Z[x_1..x_k]/(x_i^2 - b_i) (tensored with Q): substitute x_i = X^(3^(i-1)) (every
    exponent of the product is at most 2, so base-3 digits do not carry), multiply the
    two integer polynomials in FLINT, then reduce x_i^2 = b_i digit by digit.  The terms
    come out in the order of the radicands' masks over the base."""
    k = len(base)
    masks: dict = {}

    def poly(terms):
        coeffs = [0] * ((3 ** k + 1) // 2)
        for m, c in terms.items():
            index = masks.get(m)
            if index is None:
                index = 0
                for i, p in enumerate(base):
                    if m % p == 0:
                        index += 3 ** i
                masks[m] = index
            coeffs[index] = c
        return fmpz_poly(coeffs)

    pa = poly(A)
    c = (pa * pa if B is A else pa * poly(B)).coeffs()
    c += [0] * (3 ** k - len(c))
    s = 1
    for p in base:      # digit i in {0, 1, 2} -> {0, 1}: x_i^2 = b_i
        out: list = []
        for j in range(0, len(c), 3 * s):
            out += [x + p * z if z else x for x, z in zip(c[j:j + s], c[j + 2 * s:j + 3 * s])]
            out += c[j + s:j + 2 * s]
        c = out
        s *= 2
    radicands = _mask_radicands(tuple(base))
    return {radicands[mask]: v for mask, v in enumerate(c) if v}


def coprime_base(radicands) -> list[int]:
    """Pairwise coprime integers > 1 whose products give every radicand (gcd refinement)."""
    base: list[int] = []
    for m in radicands:
        pending = [m]
        while pending:
            x = pending.pop()
            if x == 1:
                continue
            for i, b in enumerate(base):
                g = gcd(x, b)
                if g > 1:
                    del base[i]
                    pending.extend(y for y in (g, b // g, x // g) if y > 1)
                    break
            else:
                base.append(x)
    return base



@lru_cache(maxsize=4096)
def _sqrt_arb_at(m: int, prec: int) -> arb:
    old = ctx.prec
    ctx.prec = prec
    try:
        return arb(m).sqrt()
    finally:
        ctx.prec = old


def sqrt_arb(m: int) -> arb:
    return _sqrt_arb_at(m, ctx.prec)


def float_sign(terms: dict):
    """The sign from doubles when the sum is provably away from zero, else ``None``.
    Each term ``c*sqrt(m)`` is within 5 units of rounding (conversions, root, product)
    and the sum adds one per term, so the error is below ``(k + 6) * 2^-52 * S`` with
    ``S`` the sum of magnitudes, provided nothing overflowed or went subnormal."""
    try:
        vals = [float(c) * (float(m) ** 0.5) for m, c in terms.items()]
    except OverflowError:
        return None
    s_abs = sum(abs(v) for v in vals)
    if not (1e-280 < s_abs < 1e280):
        return None
    total = sum(vals)
    bound = (len(vals) + 6) * _ULP * s_abs
    if total > bound:
        return 1
    if total < -bound:
        return -1
    return None


def arb_sign(terms: dict) -> int:
    prec = 64
    while prec <= _MAX_PREC:
        old = ctx.prec
        ctx.prec = prec
        try:
            total = arb(0)
            for m, c in terms.items():
                total += arb(c.p) / arb(c.q) * _sqrt_arb_at(m, prec)
            if total > 0:
                return 1
            if total < 0:
                return -1
        finally:
            ctx.prec = old
        prec *= 2
    raise ArithmeticError("sign undecided at maximal precision (non-zero element)")
