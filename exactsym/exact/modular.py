"""Exact numbers mapped into F_p, and the Legendre characters those maps give.

A ring map phi: R -> F_p (R: the numbers whose coefficients have no p in their
denominators) sends a square to a square, so a Legendre symbol of an image that is -1
proves a number no square; independent characters bound the rank of square classes
(Kummer theory).  The tower (:mod:`.tower`), its proofs (:mod:`.tower_proof`) and the
certificates use these; none of them needs the tower's own type, only raw values
(``MQ`` or ``(level, a, b)``) and sparse cyclotomic numbers (``num``/``den`` cosine sums).

Public names: :func:`image`, :func:`sparse_image`, :func:`sqrt_mod`,
:func:`kummer_split_primes`, :func:`character_rows`, :func:`independent_rows`,
:func:`square_class_rank`, :func:`kummer_subset`.
"""

from __future__ import annotations

from .factor import is_prime
from .multiquadratic import MQ


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


_NON_RESIDUES: dict = {}     # p -> the least quadratic non-residue mod p


def sqrt_mod(a: int, p: int):
    """A square root of a modulo the odd prime p, or None (Tonelli-Shanks; also None when
    the search shows p composite)."""
    a %= p
    if a == 0:
        return 0
    if pow(a, (p - 1) // 2, p) != 1:
        return None
    q, s = p - 1, 0
    while q % 2 == 0:
        q, s = q // 2, s + 1
    z = _NON_RESIDUES.get(p)
    if z is None:
        # the base primes and their products are residues mod a split prime: the search
        # passes them all, once per prime
        z = next(z for z in range(2, p) if pow(z, (p - 1) // 2, p) == p - 1)
        if len(_NON_RESIDUES) >= 1 << 12:
            _NON_RESIDUES.clear()
        _NON_RESIDUES[p] = z
    m, c, t, r = s, pow(z, q, p), pow(a, q, p), pow(a, (q + 1) // 2, p)
    while t != 1:
        i, t2 = 0, t
        while t2 != 1:
            t2, i = t2 * t2 % p, i + 1
            if i == m:
                return None             # p is not prime (a probable prime of ECPP)
        b = pow(c, 1 << (m - i - 1), p)
        m, c, t, r = i, b * b % p, t * b * b % p, r * b % p
    return r


def kummer_split_primes(primes):
    """Primes p = 1 + k M, M = 8 times the odd base primes: p = 1 mod 8 makes 2 a square
    mod p, and p = 1 mod q with p = 1 mod 4 makes q one (quadratic reciprocity)."""
    m = 8
    for q in primes:
        if q != 2:
            m *= q
    k = 0
    while True:
        k += 1
        if is_prime(k * m + 1):
            yield k * m + 1


def character_rows(primes, values, tries: int, signs: int, candidates=None):
    """Rows of characters of K_0*/K_0*^2 on the non-zero ``values`` (``MQ``), each with its
    map: ``(p, base, row)``, bit i of row set when value i is a non-residue.  Each ring map
    phi: K_0 -> F_p (p odd, every base prime a square mod p, no denominator divisible by
    p: ``base``, a root of each base prime, chooses the map) composed with the Legendre
    symbol is such a character where phi is a unit: the image of a square is a square (p
    is unramified, so a root of a p-unit is p-integral).  The primes are ``candidates``
    (by default :func:`kummer_split_primes`; ``tries`` of them, ``signs`` maps each)."""
    dens = 1
    for v in values:
        for c in v.terms.values():
            dens *= int(c.q)
    candidates = kummer_split_primes(primes) if candidates is None else candidates
    for _, p in zip(range(tries), candidates):
        if dens % p == 0:
            continue
        roots = [sqrt_mod(q, p) for q in primes]
        if any(r is None for r in roots):
            continue
        for choice in range(min(signs, 1 << len(primes))):
            base = [r if (choice >> k) & 1 == 0 else p - r for k, r in enumerate(roots)]
            images = [image(v, p, dict(zip(primes, base)), []) for v in values]
            if any(a == 0 for a in images):
                continue
            yield p, base, sum(1 << i for i, a in enumerate(images)
                               if pow(a, (p - 1) // 2, p) != 1)


def independent_rows(rows, need: int):
    """The rows (with their maps) that raise the rank over F_2, taken until it is
    ``need``: ``[(p, base, row), ...]`` (reduced rows)."""
    basis: list = []                        # row-reduced bit masks over F_2
    kept = []
    for p, base, row in rows:
        for b in basis:
            row = min(row, row ^ b)
        if row:
            basis.append(row)
            basis.sort(reverse=True)
            kept.append((p, base, row))
            if len(basis) == need:
                break
    return kept


def square_class_rank(primes, values, tries: int = 32, signs: int = 8) -> int:
    """A proved lower bound on the rank of the classes of the non-zero elements ``values``
    of K_0 = Q(sqrt q : q in ``primes``) (``MQ``) in K_0*/K_0*^2: at least that many of
    them are independent (no product of a non-empty subset of those is a square in K_0),
    so K_0(sqrt v : v in values) has degree at least 2^rank over K_0.  The rank over F_2
    of a matrix of characters (:func:`character_rows`) is a lower bound of the rank.
    Milliseconds: the tower refuses a level beyond its bound with it before any
    square-root test in a base of 2^k terms."""
    if not values:
        return 0
    return len(independent_rows(character_rows(primes, values, tries, signs), len(values)))


def kummer_subset(primes, radicands, x, tries: int = 32, signs: int = 8):
    """Which product of ``radicands`` r_1..r_L (``MQ``, non-zero) can make the non-zero x
    a square of K_0 (``MQ`` over the base ``primes``): by Kummer theory x is a square of
    K_0(sqrt r_1, ..., sqrt r_L) iff x * prod(r_j : j in S) is a square of K_0 for some S.

    Each character chi (:func:`character_rows`) must then satisfy
    chi(x) = sum(chi(r_j) : j in S) over F_2.  Returns False when that system has no
    solution (proved: x is no square up there), the tuple S (indices from 0, increasing)
    when the radicands' characters have full rank L (S is then the only candidate: the
    caller tests the one product), and None when the characters found within the bounds
    settle neither."""
    n = len(radicands)
    rows: dict = {}                      # pivot bit -> reduced row; bit 0: x, bit j: r_j
    for _, _, chars in character_rows(primes, [x] + list(radicands), tries, signs):
        row = chars
        for pivot in sorted(rows, reverse=True):
            if row >> pivot & 1:
                row ^= rows[pivot]
        if row == 1:                     # 0 = chi(x) + sum over S: no S satisfies it
            return False
        if row:
            rows[row.bit_length() - 1] = row
            if len(rows) == n:
                break
    else:
        return None
    chosen = 0                           # bit j: r_j in S
    for pivot in sorted(rows):           # back substitution, lowest pivot first
        row = rows[pivot]
        # s_pivot = chi(x) + the s_j of the lower bits of its row (all decided already)
        if (row & 1) ^ ((row & chosen).bit_count() & 1):
            chosen |= 1 << pivot
    return tuple(j - 1 for j in range(1, n + 1) if chosen >> j & 1)


def sparse_image(x, p: int, u: int) -> int | None:
    """The image of ``num / den`` (cosine form) under zeta_N -> u, a primitive N-th root of
    unity modulo p: cos(2 pi e/N) -> (u^e + u^-e)/2; None when p divides a coefficient's
    denominator or the denominator maps to 0."""
    u_inv = pow(u, -1, p)
    values = []
    for terms in (x.num, x.den):
        if terms is None:
            values.append(2)                # the halves of num and den cancel
            continue
        total = 0
        for e, c in terms.items():
            q = int(c.q)
            if q % p == 0:
                return None
            total += int(c.p) * pow(q, -1, p) * (pow(u, e, p) + pow(u_inv, e, p))
        values.append(total % p)
    if values[1] == 0:
        return None
    return values[0] * pow(values[1], -1, p) % p
