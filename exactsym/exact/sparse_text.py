"""The configuration-syntax text of a sparse cyclotomic number (:mod:`.sparse_cyclotomic`).

A real x = sum c_e zeta_N^e equals its real part sum c_e cos(2 pi e/N), so the sum of
cosines, with cos(2 pi e/N) = cos(2 pi (N-e)/N) merged and the rational cosines joining the
constant, is an expression of x that parses back to x (whatever the non-canonical form of
x, the value is right).  A fraction prints as ``(num)/(den)``.
"""

from __future__ import annotations

from math import gcd

from flint import fmpq

from .field import rational_text, sum_text

#: cos(2 pi e/N) by the order N/gcd(e, N) of zeta^e, where it is rational
_RATIONAL_COS = {1: fmpq(1), 2: fmpq(-1), 3: fmpq(-1, 2), 4: fmpq(0), 6: fmpq(1, 2)}


def _cosine_sum(terms: dict, n: int) -> str:
    const, merged = fmpq(0), {}
    for e, c in terms.items():
        e = min(e, n - e) if e else 0
        rational = _RATIONAL_COS.get(n // gcd(e, n))
        if rational is not None:
            const += c * rational
        else:
            merged[e] = merged.get(e, fmpq(0)) + c
    out = []
    for e in sorted(merged):
        c = merged[e]
        if c == 0:
            continue
        g = gcd(2 * e, n)
        p, q = 2 * e // g, n // g
        head = "pi" if p == 1 else f"{p}*pi"
        out.append((c, f"cos({head if q == 1 else f'{head}/{q}'})"))
    return sum_text([(const, "")] + out)


def sparse_text(x) -> str:
    """The text of a :class:`~.sparse_cyclotomic.SparseCyclotomic`; it parses back to x."""
    if x.is_rational():
        return rational_text(x.to_fmpq())
    num = _cosine_sum(x.num, x.ctx.n)
    if x.den is None:
        return num
    return f"({num})/({_cosine_sum(x.den, x.ctx.n)})"


__all__ = ["sparse_text"]
