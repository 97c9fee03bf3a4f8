"""Elliptic-curve primality certificates (Atkin-Morain) for primes whose p - 1 resists.

Why: a turn 1/p with p a 100-digit prime puts p in the conductor N of the sparse Q(zeta_N),
and the certificate must prove p prime.  :mod:`.prime_certificates` proves it from a factored
part of p - 1, which for p = 10^99 + 289 is 37 of 329 bits: certify refused what check
answered.  Here p is proved by a curve E: y^2 = x^3 + a x + b and a point P of prime order
q > (p^(1/4) + 1)^2 (the checker, ``ext_primes._elliptic``, verifies (q - 1) P = -P), and
q in turn, down to the checker's deterministic Miller-Rabin range.

Finding the curve (complex multiplication): for a discriminant D < 0 with 4 p = u^2 + |D| v^2
(Cornacchia), a curve with CM by D has p + 1 - t points, t among +-u (and more for D = -3,
-4).  When such an order is m = s q with s smooth and q a probable prime above the bound,
the curve is built from a root mod p of the Hilbert class polynomial H_D (its roots the
j-invariants j((-b + sqrt(D)) / 2a) of the reduced forms, computed with Arb balls at rising
precision and rounded: a wrong polynomial only makes the search fail, never a false proof),
a twist and a point P0 found at random, and P = s P0.  Discriminants down to -3000 of class
number at most 16.  Random primes (12 per size): 60 digits 0.1-0.2 s, 100 digits 0.3-0.8 s
(4 to 12 steps), 150 digits 1.4-2.5 s, 200 digits 4-7 s; above :data:`DIGIT_LIMIT` digits
the search is refused before it starts.

Public names: :func:`elliptic_proofs`, :class:`EllipticError`.
"""

from __future__ import annotations

import random
from functools import lru_cache
from math import gcd, isqrt

from flint import acb, arb, ctx, fmpz, fmpz_mod_poly_ctx

from ..exact.tower_proof import sqrt_mod

#: the checker decides primality below this by Miller-Rabin (``ext_primes.MR_LIMIT``)
MR_LIMIT = 3317044064679887385961981
_DISCRIMINANT_LIMIT = 3000
_CLASS_NUMBER_LIMIT = 16
_TRIES = 40             # (twist, point) pairs per candidate order
#: primes of more digits are refused before any search (200 digits: about 5 s, 300: 30 s)
DIGIT_LIMIT = 200


class EllipticError(Exception):
    """No elliptic certificate found within the effort bound."""


def elliptic_proofs(p: int) -> list[dict]:
    """Certificate entries ``{"prime", "curve": [a, b], "point": [x, y], "order": q}`` proving
    p prime, then q, ... down to the Miller-Rabin range (increasing primes).  Raises
    :class:`EllipticError` when a step finds no curve."""
    if len(str(p)) > DIGIT_LIMIT:
        raise EllipticError(f"elliptic primality proofs stop at {DIGIT_LIMIT} digits")
    if not fmpz(p).is_probable_prime():
        raise EllipticError(f"{p} is not prime")
    out = []
    while p >= MR_LIMIT:
        entry = _step(p)
        out.append(entry)
        p = int(entry["order"])
    return out[::-1]


def _step(n: int) -> dict:
    bound = (isqrt(isqrt(n)) + 2) ** 2
    rng = random.Random(n)
    for d in _discriminants():
        if gcd(d, n) != 1:
            continue
        rep = _cornacchia(d, n)
        if rep is None:
            continue
        for m in _orders(d, n, *rep):
            s = _smooth_part(m)
            q = m // s
            # s > 1 makes q < n, so the chain descends and ends (m itself prime could
            # exceed n and lead back to it)
            if s == 1 or q <= bound or not fmpz(q).is_probable_prime():
                continue
            found = _curve_and_point(d, n, s, q, rng)
            if found is not None:
                (a, b), (x, y) = found
                return {"prime": str(n), "curve": [str(a), str(b)], "point": [str(x), str(y)],
                        "order": str(q)}
    raise EllipticError(f"no elliptic curve found (discriminants down to "
                        f"-{_DISCRIMINANT_LIMIT}, class number at most {_CLASS_NUMBER_LIMIT})")


# ------------------------------------------------------------------ discriminants and orders
def _forms(d: int) -> list:
    """The reduced primitive forms (a, b, c) of discriminant d = b^2 - 4 a c < 0."""
    out = []
    a = 1
    while 3 * a * a <= -d:
        for b in range(-a + 1, a + 1):
            if (b * b - d) % (4 * a) == 0:
                c = (b * b - d) // (4 * a)
                if c >= a and gcd(gcd(a, abs(b)), c) == 1 and not (b < 0 and a == c):
                    out.append((a, b, c))
        a += 1
    return out


