"""Elect_Leader_Sym's tie VI = VJ within its hypothesis: an exhaustive search.

For an even polygon whose only mirror passes through two (antipodal) vertices u and w,
Elect_Leader_Sym compares VI = CW(u) and VJ = CW(w) and returns v_j when they are equal,
a choice made by the labelling. This module searches every such polygon with vertices
among the N-th roots of unity (vertex 0 and N/2 on the mirror, up to ``max_vertices``
vertices) for a tie; ``check`` asserts that there is none. Distances are the exact keys
min(d, N - d) of the angular distance.

    python proofs/elect_leader_sym_tie.py 24 12     # the full run (no tie)
"""

from __future__ import annotations

import sys
from itertools import combinations


def cw(m: int, xs: tuple, N: int) -> tuple:
    ordered = sorted(((m - x) % N, x) for x in xs if x != m)
    return tuple(min(d, N - d) for d, _ in ordered)


def check(N: int = 24, max_vertices: int = 12) -> dict:
    assert N % 2 == 0
    polygons = 0
    for k in range(4, max_vertices + 1, 2):
        for rest in combinations(range(1, N), k - 1):
            xs = (0,) + rest
            vs = set(xs)
            if N // 2 not in vs:
                continue
            if [s for s in range(N) if {(s - x) % N for x in vs} == vs] != [0]:
                continue            # exactly one mirror, the line through 0 and N/2
            polygons += 1
            assert cw(0, xs, N) != cw(N // 2, xs, N), xs
    return {"N": N, "max_vertices": max_vertices, "polygons": polygons}


if __name__ == "__main__":
    args = [int(a) for a in sys.argv[1:]]
    r = check(*args) if args else check()
    print(f"no tie VI = VJ on the {r['polygons']} polygons with one mirror through two "
          f"vertices, <= {r['max_vertices']} vertices among the {r['N']}th roots of unity")
