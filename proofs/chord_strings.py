"""Chord-length strings cannot tell an arc from its complement: where that matters
(standard library, exact, positions on the N-th roots of unity).

CW_m lists the distances from m to the vertices; a chord is the same for the arc theta and
its complement 1 - theta.  Two consequences:

* at a circle point m, equal entries only say that two vertices are mirror images across
  the diameter through m, so CW_m = ACW_m at both ends of a chord L that does not pass
  through C says nothing about L (the equilateral triangle and the chord between turns
  1/6 and 1/2: proofs/straight_sym_readings.py, ``chord_witness``; lemma-straight-sym
  needs L through C);
* between vertex strings (Theorem 1, conditions 2 and 3: CW_vi = CW_vj, CW_vi = ACW_vj)
  the ambiguity could make two vertices look alike when their arcs differ.  This module
  checks that it does not, on every asymmetric polygon with vertices among the N-th roots
  of unity (up to rotation, 3 to ``max_vertices`` vertices): equal chord strings come
  with equal arc strings, so Theorem 1's failures are the rotation (condition 2) and the
  free middle entry (condition 1), not this ambiguity.

    python proofs/chord_strings.py 24 7
"""

from __future__ import annotations

import sys
from itertools import combinations


def _strings(xs: tuple, N: int, chord: bool) -> list:
    """Per vertex (CW, ACW): the arcs (in 1/N turn) or their chord keys min(d, N - d)."""
    n, out = len(xs), []
    key = (lambda d: min(d, N - d)) if chord else (lambda d: d)
    for i, v in enumerate(xs):
        cw = tuple(key((v - xs[(i - s) % n]) % N) for s in range(1, n))
        acw = tuple(key((xs[(i + s) % n] - v) % N) for s in range(1, n))
        out.append((cw, acw))
    return out


def _symmetric(xs: tuple, N: int) -> bool:
    """A mirror or a rotation maps the vertex set onto itself."""
    S = set(xs)
    return any({(s - x) % N for x in S} == S for s in range(N)) or \
        any({(x + r) % N for x in S} == S for r in range(1, N))


def check(N: int = 12, max_vertices: int = 7) -> dict:
    """Assert: on every asymmetric polygon, chord strings of two vertices are equal (in
    the sense of conditions 2 and 3) only when their arc strings are."""
    polygons = 0
    for k in range(3, max_vertices + 1):
        for rest in combinations(range(1, N), k - 1):
            xs = (0,) + rest
            if _symmetric(xs, N):
                continue
            polygons += 1
            ch, arc = _strings(xs, N, True), _strings(xs, N, False)
            for i in range(k):
                for j in range(k):
                    if i != j:
                        assert (ch[i][0] == ch[j][0]) == (arc[i][0] == arc[j][0]), (xs, i, j)
                        assert (ch[i][0] == ch[j][1]) == (arc[i][0] == arc[j][1]), (xs, i, j)
    return {"N": N, "max_vertices": max_vertices, "asymmetric_polygons": polygons}


if __name__ == "__main__":
    r = check(*(int(a) for a in sys.argv[1:]))
    print(f"no false equality of vertex strings on {r['asymmetric_polygons']} asymmetric "
          f"polygons with <= {r['max_vertices']} vertices among the {r['N']}th roots of unity")
