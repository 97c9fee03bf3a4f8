"""Exact reciprocals of the squared lengths the paper layer divides by, cached.

An inverse in a cyclotomic field of degree hundreds costs up to a second (issue 9), and
the paper layer's keys divide by squared lengths |u|^2 of direction vectors: the vertices
of a level share one, so a cache by exact value makes it one inverse per distinct length
instead of one per key.  Rationals (the usual case: a circle of rational radius about a
rational centre) are divided directly, never cached.  The cache holds exact values: it
changes how a key is computed, never its value.
"""

from __future__ import annotations

from ..exact import exact_key, fmpq
from ..exact.number import any_algebraic, is_algebraic
from ..exact.context import Cache

_INVERSES = Cache("inverse lengths")     # exact key -> inverse
_LIMIT = 256


def reciprocal(v):
    """1/v, exact (an ``int`` becomes an ``fmpq``, never a float)."""
    return fmpq(1, v) if isinstance(v, int) else fmpq(1) / v


def inverse_length(length):
    """1/length (``length`` a non-zero exact number), cached when irrational."""
    if not is_algebraic(length) or length.is_rational():
        return reciprocal(length)
    k = exact_key(length)
    inverses = _INVERSES.table()
    inv = inverses.get(k)
    if inv is None:
        if len(inverses) >= _LIMIT:
            inverses.clear()
        inv = inverses[k] = reciprocal(length)
    return inv


_LENGTHS = Cache("squared lengths")     # id(d) -> (d, |d|^2)


def squared_length(d):
    """``d_x^2 + d_y^2`` of an exact vector, remembered per vector *object* when it holds
    algebraic numbers (the entry keeps the vector, so an id is never mistaken for another
    object's): the keys of one polygon read each vertex's length many times."""
    x, y = d
    if not any_algebraic(d):
        return x * x + y * y
    lengths = _LENGTHS.table()
    hit = lengths.get(id(d))
    if hit is not None and hit[0] is d:
        return hit[1]
    value = x * x + y * y
    if len(lengths) >= 1 << 14:
        lengths.clear()
    lengths[id(d)] = (d, value)
    return value


__all__ = ["inverse_length", "reciprocal", "squared_length"]
