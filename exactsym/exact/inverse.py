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

from .factor import is_prime

_PRIMES: list[int] = []
_FIRST = (1 << 62) + 1
#: the prime the Newton lift starts from: ``nmod_poly.xgcd`` at degree thousands is about
#: four times faster modulo a 31-bit prime than modulo a 62-bit one (0.03 s against 0.13 s
#: at degree 5,760), and the lift doubles the precision per step whatever the start
_SMALL_FIRST = (1 << 31) + 11


def nth_prime(i: int, first: int = _FIRST, found: list | None = None) -> int:
    """The i-th prime from ``first`` on (62-bit primes for multimodular arithmetic),
    remembered in ``found``."""
    found = _PRIMES if found is None else found
    while len(found) <= i:
        p = found[-1] + 2 if found else first
        while not is_prime(p):
            p += 2
        found.append(p)
    return found[i]


_SMALL_PRIMES: list[int] = []


def _small_prime(i: int) -> int:
    return nth_prime(i, _SMALL_FIRST, _SMALL_PRIMES)


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


def inverse_mod(poly: fmpq_poly, minpoly: fmpq_poly, remainder=None) -> fmpq_poly:
    """``u`` of degree < deg(minpoly) with ``poly * u == 1`` modulo the irreducible ``minpoly``.

    The inverse modulo one 31-bit prime p (``nmod_poly.xgcd``, the costly step at degree
    thousands) is lifted by Newton's iteration u <- u (2 - a u) modulo p^2, p^4, ...
    (products over Z reduced by ``remainder`` when given -- a cyclotomic field's, linear
    in the degree for Phi_p and Phi_2p radicals -- else :func:`remainder_function`,
    coefficients reduced modulo
    p^(2^k) in C), which doubles the precision per step with two products instead of one
    xgcd per further prime.  Rational reconstruction proposes, the exact test decides;
    the work is bounded by the size of the answer: the lift stops at the first modulus
    above twice the bits of its numerators and denominator (Wang's bound), after
    log2(that / 31) steps.  Answers are remembered (a few, by exact value): the paper
    layer, the audit and the truth divide by the same squared lengths."""
    a = fmpz_poly(poly.numer())          # poly = a / den
    den = fmpz(poly.denom())
    m = fmpz_poly(minpoly.numer())
    lead = int(m.coeffs()[-1])
    if lead != 1:
        return _inverse_multimodular(poly, minpoly)
    key = (tuple(int(c) for c in a.coeffs()), int(den), hash(tuple(int(c) for c in m.coeffs())))
    hit = _INVERSES.get(key)
    if hit is not None and hit[0] == m:
        return hit[1]
    u = _lifted_inverse(a, den, m, remainder)
    if len(_INVERSES) >= _INVERSES_LIMIT:
        _INVERSES.clear()
    _INVERSES[key] = (m, u)
    return u


_INVERSES: dict = {}
_INVERSES_LIMIT = 64


def _lifted_inverse(a: fmpz_poly, den: fmpz, m: fmpz_poly, remainder=None) -> fmpq_poly:
    """:func:`inverse_mod` of ``a / den`` modulo the monic integer ``m`` (no cache);
    ``remainder``: ``x -> x mod m`` for deg x <= 2 deg m - 2 when the caller has a faster
    one than Barrett's (a cyclotomic field's, .cyclotomic_reduce), else Barrett's."""
    i = 0
    while True:
        p = _small_prime(i)
        i += 1
        g, s, _ = nmod_poly(a, p).xgcd(nmod_poly(m, p))
        if g.degree() == 0:              # else p divides the resultant: skip it
            break
    s = s * pow(int(g.coeffs()[0]), -1, p)
    u = fmpz_poly([int(c) for c in s.coeffs()])
    rem = remainder or remainder_function(m)
    modulus = fmpz(p)
    while True:
        old, modulus = modulus, modulus * modulus
        # a u = 1 + old e (mod m, modulus); u' = u - old (u e mod old) has a u' = 1 - old^2
        # e^2 = 1 (mod modulus): the product u e has operands of old's size, not modulus's
        # (products and remainders over Z, m monic)
        e = (rem(a * u) % modulus - 1) // old
        u = (u - old * (rem(u * e) % old)) % modulus
        if modulus.bit_length() < 120:   # too few bits for any answer but the tiniest
            continue
        values = [int(c) for c in u.coeffs()]
        values += [0] * (m.degree() - len(values))
        candidate = _reconstruct(values, int(modulus))
        if candidate is not None:
            numer, d = candidate
            # poly * v = a * numer / (den * d) with v = numer * den / d: one iff
            # a * numer == d (mod m), over Z since m is monic
            if rem(a * fmpz_poly(numer)) == d:
                return fmpq_poly(numer) / d * den


_REMAINDERS: dict = {}


def remainder_function(m: fmpz_poly):
    """``x -> x mod m`` for a monic integer ``m`` of degree n and deg x <= 2n - 1, by
    Barrett's method: with mu = floor(X^(2n-1) / m) (an integer polynomial, m being monic;
    computed once per m from the power series 1 / rev(m) by Newton's iteration), the
    quotient is floor(x / m) = ((x >> (n-1)) * mu) >> n (polynomial floor is linear,
    and x mu / X^(2n-1) differs from x / m by a term of negative degree), and the
    remainder x - q m needs only the low n coefficients of q m: two fast products in C
    instead of a schoolbook division, and no coefficient list in Python."""
    key = tuple(int(c) for c in m.coeffs())
    found = _REMAINDERS.get(key)
    if found is not None:
        return found
    n = m.degree()
    shift = n - 1
    if n < 2:
        def remainder(x: fmpz_poly) -> fmpz_poly:
            return x % m
    else:
        rev_m = fmpz_poly(list(reversed(m.coeffs())))
        inv, k = fmpz_poly([1]), 1               # 1 / rev(m) mod X^k
        while k < n:
            k = min(2 * k, n)
            inv = inv.mul_low(2 - rev_m.mul_low(inv, k), k)
        low = inv.coeffs()
        mu = fmpz_poly(list(reversed(low + [0] * (n - len(low)))))   # degree n - 1

        def remainder(x: fmpz_poly) -> fmpz_poly:
            big = x.degree()
            if big < n:
                return x
            if big > 2 * n - 1:
                return x % m
            q = (x.right_shift(shift) * mu).right_shift(n)
            return x.truncate(n) - q.mul_low(m, n)

    if len(_REMAINDERS) > 8:
        _REMAINDERS.clear()
    _REMAINDERS[key] = remainder
    return remainder


def _inverse_multimodular(poly: fmpq_poly, minpoly: fmpq_poly) -> fmpq_poly:
    """:func:`inverse_mod` for a minimal polynomial with integer numerator not monic: the
    inverse modulo many primes (``nmod_poly.xgcd``), combined by the Chinese remainder
    theorem, proposed by rational reconstruction, confirmed exactly."""
    a = fmpz_poly(poly.numer())          # poly = a / den
    den = fmpz(poly.denom())
    m = fmpz_poly(minpoly.numer())
    lead = int(m.coeffs()[-1])
    residues = fmpz_poly([0])           # CRT image so far, coefficients in [0, modulus)
    modulus = fmpz(1)
    count, target = 0, 4
    i = 0
    while True:
        p = nth_prime(i)
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
