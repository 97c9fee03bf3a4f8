"""Primality certificates of large primes for the sparse Q(zeta_N) certificate (issue: certify
succeeds wherever check does).

Why: the checker (``ext_primes.is_prime``) proves primes by deterministic Miller-Rabin only
below :data:`MR_LIMIT` (about 3.3 * 10^24); a turn 1/(10^25 + 13) makes N and the hashing
prime l larger.  For each prime p at or above that bound this module writes
``{"prime": p, "witness": a, "factors": [[q, e], ...]}``: a factored part F = prod q^e of
p - 1 and one a with a^(p-1) = 1 and a^((p-1)/q) != 1 mod p for every q.  The checker accepts
F > sqrt(p) (Pocklington; Pratt when F = p - 1) or F^3 >= p with the Brillhart-Lehmer-Selfridge
condition, and proves each q at or above the bound by its own entry (recursion here).
When p - 1 resists, p is proved by an elliptic curve (:mod:`.elliptic_primes`: ``{"prime":
p, "curve": [a, b], "point": [x, y], "order": q}``, a point of prime order q above
(p^(1/4) + 1)^2), and q in turn.

Effort is bounded, so that certify never hangs where check answered: p - 1 is split by
python-flint's ``factor_smooth`` (trial division and ECM for factors up to 2^32, 2^48, then 2^60),
and a composite cofactor of at most :data:`FULL_DIGITS` digits is factored completely
(quadratic sieve, about a second at 56 digits).  When the prime part found is below p^(1/3)
and no elliptic curve is found either (none is searched above 200 digits),
:class:`PrimalityError` names p.  The hashing prime l = kN + 1 needs no search: l - 1 = k N
with N's factorisation known.

Public names: :func:`primality_proofs`, :class:`PrimalityError`, :data:`MR_LIMIT`.
"""

from __future__ import annotations

from functools import lru_cache
from math import gcd, isqrt, prod

from flint import fmpz

# MR_LIMIT: the checker's deterministic Miller-Rabin test decides below it (defined once, in
# the module this one builds on)
from .elliptic_primes import MR_LIMIT, EllipticError, elliptic_proofs
from ..exact.factor import factorization

#: a composite cofactor of p - 1 left by the smooth passes is factored completely up to this
FULL_DIGITS = 56
_SMOOTH_BITS = (32, 48, 60)
_WITNESS_TRIES = 2000


class PrimalityError(Exception):
    """No primality certificate of this prime within the bounded effort."""


def primality_proofs(primes, known: dict | None = None) -> list[dict]:
    """The certificate entries (increasing primes, each once) proving every prime of ``primes``
    at or above :data:`MR_LIMIT`, with the entries their factors of p - 1 need.  ``known``
    maps a prime p to a complete factorisation ``{q: e}`` of p - 1 when the caller has it."""
    proofs: dict = {}
    for p in primes:
        _prove(int(p), known or {}, proofs)
    return [proofs[p] for p in sorted(proofs)]


def _prove(p: int, known: dict, proofs: dict) -> None:
    if p < MR_LIMIT or p in proofs:
        return
    factors = dict(known[p] if p in known else _factored_part(p))
    # keep the factors that are proved (recursively): a q whose q - 1 resists drops out of F
    usable = {}
    for q, e in sorted(factors.items()):
        try:
            _prove(q, known, proofs)
            usable[q] = e
        except PrimalityError:
            continue
    f = _part(usable)
    if f ** 3 < p:
        # p - 1 resists: an elliptic curve with a point of large prime order proves p
        try:
            for entry in elliptic_proofs(p):
                proofs.setdefault(int(entry["prime"]), entry)
            return
        except EllipticError as error:
            raise PrimalityError(
                f"no primality certificate of the prime {p}: the factored part of p - 1 "
                f"found within the effort bound ({f.bit_length()} of {p.bit_length()} "
                f"bits) is below p^(1/3), and {error}") from None
    if f <= isqrt(p):                           # Brillhart-Lehmer-Selfridge, as the checker
        c2, c1 = divmod((p - 1) // f, f)
        d = c1 * c1 - 4 * c2
        if d >= 0 and isqrt(d) ** 2 == d:
            raise PrimalityError(f"{p} is not prime (BLS: c1^2 - 4 c2 is a square)")
    proofs[p] = {"prime": str(p), "witness": str(_witness(p, list(usable))),
                 "factors": [[str(q), e] for q, e in sorted(usable.items())]}


@lru_cache(maxsize=256)
def _factored_part(p: int) -> dict:
    """Prime powers ``{q: e}`` dividing p - 1, found within the effort bound (cached: certify
    may build the sparse field twice, and a refusal costs the whole effort)."""
    n, found = p - 1, {}
    for bits in _SMOOTH_BITS:
        rest = n
        for q, e in fmpz(n).factor_smooth(bits):
            if q.is_prime():                    # the last entry may be a composite cofactor
                q, e = int(q), int(e)
                found[q] = found.get(q, 0) + e
                rest //= q ** e
        n = rest
        if n == 1 or len(str(n)) <= FULL_DIGITS or _part(found) ** 3 >= p:
            break
    if 1 < n and len(str(n)) <= FULL_DIGITS and _part(found) ** 3 < p:
        for q, e in factorization(n).items():
            found[q] = found.get(q, 0) + e
    return found


def _part(factors: dict) -> int:
    return prod(q ** e for q, e in factors.items())


def _witness(p: int, qs: list) -> int:
    """The least a with a^(p-1) = 1 and gcd(a^((p-1)/q) - 1, p) = 1 for every q (a primitive
    root qualifies, so for a prime p one is found quickly)."""
    for a in range(2, 2 + _WITNESS_TRIES):
        if pow(a, p - 1, p) == 1 and all(gcd(pow(a, (p - 1) // q, p) - 1, p) == 1 for q in qs):
            return a
    raise PrimalityError(f"no witness a < {2 + _WITNESS_TRIES} proves {p} prime")


def hashing_prime_factors(ell: int, n: int, n_factors: dict) -> dict:
    """The factorisation of l - 1 = k N from N's (k is small: l is the least prime 1 mod N
    above 2^61)."""
    out = dict(n_factors)
    for q, e in factorization((ell - 1) // n).items():
        out[q] = out.get(q, 0) + e
    return out


__all__ = ["MR_LIMIT", "FULL_DIGITS", "PrimalityError", "hashing_prime_factors",
           "primality_proofs"]
