"""gathering_pattern (Def. 1) read literally has no valid pattern for some n (standard
library, exact).

Def. 1: one robot at C, layers L = 1, 2, ... of robots whose centres are 2L from C, every
inner layer full, and each robot of a layer touching at least one robot of its layer.
Robots are unit discs, so two neighbours of layer L touch when their centres are 2 apart:
consecutive centres are the angle theta_L apart, cos theta_L = 1 - 1/(2 L^2), and the
capacity of layer L is the largest k with k theta_L <= 2 pi (6, 12, 18, 25, 31, ...).
The layers of n robots are forced: full layers, then the rest in the outermost one.  When
exactly one robot is left for the outermost layer it touches no robot of its layer, and
no other arrangement exists (the inner layers must be full): Def. 1 read literally has
no pattern of n robots.  That happens for n = 2, 8, 20, 38, 63, ... (1 + the robots of
the full layers + 1).  exactsym reads the lone robot as accepted (switch ``lone``,
exactsym/gathering/pattern.py); this script derives the list independently.

Capacities are exact: w_L^k = a_k + i b_k sqrt(4 L^2 - 1) with rational a_k, b_k (the
rotation recurrence); k theta_L passes 2 pi when b_k turns from negative back to
non-negative.

    python proofs/pattern_lone_layer.py 100
"""

from __future__ import annotations

import sys
from fractions import Fraction as Q


def capacity(L: int) -> int:
    """The largest k with k theta_L <= 2 pi (exact)."""
    D, h = 4 * L * L - 1, Q(2 * L * L)
    c, d = (h - 1) / h, 1 / h                 # w_L = c + i d sqrt(D)
    a, b, k, below = Q(1), Q(0), 0, False
    while True:
        a, b = a * c - b * d * D, a * d + b * c
        k += 1
        if b < 0:
            below = True
        elif below:
            return k if b == 0 else k - 1


def no_literal_pattern(limit: int) -> list:
    """Every n <= limit whose outermost layer would hold a single robot."""
    out, full, L = [], 1, 1          # full: robots at C and in the full layers so far
    while full + 1 <= limit:
        out.append(full + 1)
        full += capacity(L)
        L += 1
    return out


def check(limit: int = 100) -> dict:
    caps = [capacity(L) for L in range(1, 6)]
    assert caps == [6, 12, 18, 25, 31], caps
    ns = no_literal_pattern(limit)
    assert ns[:4] == [2, 8, 20, 38], ns
    return {"capacities": caps, "no_literal_pattern": ns}


if __name__ == "__main__":
    r = check(*(int(a) for a in sys.argv[1:]))
    print(f"capacities {r['capacities']}; no pattern under the literal Def. 1 for "
          f"n = {', '.join(map(str, r['no_literal_pattern']))}")
