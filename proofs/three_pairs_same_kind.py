"""lem-3-pair-sym and theorem-sym-pair-symG under the readings of "common line"
(standard library; proofs/readings.py).

The witness: three concentric levels, polar about C, turns rational --

* r = 1: a rectangle with mirrors at 0 and 1/4 turn (vertices at +-1/12, 1/2 +- 1/12);
* r = 2: an equilateral triangle with a vertex at turn 0 (mirrors at 0, 1/6, 1/3 turn);
* r = 3: a rectangle with mirrors at 1/6 and 5/12 turn (vertices at 1/6 +- 1/12,
  2/3 +- 1/12).

Preprocess leaves it alone (one odd polygon), so G' = G.  Same kind of line for both
polygons of a pair: <G1, G2> share the straight line at 0, <G2, G3> the straight line at
1/6, and the two rectangles are centrally symmetric, so every line through C is a line of
skew symmetry of both.  No line is straight for all three (the rectangles' mirrors differ)
and the triangle has no line of skew symmetry: three pairwise symmetric polygons with no
common line, so lem-3-pair-sym and theorem-sym-pair-symG (t = 3) fail under every
same-kind reading.  Under the mixed reading the line at 0 is common (straight for G1 and
G2, skew for G3) and both hold here.

    python proofs/three_pairs_same_kind.py
"""

from __future__ import annotations

import sys
from fractions import Fraction as Q
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import readings as R  # noqa: E402

G1 = [Q(1, 12), Q(5, 12), Q(7, 12), Q(11, 12)]
G2 = [Q(0), Q(1, 3), Q(2, 3)]
G3 = [Q(1, 12), Q(1, 4), Q(7, 12), Q(3, 4)]
POINTS = [(Q(1), t) for t in G1] + [(Q(2), t) for t in G2] + [(Q(3), t) for t in G3]


def _name(reading) -> str:
    return (f"{reading['pair']}, {'containing' if reading['containing'] else 'literal'}, "
            f"singleton {reading['singleton']}")


def check() -> dict:
    """Assert the witness's facts and return, per reading, whether the two statements
    fail on it (every pair symmetric, yet no line common to all three)."""
    G = R.levels(POINTS)
    assert [set(g) for g in G] == [set(G1), set(G2), set(G3)]
    assert [R.polygon_type(g) for g in G] == ["type-1", "type-0", "type-1"]
    assert R.mirrors(G1) == {Q(0), Q(1, 2)} and R.mirrors(G3) == {Q(1, 3), Q(5, 6)}
    assert R.centrally_symmetric(G1) and R.centrally_symmetric(G3)
    assert not R.centrally_symmetric(G2)
    assert R.sec_centre_is_origin(POINTS)
    fails = {}
    for reading in R.READINGS:
        pairs = all(R.family_symmetric([G[i], G[j]], reading)
                    for i in range(3) for j in range(i + 1, 3))
        whole = R.family_symmetric(G, reading)
        fails[_name(reading)] = pairs and not whole
        assert pairs                                  # every pair shares a line
        assert whole == (reading["pair"] == "mixed")  # a common line only when mixed
    return {"fails_under": sorted(k for k, v in fails.items() if v),
            "holds_under": sorted(k for k, v in fails.items() if not v)}


if __name__ == "__main__":
    r = check()
    print(f"lem-3-pair-sym / theorem-sym-pair-symG fail under {len(r['fails_under'])} "
          f"readings: {'; '.join(r['fails_under'])}")
    print(f"and hold on this witness under: {'; '.join(r['holds_under'])}")
