"""Products and remainders modulo Phi_M through Phi_r(x^s): the arithmetic of Q(zeta_M) at
degree thousands (issue 9: Q(zeta_27720), degree 5,760, spent most of a full check reducing
products modulo Phi_M by Barrett's method, two dense products of degree 5,760 each).

With r the product of the primes dividing M and s = M / r, Phi_M(x) = Phi_r(x^s).  Writing
P(x) = sum_j x^j P_j(x^s) (j < s, P_j takes the coefficients of the exponents j mod s),

    P mod Phi_M = sum_j x^j (P_j mod Phi_r)(x^s),

each term of degree < s deg Phi_r = deg Phi_M: the canonical remainder, by s Barrett
reductions of degree deg Phi_r (480 for M = 27720) instead of one of degree 5,760.  The
split is done one prime p of s at a time (P(x) = sum_{j<p} x^j Q_j(x^p), Q_j reduced
modulo Phi_r(y^(s/p))), so a class that is empty (an element of a subfield: most products
of a polar file's coordinates are polynomials in x^2) costs one test.  For the same reason
a product of two polynomials in x^g (g | s) is computed as the product of their
deflations, of half the degree or less, and reduced modulo Phi_r(y^(s/g)), y = x^g.

FLINT's ``fmpz_poly.deflate(n)`` keeps the coefficients of the exponents divisible by n (it
assumes the others are zero and does not look at them); :func:`_deflate_keeps_multiples`
checks that once, and the split falls back to Python lists if it ever stops being so.
When r is an odd prime p or 2p (turns j/997 give M = 4 * 997), Phi_r divides the binomial
y^p - 1 or y^p + 1 with a linear cofactor, so the base remainder is a fold and one
subtraction (:func:`binomial_remainder`), linear in the degree, instead of Barrett's two
products.  Integer arithmetic only; a property test compares every result with
``x % Phi_M``.
"""

from __future__ import annotations

from math import gcd

from flint import fmpq_poly, fmpz_poly

from .factor import factorization
from .inverse import remainder_function


def _deflate_keeps_multiples() -> bool:
    try:
        return fmpz_poly([1, 2, 3, 4, 5]).deflate(2) == fmpz_poly([1, 3, 5])
    except (AttributeError, TypeError, ValueError):   # no deflate, or one that refuses
        # a polynomial not in x^n
        return False


_DEFLATE_SLICES = _deflate_keeps_multiples()


def _class(y: fmpz_poly, j: int, p: int) -> fmpz_poly:
    """Q_j with y = sum_{j<p} x^j Q_j(x^p)."""
    if _DEFLATE_SLICES:
        return (y.right_shift(j) if j else y).deflate(p)
    return fmpz_poly(y.coeffs()[j::p])


def binomial_remainder(r: int):
    """``y -> y mod Phi_r`` for deg y <= 2 deg Phi_r - 1 when r is an odd prime p or 2p,
    else None.  Phi_p = (y^p - 1) / (y - 1) = 1 + y + ... + y^(p-1) and Phi_2p(y) =
    Phi_p(-y) = (y^p + 1) / (y + 1): y^p = eps (mod Phi_r), eps = 1 or -1, so the
    coefficients of y^(p+k) fold onto y^k (times eps) until the degree is at most p - 1;
    then Phi_r (monic, degree p - 1) times the coefficient c of y^(p-1) is subtracted: the
    canonical remainder."""
    factors = factorization(r)
    odd = [q for q in factors if q != 2]
    if len(odd) != 1 or any(e > 1 for e in factors.values()) or r not in (odd[0], 2 * odd[0]):
        return None
    p = odd[0]
    eps = 1 if r == p else -1
    phi = fmpz_poly.cyclotomic(r)

    def remainder(y: fmpz_poly) -> fmpz_poly:
        while y.degree() >= p:
            high = y.right_shift(p)
            y = y.truncate(p) + high if eps == 1 else y.truncate(p) - high
        c = y[p - 1]
        return y - c * phi if c else y
    return remainder


#: at most this many nonzero coefficients (and degree at least _SPARSE_DEGREE): a factor is
#: multiplied term by term.  FLINT packs a product into one long integer product (Kronecker
#: substitution) whatever the zeros: a two-term cosine of degree 1,600 times a dense
#: number of 8,000-bit coefficients took 28 ms, its two scaled shifts 3 ms.
_SPARSE_TERMS = 8
_SPARSE_DEGREE = 64


