"""Canonical forms generated directly: fixed-weight bracelets and orderly generation.

Nothing here enumerates all sets and deduplicates afterwards: each generator visits only
canonical prefixes and emits each class once, in a fixed lexicographic order, and can
start after any canonical form it emitted (so a sweep resumes without replaying).

* :func:`bracelets` -- sequences of length ``n`` over beads ``0..beads-1`` (a bead is the
  set of rings a robot occupies on one ray, as a bit mask), total weight ``k`` (popcount
  summed), one per class under rotation *and reversal*: the lexicographically least
  element of the dihedral orbit.  The necklaces come from the Fredricksen-Kessler-Maiorana
  (FKM) algorithm (Ruskey, Savage and Wang, "Generating necklaces", J. Algorithms 13,
  1992), iterative, with subtrees cut when the weight can no longer be exactly ``k``
  (cutting whole subtrees keeps FKM's prenecklace invariant); a necklace is kept when it
  is not larger than the least rotation of its reversal (Sawada's bracelet test).
* :func:`orderly_subsets` -- ``k``-subsets of ``0..cells-1`` up to a permutation group,
  by Read's orderly generation: a set is canonical when its sorted tuple is the least of
  its images; removing the largest element of a canonical set leaves a canonical set, so
  the search only extends canonical prefixes and each class is reached once, from its
  unique parent.
* :func:`burnside_count` -- the number of classes by Burnside's lemma (the exact size of
  a family, and the tests' independent count).
"""

from __future__ import annotations

from typing import Iterator, Sequence

__all__ = ["bracelets", "gap_bracelets", "gaps_to_positions", "is_bracelet", "least_rotation", "orderly_subsets", "is_canonical",
           "burnside_count", "dihedral_permutations", "square_permutations"]


def least_rotation(seq: Sequence[int]) -> tuple:
    """The lexicographically least rotation of ``seq`` (O(n^2), n is at most a few hundred)."""
    s = tuple(seq)
    return min(s[i:] + s[:i] for i in range(len(s))) if s else s


def is_bracelet(neck: tuple) -> bool:
    """A necklace (least rotation) is the least of its dihedral orbit iff it is not larger
    than the least rotation of its reversal."""
    return neck <= least_rotation(neck[::-1])


def bracelets(n: int, k: int, beads: int = 2, start_after: Sequence[int] | None = None,
              weights: Sequence[int] | None = None) -> Iterator[tuple]:
    """Bracelets of length ``n`` over ``0..beads-1`` whose bead weights sum to ``k``, in
    increasing lexicographic order, each as the least element of its orbit under rotation
    and reversal; after ``start_after`` (one such bracelet) when given.  ``weights[b]`` is
    the weight of bead b (default its popcount: the number of rings it occupies); with
    ``weights = range(beads)`` the beads are numbers and the bracelets are the cyclic
    compositions of ``k`` into ``n`` parts (:func:`gap_bracelets`)."""
    if n <= 0 or k < 0:
        return
    weight = list(weights) if weights is not None else [bin(b).count("1") for b in range(beads)]
    monotone = all(x <= y for x, y in zip(weight, weight[1:]))
    heaviest = max(weight)
    if k > heaviest * n:
        return
    a = [0] * (n + 1)             # a[1..n]; a[0] = 0 is FKM's sentinel
    period = [1] * (n + 1)        # period[t]: the prenecklace a[1..t]'s period (period[0] = 1)
    w = [0] * (n + 1)             # w[t]: weight of a[1..t]
    if start_after is not None:
        if len(start_after) != n:
            raise ValueError("start_after has the wrong length")
        for t in range(1, n + 1):
            a[t] = start_after[t - 1]
            period[t] = period[t - 1] if a[t] == a[t - period[t - 1]] else t
            w[t] = w[t - 1] + weight[a[t]]
        t = n
        a[t] += 1                 # the next candidate after start_after
    else:
        t = 1
        a[1] = 0
    while True:
        # unwind exhausted positions
        while a[t] >= beads:
            t -= 1
            if t == 0:
                return
            a[t] += 1
        v = a[t]
        p = period[t - 1]
        base = a[t - p]
        if v < base:              # below the prenecklace's forced value (only after resume)
            a[t] = base
            continue
        wt = w[t - 1] + weight[v]
        if wt > k:
            a[t] = beads if monotone else v + 1     # monotone: every larger bead is too heavy
            continue
        if wt + heaviest * (n - t) < k:
            a[t] += 1
            continue
        if t == n and wt != k:
            if monotone and weights is not None and wt < k:
                a[t] = v + (k - wt)                 # numbers: jump to the one value that fits
            else:
                a[t] += 1
            continue
        w[t] = wt
        period[t] = p if v == base else t
        if t == n:
            if n % period[t] == 0:
                neck = tuple(a[1:])
                if is_bracelet(neck):
                    yield neck
            a[t] += 1
        else:
            t += 1
            a[t] = a[t - period[t - 1]]


