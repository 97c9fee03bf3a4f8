"""The inverse of a number-field element by a multi-modular method.

``fmpq_poly.xgcd`` works over Q and its intermediate coefficients explode: inverting an
element of Q(zeta_2520) whose coefficients have 3,000 bits took minutes (issue 9: 94% of
the time on small algebraic inputs was in ``FieldElement.inverse``).  Here the inverse is
computed modulo 62-bit primes (``nmod_poly.xgcd``, in C), combined by the Chinese remainder
theorem, and recovered by rational reconstruction of a common denominator; the number of
primes doubles until the candidate ``u`` passes the exact test ``a * u == 1`` modulo the
minimal polynomial.  That test decides: reconstruction only proposes.
"""

from __future__ import annotations

from flint import fmpq_poly, fmpz, fmpz_poly, nmod_poly

_PRIMES: list[int] = []
_FIRST = (1 << 62) + 1


def _prime(i: int) -> int:
    while len(_PRIMES) <= i:
        p = _PRIMES[-1] + 2 if _PRIMES else _FIRST
        while not fmpz(p).is_prime():
            p += 2
        _PRIMES.append(p)
    return _PRIMES[i]


def _rational_reconstruction(a: int, m: int):
    """``(n, d)`` with ``n / d == a`` modulo m, |n|, d <= sqrt(m / 2), or None (Wang)."""
    bound = (m >> 1).bit_length() // 2
    r0, r1, s0, s1 = m, a % m, 0, 1
    while r1.bit_length() > bound:
        q = r0 // r1
        r0, r1 = r1, r0 - q * r1
        s0, s1 = s1, s0 - q * s1
    if s1 == 0 or abs(s1).bit_length() > bound:
        return None
    return (r1, s1) if s1 > 0 else (-r1, -s1)


def inverse_mod(poly: fmpq_poly, minpoly: fmpq_poly) -> fmpq_poly:
    """``u`` of degree < deg(minpoly) with ``poly * u == 1`` modulo the irreducible ``minpoly``."""
    a = fmpz_poly(poly.numer())          # poly = a / den
    den = fmpz(poly.denom())
    m = fmpz_poly(minpoly.numer())
    lead = int(m.coeffs()[-1])
    residues = fmpz_poly([0])           # CRT image so far, coefficients in [0, modulus)
    modulus = fmpz(1)
    count, target = 0, 4
    i = 0
    while True:
        p = _prime(i)
        i += 1
        if lead % p == 0:
            continue
        ap, mp = nmod_poly(a, p), nmod_poly(m, p)
        g, s, _ = ap.xgcd(mp)
        if g.degree() != 0:              # p divides the resultant: skip it
            continue
        s = s * pow(int(g.coeffs()[0]), -1, p)
        # CRT in flint (C): residues += modulus * ((s - residues) / modulus mod p)
        step = (s - nmod_poly(residues, p)) * pow(int(modulus % p), -1, p)
        residues = residues + fmpz_poly([int(c) for c in step.coeffs()]) * modulus
        modulus *= p
        count += 1
        if count < target:
            continue
        target *= 2
        values = [int(c) for c in residues.coeffs()]
        values += [0] * (m.degree() - len(values))
        candidate = _reconstruct(values, int(modulus))
        if candidate is not None:
            u = fmpq_poly(candidate[0]) / candidate[1] * den
            if (poly * u) % minpoly == 1:
                return u


def _reconstruct(residues: list[int], modulus: int):
    """``(integer coefficients, common denominator)`` from residues, or None when the
    modulus is still too small (the first coefficient that does not fit gives up cheaply)."""
    half = modulus >> 1
    limit = modulus.bit_length() // 2 - 1        # |numerator| and denominator below 2^limit
    d = 1
    out = []
    for r in residues:
        v = r * d % modulus
        if v > half:
            v -= modulus
        if v.bit_length() > limit:               # needs a larger denominator
            found = _rational_reconstruction(v % modulus, modulus)
            if found is None or (d * found[1]).bit_length() > limit:
                return None
            d *= found[1]
            out = [x * found[1] for x in out]
            v = found[0]
        out.append(v)
    return out, d