def sparse_terms(a: fmpz_poly):
    """``[(exponent, coefficient)]`` of ``a`` when it has at most :data:`_SPARSE_TERMS`
    nonzero coefficients and degree at least :data:`_SPARSE_DEGREE`, else None."""
    n = a.degree()
    if n < _SPARSE_DEGREE:
        return None
    # more than _SPARSE_TERMS nonzero among 17 probes: dense, without listing n coefficients
    if sum(1 for k in range(17) if a[k * n // 16]) > _SPARSE_TERMS:
        return None
    cs = a.coeffs()
    if len(cs) - cs.count(0) > _SPARSE_TERMS:
        return None
    return [(e, c) for e, c in enumerate(cs) if c]


def _product(a: fmpz_poly, b: fmpz_poly, ta, tb, ka: int, kb: int) -> fmpz_poly:
    """``a * b``; ``ta``/``tb``: the terms of a/b deflated by ka/kb (a(x) = A(x^ka)),
    or None.  A factor with few terms is multiplied as a sum of the other factor's scaled
    shifts (the same polynomial, exactly)."""
    for terms, k, other in ((ta, ka, b), (tb, kb, a)):
        if terms is not None:
            out = None
            for e, c in terms:
                part = other * c
                if e:
                    part = part.left_shift(e * k)
                out = part if out is None else out + part
            return out
    return a * b


class CyclotomicArithmetic:
    """Remainders and products modulo Phi_M for integer polynomials (numerators)."""

    def __init__(self, order: int):
        primes = factorization(order)
        r = 1
        for p in primes:
            r *= p
        self.order = order
        self.s = order // r
        self.phi_r = fmpz_poly.cyclotomic(r)
        self.degree = self.phi_r.degree() * self.s
        # degree <= 2 deg Phi_r - 1
        self._base = binomial_remainder(r) or remainder_function(self.phi_r)
        # the primes of s with multiplicity, 2 first (the class test that most often
        # finds half the coefficients zero)
        self._steps = sorted(p for p, e in factorization(self.s).items() for _ in range(e)) \
            if self.s > 1 else []

    def remainder(self, y: fmpz_poly, g: int = 1) -> fmpz_poly:
        """``y(x^g) mod Phi_M`` as a polynomial in x^g, for g | s and
        deg y <= 2 deg Phi_M / g - 1."""
        t = self.s // g
        if y.degree() < self.degree // g:
            return y
        if 2 * self.degree // g <= y.degree():      # beyond the split's bound
            return y % self.phi_r.inflate(t)
        steps = list(self._steps)
        for p, e in factorization(g).items() if g > 1 else ():
            for _ in range(e):
                steps.remove(p)
        return self._split(y, t, steps)

    def _split(self, y: fmpz_poly, t: int, steps: list) -> fmpz_poly:
        """y mod Phi_r(x^t), t the product of ``steps``."""
        if t == 1:
            return self._base(y)
        p, rest = steps[0], steps[1:]
        out = None
        for j in range(p):
            piece = _class(y, j, p)
            if piece.is_zero():
                continue
            part = self._split(piece, t // p, rest).inflate(p)
            if j:
                part = part.left_shift(j)
            out = part if out is None else out + part
        return fmpz_poly() if out is None else out

    def prepared(self, a: fmpq_poly) -> tuple:
        """``(denominator, d, numerator deflated by d, its sparse terms or None)`` with d
        the gcd of the exponents of ``a`` (0 for a constant: a polynomial in every x^g).
        The numerator is not kept (elements remember this form): it is the deflation
        inflated by d."""
        an = a.numer()
        if a.degree() <= 0:
            return int(a.denom()), 0, an, None
        q, d = an.deflation()
        return int(a.denom()), d, q, sparse_terms(q)

    def product_sum(self, terms) -> fmpq_poly:
        """``sum(sign * a * b) mod Phi_M`` over ``terms``, ``(a, b)`` or ``(a, b, sign)``
        with sign +-1 and :meth:`prepared` operands of
        degree < deg Phi_M: the products of the deflations by the largest g | s that all
        operands admit, over one common denominator, reduced once."""
        g = self.s
        common = 1
        for term in terms:
            a, b = term[0], term[1]
            g = gcd(g, a[1], b[1])
            d = a[0] * b[0]
            common = common // gcd(common, d) * d
        g = g or 1
        total = None
        for term in terms:
            (da, dega, qa, ta), (db, degb, qb, tb) = term[0], term[1]
            if qa.is_zero() or qb.is_zero():
                continue
            # g divides every nonzero d: the operands deflated by g
            ka = 1 if dega in (g, 0) else dega // g
            kb = 1 if degb in (g, 0) else degb // g
            an = qa if ka == 1 else qa.inflate(ka)
            bn = qb if kb == 1 else qb.inflate(kb)
            p = _product(an, bn, ta, tb, ka, kb)
            factor = common // (da * db) * (term[2] if len(term) > 2 else 1)
            if factor != 1:
                p *= factor
            total = p if total is None else total + p
        if total is None:
            return fmpq_poly()
        out = self.remainder(total, g)
        if g > 1:
            out = out.inflate(g)
        return fmpq_poly(out) / common if common != 1 else fmpq_poly(out)


_ARITHMETIC: dict = {}


def cyclotomic_arithmetic(order: int) -> CyclotomicArithmetic:
    found = _ARITHMETIC.get(order)
    if found is None:
        if len(_ARITHMETIC) > 8:
            _ARITHMETIC.clear()
        found = _ARITHMETIC[order] = CyclotomicArithmetic(order)
    return found


__all__ = ["CyclotomicArithmetic", "cyclotomic_arithmetic"]
