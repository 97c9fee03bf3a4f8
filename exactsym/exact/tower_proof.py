"""Proofs that the radicands of a tower (:mod:`.tower`) are non-squares, for certificates.

A level's radicand r_i is proved a non-square of K_(i-1) by a ring homomorphism
phi: R -> F_p (R: the elements whose coefficients have no p in their denominators) under
which r_i is a quadratic non-residue; docs/certificates.md ("Towers") gives the argument and
its conditions (p odd, p divides no base radicand, r_j p-integral and N(r_j) a p-unit for
j < i), which the checker (exactsym.checker_tower) re-checks.

Public names: :func:`nonsquare_witness`, :func:`norm`, :func:`image`.
"""

from __future__ import annotations

from flint import fmpq

from .multiquadratic import MQ
from .tower import Tower, _split, level, sub


def norm(tower: Tower, x) -> fmpq:
    """N_(K_L/Q)(x) for a raw value of level L (down the tower, then over the base primes)."""
    for lev in range(level(x), 0, -1):
        a, b = _split(x, lev)
        x = sub(tower.mul(a, a), tower.mul(tower.radicands[lev - 1], tower.mul(b, b)))
    for p in tower.primes:
        x = x * MQ({m: (-c if m % p == 0 else c) for m, c in x.terms.items()})
    return x.to_fmpq()


def _coefficients(x):
    if isinstance(x, MQ):
        yield from x.terms.values()
    else:
        yield from _coefficients(x[1])
        yield from _coefficients(x[2])


def image(x, p: int, base: dict, roots: list) -> int:
    """phi(x) in F_p: sqrt(q) -> base[q] for the base primes, y_j -> roots[j - 1]."""
    if isinstance(x, MQ):
        total = 0
        for m, c in x.terms.items():
            v = int(c.p) * pow(int(c.q), -1, p)
            for q, s in base.items():
                if m % q == 0:
                    v *= s
            total += v
        return total % p
    lev, a, b = x
    return (image(a, p, base, roots) + image(b, p, base, roots) * roots[lev - 1]) % p


def _sqrt_mod(a: int, p: int):
    """A square root of a modulo the odd prime p, or None (Tonelli-Shanks)."""
    a %= p
    if a == 0:
        return 0
    if pow(a, (p - 1) // 2, p) != 1:
        return None
    q, s = p - 1, 0
    while q % 2 == 0:
        q, s = q // 2, s + 1
    z = next(z for z in range(2, p) if pow(z, (p - 1) // 2, p) == p - 1)
    m, c, t, r = s, pow(z, q, p), pow(a, q, p), pow(a, (q + 1) // 2, p)
    while t != 1:
        i, t2 = 0, t
        while t2 != 1:
            t2, i = t2 * t2 % p, i + 1
        b = pow(c, 1 << (m - i - 1), p)
        m, c, t, r = i, b * b % p, t * b * b % p, r * b % p
    return r


def _odd_primes(limit: int):
    sieve = bytearray([1]) * limit
    for p in range(2, limit):
        if sieve[p]:
            if p > 2:
                yield p
            sieve[p * p::p] = bytearray(len(range(p * p, limit, p)))


def nonsquare_witness(tower: Tower, lev: int, limit: int = 200_000):
    """``(p, base, roots)``: a homomorphism K_(lev-1) -> F_p (base: a root mod p of each base
    prime; roots: of each r_j, j < lev) under which r_lev is a non-residue; None if no prime
    below ``limit`` gives one (then the tower cannot be certified)."""
    radicands = tower.radicands[:lev]
    dens = 1
    for r in radicands:
        for c in _coefficients(r):
            dens *= int(c.q)
    norms = [norm(tower, r) for r in radicands[:-1]]
    bad = dens
    for n in norms:
        bad *= int(n.p) * int(n.q)
    for q in tower.primes:
        bad *= q
    for p in _odd_primes(limit):
        if bad % p == 0:
            continue
        base_roots = [_sqrt_mod(q, p) for q in tower.primes]
        if any(s is None for s in base_roots):
            continue
        found = _search(tower, p, radicands, base_roots)
        if found is not None:
            return p, found[0], found[1]
    return None


def _search(tower: Tower, p: int, radicands: list, base_roots: list, budget: int = 256):
    """Sign choices of the base roots and a root of each phi(r_j), depth first, until
    phi(r_lev) is a non-residue (``budget`` leaves at most)."""
    k = len(tower.primes)
    stack = [([], [])]
    leaves = 0
    while stack and leaves < budget:
        signs, roots = stack.pop()
        if len(signs) < k:
            s = base_roots[len(signs)]
            stack += [(signs + [s], roots), (signs + [p - s], roots)] if s else \
                [(signs + [s], roots)]
            continue
        base = dict(zip(tower.primes, signs))
        j = len(roots)
        value = image(radicands[j], p, base, roots)
        if j == len(radicands) - 1:
            leaves += 1
            if pow(value, (p - 1) // 2, p) == p - 1:
                return signs, roots
            continue
        t = _sqrt_mod(value, p)
        if t is not None:
            stack += [(signs, roots + [t]), (signs, roots + [p - t])]
    return None
