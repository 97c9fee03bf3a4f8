"""``lemma-straight-sym`` under its readings: an exhaustive finite check.

The lemma: for a straight symmetric polygon G, a line L (through C) is a line of straight
symmetry iff CW_m = ACW_m or CW_m' = ACW_m', where m, m' are where L meets G.  Readings:

* ``or`` (as printed) with m, m' the points of the circle on L: **false** -- a string of
  odd length has a free middle entry (an even polygon's vertex string, an odd polygon's
  edge string), so one end can be a palindrome on a line that is no mirror
  (``cases/discrepancies/isosceles-triangle.toml``: every edge midpoint of a triangle);
* ``and`` with m, m' the points of the circle on L: **true** (this module checks it
  exhaustively; proofs/straight_sym_readings.md gives the argument for every polygon);
* ``and`` with m, m' the points where L meets the polygon's boundary: false when an edge
  is a diameter (m' = C, every distance equal: ``cases/discrepancies/half-hexagon-
  trapezoid.toml``, turns 0, 1/6, 1/3, 1/2, the line through the vertex at 1/6);
* ``and`` with m, m' on the circle but L any straight line, as printed (not only lines
  through C): false -- in the equilateral triangle (turns 0, 1/3, 2/3) the chord between
  the circle points at turns 1/6 and 1/2 has both strings palindromes and is no mirror
  (:func:`chord_witness`): equal distances from a circle point m make two points mirror
  images across the diameter through m, which is L only when L passes through C.

Polygons: vertices among the N-th roots of unity (turns x/N), 2..``max_vertices``
vertices, up to rotation; lines: the N lines through C at turns s/(2N).  Work in units of
1/(2N) turn: vertices at even positions 2x, the ends of line s at s and s + N.  Distance
keys: min(d, 2N - d) of the angular distance (the chord is increasing in it).
"""

from __future__ import annotations

import sys
from itertools import combinations


def string_at(p: int, vertices: tuple, M: int) -> tuple:
    """The distance keys from the circle point p to the vertices other than p, clockwise
    (decreasing position) from p; M = 2N positions."""
    others = sorted(((p - v) % M, v) for v in vertices if v % M != p % M)
    return tuple(min(d, M - d) for d, _ in others)


def palindrome(s: tuple) -> bool:
    return s == s[::-1]


def chord_witness() -> tuple:
    """The equilateral triangle and the chord between the circle points at turns 1/6 and
    1/2 (12th roots: vertices at positions 0, 8, 16 of M = 24; the chord's ends at 4 and
    12): both strings are palindromes, the chord does not pass through C (its ends are
    not antipodal), so it is no line of symmetry."""
    M, vertices, ends = 24, (0, 8, 16), (4, 12)
    strings = tuple(string_at(p, vertices, M) for p in ends)
    assert all(palindrome(s) for s in strings), strings
    assert (ends[1] - ends[0]) % M != M // 2          # not a diameter: not through C
    return strings


def check(N: int = 24, max_vertices: int = 8) -> dict:
    """Assert the ``and`` reading on every polygon; count the ``or`` reading's failures."""
    M = 2 * N
    polygons = or_failures = 0
    first_or_failure = None
    for k in range(2, max_vertices + 1):
        for rest in combinations(range(1, N), k - 1):
            xs = (0,) + rest
            vertices = tuple(2 * x for x in xs)
            vs = set(xs)
            mirror = {s for s in range(N) if {(s - x) % N for x in vs} == vs
                      and not all((2 * x - s) % N == 0 for x in vs)}
            if not mirror:
                continue            # the lemma assumes G straight symmetric
            polygons += 1
            for s in range(N):
                a = palindrome(string_at(s, vertices, M))
                b = palindrome(string_at(s + N, vertices, M))
                contains_all = all((2 * x - s) % N == 0 for x in vs)
                if contains_all:
                    continue        # not a candidate line (def-straight-symmetric-conf)
                assert (a and b) == (s in mirror), (xs, s)
                if (a or b) != (s in mirror):
                    or_failures += 1
                    first_or_failure = first_or_failure or (xs, s)
    return {"N": N, "max_vertices": max_vertices, "straight_symmetric_polygons": polygons,
            "or_reading_failures": or_failures, "first_or_failure": first_or_failure,
            "chord_not_through_C": chord_witness()}


if __name__ == "__main__":
    args = [int(a) for a in sys.argv[1:]]
    r = check(*args) if args else check()
    print(f"'and' reading holds on all {r['straight_symmetric_polygons']} straight symmetric "
          f"polygons with <= {r['max_vertices']} vertices among the {r['N']}th roots of "
          f"unity (up to rotation), every line through C; the 'or' reading fails on "
          f"{r['or_reading_failures']} (polygon, line) pairs, first {r['first_or_failure']}")