@lru_cache(maxsize=1)
def _discriminants() -> tuple:
    """Discriminants by increasing class number (then size): small H_D first."""
    found = []
    for k in range(3, _DISCRIMINANT_LIMIT):
        d = -k
        if d % 4 in (0, 1):
            h = len(_forms(d))
            if h <= _CLASS_NUMBER_LIMIT:
                found.append((h, k, d))
    return tuple(d for _, _, d in sorted(found))


def _cornacchia(d: int, n: int):
    """(u, v) with u^2 + |d| v^2 = 4 n, or None."""
    x = sqrt_mod(d, n)
    if x is None:
        return None
    if (x - d) % 2:
        x = n - x
    a, b, limit = 2 * n, x, isqrt(4 * n)
    while b > limit:
        a, b = b, a % b
    rest = 4 * n - b * b
    if rest % -d:
        return None
    v = isqrt(rest // -d)
    return (b, v) if v * v == rest // -d else None


def _orders(d: int, n: int, u: int, v: int) -> list:
    """The orders n + 1 - t of the curves with CM by d (their traces t)."""
    if d == -4:
        traces = (u, -u, 2 * v, -2 * v)
    elif d == -3:
        traces = (u, -u, (u + 3 * v) // 2, -(u + 3 * v) // 2, (u - 3 * v) // 2,
                  -(u - 3 * v) // 2)
    else:
        traces = (u, -u)
    return [n + 1 - t for t in traces]


def _smooth_part(m: int) -> int:
    """The part of m made of primes below 2^64 found by trial division and ECM (the
    cofactor left, prime or not, is the candidate order q)."""
    s = 1
    for f, e in fmpz(m).factor_smooth(32):
        if f.is_prime() and int(f).bit_length() <= 64:
            s *= int(f) ** int(e)
    return s


# ------------------------------------------------------------------ the curve and the point
def _hilbert(d: int) -> list[int]:
    """The coefficients of H_d (constant first), from Arb balls of j at the reduced forms."""
    forms, prec = _forms(d), 64
    while prec <= 1 << 16:
        with ctx.workprec(prec):
            root = acb(0, arb(-d).sqrt())
            poly = [acb(1)]
            for a, b, _ in forms:
                j = ((acb(-b) + root) / (2 * a)).modular_j()
                new = [acb(0)] * (len(poly) + 1)
                for i, c in enumerate(poly):
                    new[i + 1] += c
                    new[i] -= c * j
                poly = new
            coefficients = [c.real.unique_fmpz() for c in poly]
        if all(c is not None for c in coefficients):
            return [int(c) for c in coefficients]
        prec *= 4
    raise EllipticError(f"H_{d} not found")


def _curve_and_point(d: int, n: int, s: int, q: int, rng):
    """((a, b), (x, y)): a curve with CM by d and a point of order q, or None."""
    if d == -3:
        invariants = [0]
    elif d == -4:
        invariants = [1728]
    else:
        field = fmpz_mod_poly_ctx(fmpz(n))
        invariants = [int(r) for r, _ in field(_hilbert(d)).roots()]
    for j in invariants:
        for _ in range(_TRIES):
            c = rng.randrange(1, n)
            if j == 0:
                a, b = 0, c
            elif j == 1728:
                a, b = c, 0
            else:
                k = j * pow(1728 - j, -1, n) % n
                a, b = 3 * k * c * c % n, 2 * k * c * c * c % n
            point = _random_point(a, b, n, rng)
            if point is None:
                continue
            top = _multiply(point, s, a, n)
            if top is None:
                continue
            check = _multiply(top, q - 1, a, n)
            if check == (top[0], (-top[1]) % n):
                return (a, b), top
    return None


def _random_point(a: int, b: int, n: int, rng):
    for _ in range(64):
        x = rng.randrange(n)
        y = sqrt_mod(x ** 3 + a * x + b, n)
        if y:
            return x, y
    return None


def _multiply(point, k: int, a: int, n: int):
    """k P (affine, modulo the probable prime n), or None at the point at infinity."""
    result, addend = None, point
    while k:
        if k & 1:
            result = _add(result, addend, a, n)
        addend = _add(addend, addend, a, n)
        k >>= 1
    return result


def _add(u, v, a: int, n: int):
    if u is None:
        return v
    if v is None:
        return u
    (x1, y1), (x2, y2) = u, v
    if x1 == x2:
        if (y1 + y2) % n == 0:
            return None
        slope = (3 * x1 * x1 + a) * pow(2 * y1, -1, n) % n
    else:
        slope = (y2 - y1) * pow(x2 - x1, -1, n) % n
    x3 = (slope * slope - x1 - x2) % n
    return x3, (slope * (x1 - x3) - y1) % n


__all__ = ["EllipticError", "elliptic_proofs"]
