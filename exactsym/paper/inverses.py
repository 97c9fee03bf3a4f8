"""Exact reciprocals of the squared lengths the paper layer divides by, cached.

An inverse in a cyclotomic field of degree hundreds costs up to a second (issue 9), and
the paper layer's keys divide by squared lengths |u|^2 of direction vectors: the vertices
of a level share one, so a cache by exact value makes it one inverse per distinct length
instead of one per key.  Rationals (the usual case: a circle of rational radius about a
rational centre) are divided directly, never cached.  The cache holds exact values: it
changes how a key is computed, never its value.
"""

from __future__ import annotations

from ..exact import FieldElement, exact_key, fmpq

_INVERSES: dict = {}
_LIMIT = 256


def reciprocal(v):
    """1/v, exact (an ``int`` becomes an ``fmpq``, never a float)."""
    return fmpq(1, v) if isinstance(v, int) else fmpq(1) / v


def inverse_length(length):
    """1/length (``length`` a non-zero exact number), cached when irrational."""
    if not isinstance(length, FieldElement) or length.is_rational():
        return reciprocal(length)
    k = exact_key(length)
    inv = _INVERSES.get(k)
    if inv is None:
        if len(_INVERSES) >= _LIMIT:
            _INVERSES.clear()
        inv = _INVERSES[k] = reciprocal(length)
    return inv


__all__ = ["inverse_length", "reciprocal"]
