"""Polynomials with exact coefficients: tuples, lowest degree first.

The coefficients are numbers of one field (multiquadratic ``MQ`` numbers, or numbers of a
tower or of ``K(alpha)`` built on them): every operation here is exact field arithmetic,
and a polynomial is kept trimmed (no zero leading coefficient; ``()`` is zero).  The
critical instants of the gathering simulator are roots of such polynomials
(:mod:`.roots`); :mod:`.factor` factors them over their coefficients' field.
"""

from __future__ import annotations

from ..multiquadratic import MQ, sum_of_products

__all__ = ["ZERO", "ONE", "trim", "padd", "psub", "pmul", "pscale", "peval", "pderiv",
           "pdivmod", "pgcd", "monic", "coefficient_bits", "bounded_gcd", "shift"]

ZERO = MQ()
ONE = MQ.rational(1)


def trim(p) -> tuple:
    p = list(p)
    while p and p[-1].is_zero():
        p.pop()
    return tuple(p)


def padd(p, q) -> tuple:
    n = max(len(p), len(q))
    return trim((p[i] if i < len(p) else ZERO) + (q[i] if i < len(q) else ZERO)
                for i in range(n))


def psub(p, q) -> tuple:
    return padd(p, tuple(-c for c in q))


def pmul(p, q) -> tuple:
    if not p or not q:
        return ()
    if all(type(c) is MQ for c in p) and all(type(c) is MQ for c in q) and \
            max(len(c.terms) for c in p) * max(len(c.terms) for c in q) >= 16:
        # each coefficient a sum of products made canonical once (sum_of_products)
        return trim(sum_of_products((1, p[i], q[k - i])
                                    for i in range(max(0, k - len(q) + 1), min(k, len(p) - 1) + 1))
                    for k in range(len(p) + len(q) - 1))
    out = [ZERO] * (len(p) + len(q) - 1)
    for i, a in enumerate(p):
        if a.is_zero():
            continue
        for j, b in enumerate(q):
            out[i + j] = out[i + j] + a * b
    return trim(out)


def pscale(p, c) -> tuple:
    return trim(a * c for a in p)


def peval(p, x) -> MQ:
    acc = ZERO
    for c in reversed(p):
        acc = acc * x + c
    return acc


def pderiv(p) -> tuple:
    return trim(c * i for i, c in enumerate(p) if i > 0)


def pdivmod(p, q) -> tuple:
    """Quotient and remainder over the field (``q`` non-zero, trimmed)."""
    p, q = list(trim(p)), trim(q)
    lead_inv = 1 / q[-1]
    quot = [ZERO] * max(len(p) - len(q) + 1, 0)
    while len(p) >= len(q) and p:
        k = len(p) - len(q)
        c = p[-1] * lead_inv
        quot[k] = c
        for i, b in enumerate(q):
            p[i + k] = p[i + k] - c * b
        p = list(trim(p))
    return trim(quot), tuple(p)


def pgcd(p, q) -> tuple:
    """A greatest common divisor (up to a non-zero factor; a constant when coprime), by
    pseudo-remainders and without a division: an inverse of a coefficient with k primes
    in its radicands is k products of numbers of up to 2^k terms (the corrected variant's
    n = 30 run spent 30 s of one event there).  Once a remainder is linear, the other
    polynomial vanishes at its root or the two are coprime."""
    p, q = trim(p), trim(q)
    if len(p) < len(q):
        p, q = q, p
    while q:
        if len(q) == 2 and len(p) > 1:
            return q if _vanishes_at_root(p, q) else (MQ.rational(1),)
        p, q = q, _pseudo_remainder(p, q)
    return p


def _pseudo_remainder(p, q) -> tuple:
    """``lc(q)^k p`` modulo ``q`` (``len(p) >= len(q)``), with products only."""
    r, lead = list(p), q[-1]
    while len(r) >= len(q) and r:
        k, top = len(r) - len(q), r[-1]
        r = [c * lead for c in r]
        for i, b in enumerate(q):
            r[i + k] = r[i + k] - top * b
        r = list(trim(r))
    return tuple(r)


def _vanishes_at_root(p, line) -> bool:
    """Is ``p`` zero at the root ``-b / a`` of ``line = (b, a)``?  Homogeneously:
    ``sum_k p_k (-b)^k a^(n-k) == 0`` (n the degree of ``p``, ``a`` non-zero)."""
    b, a = line
    n = len(p) - 1
    acc, pb, pa = ZERO, MQ.rational(1), [MQ.rational(1)]
    for _ in range(n):
        pa.append(pa[-1] * a)
    for k, c in enumerate(p):
        if not c.is_zero():
            acc = acc + c * pb * pa[n - k]
        pb = pb * -b
    return acc.is_zero()


def monic(p) -> tuple:
    inv = 1 / p[-1]
    return tuple(c * inv for c in p)


def coefficient_bits(p) -> int:
    """The largest size in bits of a rational of ``p``'s MQ coefficients."""
    return max((int(c.p).bit_length() + int(c.q).bit_length()
                for x in p for c in x.terms.values()), default=0)


def bounded_gcd(p, q, budget: int | None = None):
    """The monic gcd over the coefficients' field by Euclid's algorithm; None when a
    remainder's coefficients exceed ``budget`` bits (they swell over a number field)."""
    p, q = trim(p), trim(q)
    while q:
        p, q = q, pdivmod(p, q)[1]
        if budget is not None and coefficient_bits(q) > budget:
            return None
    return monic(p) if p else p


def shift(p, c) -> tuple:
    """``p(x + c)`` (Horner)."""
    acc: tuple = ()
    for a in reversed(p):
        acc = padd(pmul(acc, (c, ONE)), (a,))
    return acc