def gap_bracelets(m: int, k: int, start_after: Sequence[int] | None = None) -> Iterator[tuple]:
    """``k``-subsets of the m-gon's vertices up to rotation and reflection, as their gap
    sequences: ``g_i`` empty vertices after the i-th robot, sum m - k; one bracelet per
    class (a rotation or reversal of the polygon rotates or reverses the cyclic gap
    sequence, and back).  Depth k instead of m: the sparse families stay fast."""
    if k <= 0 or k > m:
        return
    yield from bracelets(k, m - k, beads=m - k + 1, start_after=start_after,
                         weights=range(m - k + 1))


def gaps_to_positions(gaps: Sequence[int]) -> tuple:
    """The vertices of a gap sequence, the first robot at vertex 0."""
    out, p = [], 0
    for g in gaps:
        out.append(p)
        p += g + 1
    return tuple(out)


def is_canonical(subset: Sequence[int], perms: Sequence[Sequence[int]]) -> bool:
    """True iff the sorted ``subset`` is the least (lexicographically) of its images."""
    s = tuple(subset)
    for g in perms:
        image = tuple(sorted(g[c] for c in s))
        if image < s:
            return False
    return True


def orderly_subsets(cells: int, k: int, perms: Sequence[Sequence[int]],
                    start_after: Sequence[int] | None = None) -> Iterator[tuple]:
    """The ``k``-subsets of ``0..cells-1``, one per orbit of the group ``perms`` (every
    element, identity included or not), each as its least sorted tuple, in increasing
    lexicographic order; after ``start_after`` when given."""
    if k <= 0 or k > cells:
        return
    perms = [tuple(g) for g in perms]
    a = [0] * k
    if start_after is not None:
        a = list(start_after)
        d = k - 1
        a[d] += 1
    else:
        d = 0
    while True:
        if a[d] > cells - (k - d):               # no room for the remaining elements
            d -= 1
            if d < 0:
                return
            a[d] += 1
            continue
        if is_canonical(a[:d + 1], perms):
            if d == k - 1:
                yield tuple(a)
                a[d] += 1
            else:
                d += 1
                a[d] = a[d - 1] + 1
        else:
            a[d] += 1


def _cycle_lengths(perm: Sequence[int]) -> list[int]:
    seen = [False] * len(perm)
    out = []
    for i in range(len(perm)):
        if not seen[i]:
            length, j = 0, i
            while not seen[j]:
                seen[j] = True
                j = perm[j]
                length += 1
            out.append(length)
    return out


def burnside_count(perms: Sequence[Sequence[int]], k: int) -> int:
    """Number of orbits of ``k``-subsets under the group ``perms`` (listed in full, each
    element once): the mean over the group of the subsets each element fixes (a fixed
    subset is a union of whole cycles: the coefficient of x^k in prod (1 + x^len))."""
    total = 0
    for g in perms:
        poly = [1] + [0] * k
        for length in _cycle_lengths(g):
            for d in range(k, length - 1, -1):
                poly[d] += poly[d - length]
        total += poly[k]
    assert total % len(perms) == 0
    return total // len(perms)


def dihedral_permutations(m: int, rings: int = 1) -> list[tuple]:
    """The dihedral group of order 2m on the cells ``ring * m + j`` (ray j of ring ``ring``):
    rotations j -> j + s and reflections j -> s - j, the same on every ring."""
    out = []
    for s in range(m):
        for sign in (1, -1):
            out.append(tuple(r * m + (s + sign * j) % m for r in range(rings) for j in range(m)))
    return out


def square_permutations(n: int) -> list[tuple]:
    """The eight symmetries of the n x n grid on the cells ``x * n + y``."""
    maps = [lambda x, y: (x, y), lambda x, y: (n - 1 - y, x), lambda x, y: (n - 1 - x, n - 1 - y),
            lambda x, y: (y, n - 1 - x), lambda x, y: (n - 1 - x, y), lambda x, y: (x, n - 1 - y),
            lambda x, y: (y, x), lambda x, y: (n - 1 - y, n - 1 - x)]
    out = []
    for f in maps:
        perm = []
        for x in range(n):
            for y in range(n):
                u, v = f(x, y)
                perm.append(u * n + v)
        out.append(tuple(perm))
    return out
