"""Check_Symmetry_Odd with its loop fixed counts the mirrors: an exhaustive finite check.

Claim (proofs/check_symmetry_odd.md gives the proof for every odd polygon inscribed in a
circle): for a polygon with an odd number n of vertices, the number of vertices v with
CW_v = ACW_v (what Check_Symmetry_Odd's ``deg_sym`` counts once ``i++`` runs after every
vertex) equals the number of its lines of straight symmetry, and each such line passes
through exactly one vertex.  So, read with the evident loop, Check_Symmetry_Odd reports
"asymmetric" exactly when the polygon has no mirror -- which for odd n is the paper's
definition of asymmetric (an odd polygon is never skew symmetric: the half-turn about C
would pair its vertices).

The check: every polygon whose vertices are among the N-th roots of unity (turns x/N),
with an odd number of vertices up to ``max_vertices``, up to rotation (vertex 0 always
present; both counts are invariant under rotation).  Distances are compared through the
exact integer key min(d, N - d) of the angular distance d (the chord 2 sin(pi d/N) is
strictly increasing in it).  Standard library only.

    python proofs/check_symmetry_odd.py            # N = 24, up to 11 vertices (the full run)
    python proofs/check_symmetry_odd.py 24 7       # a smaller bound (the test suite's)
"""

from __future__ import annotations

import sys
from itertools import combinations


def cw_keys(vertices: tuple, m: int, N: int) -> tuple:
    """CW_m: the distance keys from vertex m to the others, in cyclic order after m."""
    k = len(vertices)
    out = []
    for step in range(1, k):
        d = (vertices[(m + step) % k] - vertices[m]) % N
        out.append(min(d, N - d))
    return tuple(out)


def deg_sym_fixed_loop(vertices: tuple, N: int) -> int:
    """Check_Symmetry_Odd with ``i++`` after every vertex: #{v : CW_v = ACW_v}."""
    count = 0
    for m in range(len(vertices)):
        s = cw_keys(vertices, m, N)
        if s == s[::-1]:
            count += 1
    return count


def mirrors(vertices: tuple, N: int) -> list:
    """The lines of straight symmetry: s with x -> s - x (mod N) mapping the set onto
    itself (the line at turn s/(2N)); for an odd polygon none contains every vertex."""
    vs = set(vertices)
    return [s for s in range(N) if {(s - x) % N for x in vs} == vs]


def vertices_on(s: int, vertices: tuple, N: int) -> int:
    return sum(1 for x in vertices if (2 * x - s) % N == 0)


def check(N: int = 24, max_vertices: int = 11) -> dict:
    """Run the check; raise AssertionError naming the first counterexample."""
    polygons = 0
    for k in range(1, max_vertices + 1, 2):
        for rest in combinations(range(1, N), k - 1):
            vertices = (0,) + rest
            lines = mirrors(vertices, N)
            deg = deg_sym_fixed_loop(vertices, N)
            assert deg == len(lines), (vertices, deg, lines)
            assert all(vertices_on(s, vertices, N) == 1 for s in lines), (vertices, lines)
            polygons += 1
    return {"N": N, "max_vertices": max_vertices, "polygons": polygons}


if __name__ == "__main__":
    args = [int(a) for a in sys.argv[1:]]
    result = check(*args) if args else check()
    print(f"holds on all {result['polygons']} polygons with an odd number of vertices "
          f"<= {result['max_vertices']} among the {result['N']}th roots of unity "
          "(up to rotation)")
