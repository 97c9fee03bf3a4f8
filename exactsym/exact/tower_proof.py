"""Proofs that the radicands of a tower (:mod:`.tower`) are non-squares, for certificates.

A level's radicand r_i is proved a non-square of K_(i-1) by a ring homomorphism
phi: R -> F_p (R: the elements whose coefficients have no p in their denominators) under
which r_i is a quadratic non-residue; docs/certificates.md ("Towers") gives the argument and
its conditions (p odd, p divides no base radicand, r_j p-integral and N(r_j) a p-unit for
j < i), which the checker (exactsym.checker.tower) re-checks.

Over a cyclotomic base (:mod:`.cyclotomic_tower`) the map sends zeta to a root w of Phi_M
modulo a prime p = 1 mod M (:func:`cyclotomic_nonsquare_witness`); the checker re-checks it in
``exactsym.checker.tower``.

Levels that are all square roots of rationals over a cyclotomic base (:mod:`.kummer`) are
proved together by :func:`kummer_witness`: Legendre symbols of full rank over F_2; levels
whose radicands all lie in K_0 = Q(sqrt q, ...) likewise by :func:`base_kummer_witness`.

Public names: :func:`nonsquare_witness`, :func:`cyclotomic_nonsquare_witness`,
:func:`kummer_witness`, :func:`base_kummer_witness`, :func:`norm`, :func:`image`.
"""

from __future__ import annotations

from itertools import chain, islice
from math import gcd, lcm

from flint import fmpq

from .context import Cache
from .cyclotomic_sqrt import image_mod, root_of_unity_mod, split_primes
from .factor import factorization, is_prime
from .modular import (character_rows, image, independent_rows, kummer_split_primes, sparse_image,
                      sqrt_mod)
from .multiquadratic import MQ
from .tower import Tower, level, split, sub


def norm(tower: Tower, x) -> fmpq:
    """N_(K_L/Q)(x) for a raw value of level L (down the tower, then over the base primes)."""
    for lev in range(level(x), 0, -1):
        a, b = split(x, lev)
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


#: id(tower) -> (tower, number of radicands, maps or None): a table of the analysis
#: (:mod:`.context`), so an id names its tower only while the analysis keeps both
_MAPS = Cache("tower maps mod p")


def tower_maps(tower: Tower, tries: int = 128, budget: int = 256):
    """``(p, (base, roots), (base2, roots2))``: two ring maps of the tower's numbers into
    F_p (a sign for each base prime's root, then for each level a root of its radicand's
    image, depth first: at most ``budget`` steps a prime), or None when no prime among
    ``tries`` of :func:`kummer_split_primes` gives two (a radicand's image a non-residue or 0,
    a denominator divisible by p).  A rational number has one image under every map, so
    two maps that disagree on a number prove it irrational (:func:`tower_images`).
    Remembered per tower and number of levels."""
    table = _MAPS.table()
    hit = table.get(id(tower))
    if hit is not None and hit[0] is tower and hit[1] == len(tower.radicands):
        return hit[2]
    if getattr(tower, "classes", None) is not None:
        found = _kummer_maps(tower)
        table[id(tower)] = (tower, len(tower.radicands), found)
        return found
    found = None
    primes = kummer_split_primes(tower.primes)
    k, levels = len(tower.primes), len(tower.radicands)
    for _ in range(tries):
        p = next(primes)
        base_roots = [sqrt_mod(q, p) for q in tower.primes]
        maps: list = []
        stack = [([], [])]
        steps = 0
        try:
            while stack and len(maps) < 2 and steps < budget:
                steps += 1
                signs, roots = stack.pop()
                if len(signs) < k:
                    s = base_roots[len(signs)]
                    stack += [(signs + [s], roots), (signs + [p - s], roots)]
                    continue
                base = dict(zip(tower.primes, signs))
                if len(roots) == levels:
                    maps.append((base, roots))
                    continue
                t = sqrt_mod(image(tower.radicands[len(roots)], p, base, roots), p)
                if t:
                    stack += [(signs, roots + [t]), (signs, roots + [p - t])]
        except (ValueError, AttributeError, TypeError):   # p | a denominator; not an MQ base
            continue
        if len(maps) == 2:
            found = (p, maps[0], maps[1])
            break
    if len(table) > 64:
        table.clear()
    table[id(tower)] = (tower, len(tower.radicands), found)
    return found


