"""The strings of symbols the ground truth compares (issue 2, ``docs/interpretations.md``):
the rays' symbols (radii of a ray, angle to the next) read either way, interned as small
integers, and the least rotation of such a string (Booth's algorithm).  Nothing here is
shared with the paper layer.

Public names: :func:`least_rotation`, :class:`Symbols`, :func:`intern_symbols`,
:func:`rotation_less`.
"""

from __future__ import annotations

from typing import Sequence

from ..exact.number import is_plain_rational, large_dense
from ..exact.ordering import value_key


def least_rotation(ids: Sequence[int], values: Sequence, candidates: Sequence[int] | None = None
                   ) -> int:
    """Booth's algorithm: the least j such that the rotation of the string by j is
    lexicographically least.  ``ids[i]`` decides equality of symbols (equal ids iff
    equal symbols), ``values[i]`` their order when they differ.  ``candidates``, when
    given, must hold every position of the least symbol (it saves a pass over the
    string when that symbol is unique, the usual case)."""
    m = len(ids)
    if m == 0:
        return 0
    pool = range(m) if candidates is None else candidates
    low = min(pool, key=values.__getitem__)
    if sum(1 for i in pool if ids[i] == ids[low]) == 1:    # a unique least symbol
        return low
    s = list(ids) + list(ids)
    f = [-1] * (2 * m)
    k = 0
    for j in range(1, 2 * m):
        sj = s[j]
        i = f[j - k - 1]
        while i != -1 and sj != s[k + i + 1]:
            if values[j % m] < values[(k + i + 1) % m]:
                k = j - i - 1
            i = f[i]
        if sj != s[k + i + 1]:          # here i == -1
            if values[j % m] < values[k % m]:
                k = j
            f[j - k] = -1
        else:
            f[j - k] = i + 1
    return k % m


class Symbols:
    """The symbols ``(radii of ray r, angle to the next ray)`` read counter-clockwise, or
    clockwise (``(radii of ray -i, angle from ray -i-1 to ray -i)``), made on demand."""

    __slots__ = ("radii", "gaps", "clockwise")

    def __init__(self, radii, gaps, clockwise: bool):
        self.radii, self.gaps, self.clockwise = radii, gaps, clockwise

    def __getitem__(self, i: int):
        m = len(self.radii)
        if self.clockwise:
            return (self.radii[-i % m], self.gaps[(-i - 1) % m])
        return (self.radii[i], self.gaps[i])

    def __len__(self) -> int:
        return len(self.radii)


def intern_symbols(values, tuples: bool) -> list[int]:
    """Small integers, equal iff the values (numbers, or tuples of numbers) are equal.
    An ``fmpq`` is keyed by its (reduced, hence canonical) numerator and denominator:
    ``hash(fmpq)`` goes through ``fractions.Fraction`` and costs about 2 us."""
    first = values[0][0] if tuples else values[0]
    ids: dict = {}
    if is_plain_rational(first):
        if tuples:
            keys = (tuple([(x.p, x.q) for x in v]) if len(v) > 1 else (v[0].p, v[0].q)
                    for v in values)
        else:
            keys = ((x.p, x.q) for x in values)
    elif large_dense(first):
        # a field of large degree: hashing an element's fmpq coefficients costs ms
        keys = (tuple([value_key(x) for x in v]) if tuples else value_key(v) for v in values)
    else:
        keys = iter(values)
    return [ids.setdefault(key, len(ids)) for key in keys]


def rotation_less(a_ids, a_vals, a_start, b_ids, b_vals, b_start) -> bool:
    """Is the rotation of string a by ``a_start`` lexicographically less than that of b?"""
    m = len(a_ids)
    for d in range(m):
        i, j = (a_start + d) % m, (b_start + d) % m
        if a_ids[i] != b_ids[j]:
            return a_vals[i] < b_vals[j]
    return False


__all__ = ["least_rotation", "Symbols", "intern_symbols", "rotation_less"]
