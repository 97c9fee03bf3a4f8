"""Exact string matching (Knuth-Morris-Pratt) on sequences of hashable symbols.

Used by the ground truth (periods and mirror occurrences of the ray string) and by the
paper layer (periods of gap sequences): generic text algorithms, no geometry.
"""

from __future__ import annotations

from typing import Iterator, Sequence


def prefix_function(s: Sequence) -> list[int]:
    """``pi[i]``: length of the longest proper border of ``s[:i + 1]``."""
    pi = [0] * len(s)
    k = 0
    for i in range(1, len(s)):
        c = s[i]
        while k and s[k] != c:
            k = pi[k - 1]
        if s[k] == c:
            k += 1
        pi[i] = k
    return pi


def find_all(pattern: Sequence, text: Sequence) -> Iterator[int]:
    """Start positions of ``pattern`` (non-empty) in ``text``, increasing, lazily."""
    m = len(pattern)
    pi = prefix_function(pattern)
    k = 0
    for i, c in enumerate(text):
        while k and pattern[k] != c:
            k = pi[k - 1]
        if pattern[k] == c:
            k += 1
        if k == m:
            yield i - m + 1
            k = pi[k - 1]


def first_occurrence(pattern: Sequence, text: Sequence) -> int | None:
    """The first start position of ``pattern`` in ``text``, or None."""
    return next(find_all(pattern, text), None)


def cyclic_period(s: Sequence) -> int:
    """The least p > 0 with ``s`` equal to itself rotated by p (p divides ``len(s)``)."""
    m = len(s)
    if m == 0:
        return 1
    p = m - prefix_function(s)[-1]
    return p if m % p == 0 else m


def cyclic_occurrences(pattern: Sequence, cyclic: Sequence) -> list[int]:
    """The j in ``range(len(cyclic))`` with ``cyclic`` rotated by j equal to ``pattern``."""
    m = len(pattern)
    if m != len(cyclic):
        return []
    if m == 0:
        return [0]
    return list(find_all(pattern, list(cyclic) + list(cyclic[:-1])))
