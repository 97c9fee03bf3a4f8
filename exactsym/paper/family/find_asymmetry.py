"""``FindAsymmetry`` and ``Find_Asymmetry_Pair`` (named by MakeAsym, Section 4.2,
but not given): the evident meanings, ``lem-one-pair-asym-ord`` and
``lem-all-pair-asym-ord``.
"""

from __future__ import annotations

from bisect import bisect_left
from typing import Sequence

from .concentric import (ALL_LINES, Ring, common_lines, has_lines, intersect_lines,
                         is_symmetric_polygon)
from .limits import WorkBudgetExceeded


def find_asymmetry(G: Sequence[Ring]) -> int | None:
    """``FindAsymmetry`` (named, not given): the evident meaning, the first polygon of G'
    (nearest first) that is asymmetric (``def-asymmetric-poly``: no line of straight or
    skew symmetry); its index, or None.  (The paper's "binary search on G_1 u ... u G_t"
    cannot find an asymmetric polygon faster than looking at each: we look at each.)"""
    for i, ring in enumerate(G):
        if not is_symmetric_polygon(ring):
            return i
    return None


def find_asymmetry_pair(G: Sequence[Ring], budget: int | None = None) -> tuple[int, int] | None:
    """``Find_Asymmetry_Pair`` (named, not given): the first asymmetric pair (no common
    line, ``def-sym-pair``) <G_i, G_j>, i < j, in lexicographic order of (i, j) (the
    order ``lem-all-pair-asym-ord``'s proof uses); None when every pair is symmetric.

    Exact, without looking at every pair: when all polygons have a common line every pair
    shares it (None at once); a polygon without a line pairs asymmetrically with the next
    one; otherwise the next few polygons are tried, and then an index from each line to
    the polygons having it counts the polygons after G_i that share a line with it (or
    have every line): G_i has an asymmetric partner iff that count falls short, and the
    first partner is then located.  ``budget``: index steps (None: unbounded); exceeding
    it raises :class:`WorkBudgetExceeded`."""
    t = len(G)
    if t < 2 or has_lines(common_lines(G)):
        return None
    steps = 0

    def spend(k):
        nonlocal steps
        steps += k
        if budget is not None and steps > budget:
            raise WorkBudgetExceeded(f"Find_Asymmetry_Pair: more than {budget} steps")

    quick = 8
    index = None
    for i in range(t - 1):
        li = G[i].lines
        if not has_lines(li):
            return i, i + 1
        end = min(t, i + 1 + quick)
        spend(end - i)
        for j in range(i + 1, end):
            if not has_lines(intersect_lines(li, G[j].lines)):
                return i, j
        if end == t:
            continue
        if index is None:
            spend(t)
            index, all_after, next_empty = _line_index(G)
        # polygons at positions >= end compatible with G_i
        if li is ALL_LINES:
            j = next_empty[end]
            if j < t:
                return i, j
            continue
        sharing = set()
        for line in li:
            positions = index.get(line, ())
            lo = bisect_left(positions, end)
            spend(len(positions) - lo + 1)
            sharing.update(positions[lo:])
        if len(sharing) + all_after[end] == t - end:
            continue
        for j in range(end, t):
            spend(1)
            if j not in sharing and G[j].lines is not ALL_LINES:
                return i, j
    return None


def _line_index(G: Sequence[Ring]):
    """``(line -> sorted positions of the polygons with that line (finite sets only),
    all_after[k] = number of polygons at positions >= k with every line, next_empty[k] =
    first position >= k of a polygon without a line (len(G) when none))``."""
    t = len(G)
    index: dict = {}
    all_after = [0] * (t + 1)
    next_empty = [t] * (t + 1)
    for k in range(t - 1, -1, -1):
        lines = G[k].lines
        all_after[k] = all_after[k + 1] + (lines is ALL_LINES)
        next_empty[k] = k if lines is not ALL_LINES and not lines else next_empty[k + 1]
    for k, g in enumerate(G):
        lines = g.lines
        if lines is not ALL_LINES:
            for line in lines:
                index.setdefault(line, []).append(k)
    return index, all_after, next_empty