def tower_images(tower: Tower, raws) -> tuple | None:
    """``(p, [images under the first map], [under the second])`` of raw values of
    ``tower`` (:func:`tower_maps`), or None."""
    maps = tower_maps(tower)
    if maps is None:
        return None
    p, first, second = maps
    out = ([], [])
    if getattr(tower, "classes", None) is not None:
        for v in raws:
            a, b = _kummer_image(v, p, *first), _kummer_image(v, p, *second)
            if a is None or b is None:
                return None
            out[0].append(a)
            out[1].append(b)
        return p, out
    try:
        for v in raws:
            out[0].append(image(v, p, *first))
            out[1].append(image(v, p, *second))
    except (ValueError, AttributeError, TypeError):   # a pole at p; not an MQ base
        return None
    return p, out


def _odd_primes(limit: int):
    sieve = bytearray([1]) * limit
    for p in range(2, limit):
        if sieve[p]:
            if p > 2:
                yield p
            sieve[p * p::p] = bytearray(len(range(p * p, limit, p)))


def base_kummer_witness(primes, radicands, limit: int = 1 << 24, signs: int = 16):
    """``[(p, base), ...]``: ring maps K_0 -> F_p, K_0 = Q(sqrt q : q in ``primes``) (p an
    odd prime, ``base`` a root mod p of each q, none 0; no denominator of a radicand's
    coefficient divisible by p and no radicand's image 0) whose Legendre characters on the
    ``radicands`` (``MQ``, all in K_0) have rank L = len(radicands) over F_2.  Then no
    product of a non-empty subset of them is a square of K_0 (:func:`character_rows`), so
    by Kummer theory each level of K_0(sqrt r_1, ..., sqrt r_L) is new: the certificate of
    a tower whose radicands all lie in K_0 ("kummer" levels, checker_tower), where a proof
    per level needs a prime at which every lower radicand is a residue (ten nested radicals
    over ten primes: none below 200,000).  None when the primes below ``limit`` do not
    reach rank L."""
    def candidates():           # small primes at which every base prime is a square
        for p in range(3, limit, 2):
            if all(pow(q, (p - 1) // 2, p) == 1 for q in primes) and is_prime(p):
                yield p
    kept = independent_rows(character_rows(primes, radicands, limit, signs, candidates()),
                             len(radicands))
    return [(p, base) for p, base, _ in kept] if len(kept) == len(radicands) else None


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
        base_roots = [sqrt_mod(q, p) for q in tower.primes]
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
        t = sqrt_mod(value, p)
        if t is not None:
            stack += [(signs, roots + [t]), (signs, roots + [p - t])]
    return None


# ------------------------------------------------------------------ over a cyclotomic base
def _cyclotomic_image(x, p: int, w: int, roots: list):
    """phi(x) in F_p: zeta -> w, y_j -> roots[j - 1]; None if p divides a denominator."""
    if type(x) is not tuple:
        return image_mod(x.poly, w, p)
    lev, a, b = x
    va, vb = _cyclotomic_image(a, p, w, roots), _cyclotomic_image(b, p, w, roots)
    return None if va is None or vb is None else (va + vb * roots[lev - 1]) % p


def _tower_norm_to_base(tower, x):
    """N_(K_L/K_0)(x), a base value (conjugates a^2 - r b^2 down the tower)."""
    for lev in range(level(x), 0, -1):
        a, b = split(x, lev)
        x = sub(tower.mul(a, a), tower.mul(tower.radicands[lev - 1], tower.mul(b, b)))
    return x


def cyclotomic_nonsquare_witness(tower, lev: int, limit: int = 200_000):
    """``(p, thetas, roots)`` proving the radicand of level ``lev`` of a
    :class:`~.cyclotomic_tower.CyclotomicTower` a non-square of K_(lev-1): p = 1 mod M, thetas
    the phi(M)/2 roots w^k + w^-k of Psi_M modulo p (distinct: Psi_M splits, so the base ring
    is integrally closed at p), the map theta -> thetas[0] (zeta -> w^k) and a root of the
    image of each lower radicand, under which r_lev is a non-residue and every lower radicand
    is p-integral with a norm prime to p (docs/certificates.md, "Towers over Q(zeta_M)").
    None if no prime below ``limit`` is found."""
    m = tower.conductor
    radicands = tower.radicands[:lev]
    base_norms = [_tower_norm_to_base(tower, r) for r in radicands[:-1]]
    half = _half_units(m)
    for p in split_primes(m, start=3):
        if p >= limit:
            return None
        w = root_of_unity_mod(m, p)
        ok = True
        for n in base_norms:            # N_(K_0/Q)(n) mod p: the product over the e embeddings
            total = 1
            for k in half:
                v = image_mod(n.poly, pow(w, k, p), p)
                total = 0 if v is None else total * v % p
            if total == 0:
                ok = False
                break
        if not ok or any(image_mod(c.poly, w, p) is None
                         for r in radicands for c in _base_parts(r)):
            continue
        for k in half[:8]:
            wk = pow(w, k, p)
            roots = _cyclotomic_search(p, wk, radicands)
            if roots is not None:
                thetas = [(pow(w, j, p) + pow(w, -j, p)) % p for j in half]
                chosen = (wk + pow(wk, -1, p)) % p
                thetas.remove(chosen)
                return p, [chosen] + thetas, roots
    return None


def _half_units(m: int) -> list:
    """The units k of Z/m up to sign (1 <= k <= m/2): w^k + w^-k runs over the roots of
    Psi_m modulo a prime p = 1 mod m (w a primitive m-th root of unity there)."""
    return [k for k in range(1, m // 2 + 1) if gcd(k, m) == 1] if m > 2 else [1]


def _base_parts(x):
    if type(x) is not tuple:
        yield x
    else:
        yield from _base_parts(x[1])
        yield from _base_parts(x[2])


def _cyclotomic_search(p: int, w: int, radicands: list, budget: int = 64):
    """Roots of the images of the lower radicands, depth first, until the image of the last
    one is a non-residue (``budget`` leaves at most); None if none found."""
    stack, leaves = [[]], 0
    while stack and leaves < budget:
        roots = stack.pop()
        j = len(roots)
        value = _cyclotomic_image(radicands[j], p, w, roots)
        if value is None:
            return None
        if j == len(radicands) - 1:
            leaves += 1
            if pow(value, (p - 1) // 2, p) == p - 1:
                return roots
            continue
        t = sqrt_mod(value, p)
        if t is not None:
            stack += [roots + [t], roots + [(p - t) % p]]
    return None


# ------------------------------------------------- square roots of rationals (Kummer levels)
def kummer_witness(tower, limit: int = 1 << 40):
    """``[(p, thetas), ...]`` proving the rational radicands r_1, ..., r_L of a
    :class:`~.cyclotomic_tower.CyclotomicTower` whose levels are all square roots of
    rationals independent modulo squares of K_0: primes p = 1 mod M (Psi_M splits: thetas
    its roots modulo p, as in :func:`cyclotomic_nonsquare_witness`), none dividing a
    radicand, whose vectors of Legendre symbols ((r_1|p), ..., (r_L|p)) have rank L over F_2
    (docs/certificates.md, "Square roots of rationals over Q(zeta_M)").  One prime per
    level, never a chain of roots: L levels would need a prime where L - 1 radicands are
    residues.  None if the primes up to ``limit`` do not reach rank L."""
    m = tower.conductor
    primes = legendre_rank_primes(m, tower.radicands, limit)
    if primes is None:
        return None
    half = _half_units(m)
    out = []
    for p in primes:
        w = root_of_unity_mod(m, p)
        out.append((p, [(pow(w, j, p) + pow(w, -j, p)) % p for j in half]))
    return out


def legendre_rank_primes(m: int, radicands, limit: int):
    """Primes p = 1 mod m below ``limit``, none dividing a numerator or denominator of the
    rational ``radicands``, each adding rank to the vectors of Legendre symbols
    ((r_1|p), ..., (r_L|p)) over F_2 until it is L; None if the primes below ``limit`` do not
    reach it.  Alone (no roots of Psi_m) they prove the radicands independent modulo squares
    of Q(zeta_m) (docs/certificates.md, "Square roots of rationals over the sparse
    Q(zeta_N)")."""
    values = [int(r.to_fmpq().p) * int(r.to_fmpq().q) for r in radicands]
    rows: dict = {}
    out: list = []
    if not values:
        return out
    for p in split_primes(m, start=3):
        if p >= limit:
            return None
        if any(v % p == 0 for v in values):
            continue
        vector = 0
        for i, v in enumerate(values):
            if pow(v, (p - 1) // 2, p) == p - 1:
                vector |= 1 << i
        while vector and vector.bit_length() - 1 in rows:
            vector ^= rows[vector.bit_length() - 1]
        if not vector:
            continue                                   # no new rank from this prime
        rows[vector.bit_length() - 1] = vector
        out.append(p)
        if len(rows) == len(values):
            return out
    return None


# ------------------------------------- ring maps of a tower of Kummer levels into F_p (keys)
def _kummer_maps(tower):
    """``(p, (w, roots), (w', roots'))`` for a tower over Q(zeta_N) (dense or sparse) whose
    levels are all square roots of rationals: p = 1 mod lcm(N, 8, the radicands' odd
    primes), so zeta_N has images (w and w' = w^j, j != +-1 mod N: two embeddings) and
    every radicand is a residue ((l | p) = (p | l) = 1 by reciprocity, p = 1 mod 4, and
    (2 | p) = 1 as p = 1 mod 8): y_i -> roots[i] and its negative.  None when N has no
    second embedding (N <= 6)."""
    n = tower.conductor
    j = next((j for j in range(2, n - 1) if gcd(j, n) == 1), None)
    if j is None:
        return None
    nested = getattr(tower, "nested", 0)
    rational = tower.radicands[:len(tower.radicands) - nested]
    values = [int(r.to_fmpq().p) * int(r.to_fmpq().q) for r in rational]
    modulus = lcm(n, 8)
    for v in values:
        for q in factorization(v) if v > 1 else ():
            modulus = lcm(modulus, q)
    k = (1 << 62) // modulus + 1
    while not is_prime(k * modulus + 1):
        k += 1
    p = k * modulus + 1
    w = root_of_unity_mod(n, p)
    roots = [sqrt_mod(v % p, p) for v in values]
    if any(t is None for t in roots):          # cannot happen (reciprocity)
        return None
    if not nested:
        return p, (w, roots), (pow(w, j, p), [(p - t) % p for t in roots])
    # levels whose radicands are not rational (MakeAsym's radial moves over the sparse
    # base, .sparse_tower): embeddings w^u through which each such image is a residue.
    # The images are remembered by (number, p, w): so the roots of the rational levels
    # under w^u are those the maps above give (negated for u = j), for every tower
    found: list = []
    others = (u for u in range(2, n // 2 + 1) if gcd(u, n) == 1 and u != j)
    for u in chain((1, j), islice(others, 256)):
        wu = pow(w, u, p)
        extended = [(p - t) % p for t in roots] if u == j else list(roots)
        for r in tower.radicands[len(rational):]:
            t = _kummer_image_of(r, p, wu, extended)
            t = sqrt_mod(t, p) if t else None
            if not t:
                break
            extended.append(t)
        else:
            found.append((wu, extended))
            if len(found) == 2:
                return (p,) + tuple(found)
    return None


#: (id(x), p, w) -> (x, image): coordinates enter many keys; a table of the analysis
#: (:mod:`.context`), so an id names its object only while the analysis keeps both
_KUMMER_IMAGES = Cache("Kummer images mod p")


def _kummer_image(x, p: int, w: int, roots: list):
    """The image of a raw value: zeta_N -> w, y_i -> roots[i - 1]; None at a pole.
    Remembered by identity (the entry keeps x alive, so its id is not reused): a sparse
    base number of hundreds of terms costs as many modular powers."""
    table = _KUMMER_IMAGES.table()
    key = (id(x), p, w)
    hit = table.get(key)
    if hit is not None and hit[0] is x:
        return hit[1]
    value = _kummer_image_of(x, p, w, roots)
    if len(table) >= 1 << 14:
        table.clear()
    table[key] = (x, value)
    return value


def _kummer_image_of(x, p: int, w: int, roots: list):
    if type(x) is tuple:
        a, b = _kummer_image(x[1], p, w, roots), _kummer_image(x[2], p, w, roots)
        return None if a is None or b is None else (a + b * roots[x[0] - 1]) % p
    if isinstance(x, MQ):
        q = x.to_fmpq()
        return None if int(q.q) % p == 0 else int(q.p) * pow(int(q.q), -1, p) % p
    poly = getattr(x, "poly", None)
    if poly is not None:                     # dense: a polynomial in zeta_N
        if p < 1 << 63:
            return image_mod(poly, w, p)
        den = int(poly.denom())
        if den % p == 0:
            return None
        value = 0
        for c in reversed(poly.numer().coeffs()):
            value = (value * w + int(c)) % p
        return value * pow(den, -1, p) % p
    return sparse_image(x, p, w)
