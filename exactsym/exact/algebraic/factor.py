"""Factoring over a multiquadratic field K = Q(sqrt q : q prime), by Trager's algorithm.

:func:`factor_over_k` factors a square-free polynomial with MQ coefficients into
irreducible factors over ``K``, the field of its coefficients' primes: the norm
``N(x) = prod_sigma sigma(p)(x - s theta)`` over the automorphisms of ``K`` (each flips the
sign of one ``sqrt q``; ``theta`` the sum of the ``sqrt q``, a primitive element; the shift
``s = 0, 1, 2, ...`` until ``N`` is square-free) is a rational polynomial, python-flint
factors it over Q, and the gcd over ``K`` of ``p(x - s theta)`` with each rational factor is
an irreducible factor over ``K`` (Trager 1976, Algebraic factoring and rational function
integration, valid for any number field).  :func:`stable` tells whether a factor stays
irreducible over every multiquadratic extension of ``K`` (:mod:`.algebraic_numbers`).
"""

from __future__ import annotations

from functools import lru_cache

from flint import fmpq, fmpq_poly, fmpz

from ..multiquadratic import MQ
from .polynomials import ONE, bounded_gcd, monic, peval, pmul, shift, trim

__all__ = ["factor_over_k", "group_basis", "stable", "changes_sign", "MAX_NORM_DEGREE",
           "GCD_BITS"]

#: The largest degree of the rational norm factored (degree of p times 2^#primes of K).
MAX_NORM_DEGREE = 96
#: The largest coefficient size (bits of a rational) of a remainder in a gcd over K.
GCD_BITS = 20000


def group_basis(p, radicands=()) -> tuple:
    """``(basis, coords)``: squarefree ``b_1, ..., b_d`` independent modulo squares with
    ``K = Q(sqrt b_1, ..., sqrt b_d)`` (``[K:Q] = 2^d``), and ``coords(m)``: the set of
    ``j`` with ``m = prod_{j} b_j`` modulo squares, for every radicand ``m`` of ``p``
    (Gaussian elimination over GF(2) on the primes' exponent vectors), and for every
    one of the extra squarefree ``radicands`` (K then holds their square roots too).  The
    automorphism ``sigma_j`` flips the sign of ``sqrt m`` iff ``j`` is in ``coords(m)``."""
    rads = sorted({m for c in p for m in c.radicands()} | {int(r) for r in radicands})
    primes = sorted({int(q) for m in rads for q, _ in fmpz(m).factor()})
    bit = {q: 1 << k for k, q in enumerate(primes)}

    def vec(m):
        return sum(bit[int(q)] for q, e in fmpz(m).factor() if e % 2)

    rows: list = []                 # (vector, pivot, combination of basis indices)
    basis: list = []
    for m in rads:
        v, comb = vec(m), 0
        for w, piv, c in rows:
            if v & piv:
                v, comb = v ^ w, comb ^ c
        if v:
            j = len(basis)
            basis.append(m)
            rows.append((v, v & -v, comb ^ (1 << j)))
    coords: dict = {}
    for m in rads:
        v, comb = vec(m), 0
        for w, piv, c in rows:
            if v & piv:
                v, comb = v ^ w, comb ^ c
        coords[m] = comb
    return tuple(basis), coords


def _complete_coords(p, basis, coords: dict) -> None:
    """Add to ``coords`` every radicand of ``p`` it lacks (products of the basis that
    ``p``'s own coefficients did not show, met after a shift by ``theta``): the set of
    ``j`` with ``m * prod_j b_j`` a square."""
    for m in {m for c in p for m in c.radicands()} - coords.keys():
        for comb in range(1 << len(basis)):
            prod = fmpz(m)
            for j, b in enumerate(basis):
                if comb >> j & 1:
                    prod *= b
            if prod.is_square():
                coords[m] = comb
                break
        else:
            raise ArithmeticError(f"sqrt({m}) is not in the field of the basis")


def _conjugate(x: MQ, j: int, coords: dict) -> MQ:
    return MQ({m: (-c if m != 1 and coords[m] >> j & 1 else c) for m, c in x.terms.items()})


def _rational_poly(p) -> fmpq_poly:
    return fmpq_poly([c.to_fmpq() for c in p])


def _from_rational(h: fmpq_poly) -> tuple:
    return tuple(MQ.rational(c) for c in h.coeffs())


# -- factoring over K = Q(sqrt primes) ---------------------------------------------------------
@lru_cache(maxsize=512)
def factor_over_k(p: tuple, radicands: tuple = ()):
    """The monic irreducible factors of the square-free ``p`` (MQ coefficients, degree >= 1)
    over ``K``, the multiquadratic field of its coefficients' primes and of the square
    roots of the extra squarefree integers ``radicands`` (Trager's algorithm);
    None when the norm's degree exceeds :data:`MAX_NORM_DEGREE`, or when ``p`` is
    reducible over ``K`` and a gcd over ``K`` grows beyond :data:`GCD_BITS` (Euclid's
    coefficients swell over a number field)."""
    p = monic(trim(p))
    basis, coords = group_basis(p, radicands)
    if len(p) - 1 << len(basis) > MAX_NORM_DEGREE:
        return None
    if not basis:
        return tuple(monic(_from_rational(h)) for h, _ in _rational_poly(p).factor()[1])
    theta = MQ({b: fmpq(1) for b in basis})            # a primitive element of K
    for s in range(0, 12):
        ps = shift(p, -theta * s) if s else p          # ps(x) = p(x - s theta)
        coords_s = dict(coords)
        coords_s.update({b: 1 << j for j, b in enumerate(basis)})
        norm = ps
        for j in range(len(basis)):         # the product over the group, one flip at a time
            _complete_coords(norm, basis, coords_s)
            norm = pmul(norm, tuple(_conjugate(c, j, coords_s) for c in norm))
        n = _rational_poly(norm)
        if n.gcd(n.derivative()).degree() > 0:
            continue                         # not square-free: another shift
        factors = n.factor()[1]
        if len(factors) == 1:                # N(p) irreducible: so is p over K (no gcd)
            return (p,)
        out = []
        for h, _ in factors:
            g = bounded_gcd(ps, _from_rational(h), GCD_BITS)
            if g is None:
                return None
            if len(g) > 1:
                out.append(monic(shift(g, theta * s)) if s else g)
        return tuple(out)
    return None


def changes_sign(f, lo, hi) -> bool:
    return peval(f, MQ.rational(lo)).sign() * peval(f, MQ.rational(hi)).sign() < 0


def stable(f) -> bool:
    """Is the irreducible ``f`` over K irreducible over every multiquadratic extension
    of K (module docstring)?"""
    d = len(f) - 1
    if d % 2:
        return True
    if d == 4:
        e, dd, c, b = f[3], f[2], f[1], f[0]          # x^4 + e x^3 + dd x^2 + c x + b
        resolvent = (-(e * e * b - dd * b * 4 + c * c), e * c - b * 4, -dd, ONE)
        factors = factor_over_k(trim(resolvent))
        return factors is not None and len(factors) == 1 and len(factors[0]) == 4
    return False
