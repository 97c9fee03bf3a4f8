"""The ledger's witnesses under every reading (standard library; proofs/readings.py).

Each witness is a polar configuration (the same points as the case file named) and a
check that states, for every reading in ``readings.READINGS``, what the statement says
and what is true.  ``check()`` runs them all and returns, per statement, the readings
under which some witness refutes it; the ledger's ``--check`` runs it and the test suite
asserts the exact sets.

    python proofs/witnesses.py
"""

from __future__ import annotations

import sys
from fractions import Fraction as Q
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import readings as R  # noqa: E402


def _orbit(e, k=3):
    return [R.norm(Q(e) + Q(j, k)) for j in range(k)]


#: name -> (case file, [(r, turns)])
WITNESSES = {
    "merge_within_hypotheses": (
        "cases/discrepancies/family-merge-within-hypotheses.toml",
        [(1, [Q(0), Q(1, 3), Q(2, 3)] + _orbit(Q(3, 60)) + _orbit(Q(-3, 60))),
         (2, _orbit(Q(7, 60)) + _orbit(Q(-7, 60)) + _orbit(Q(11, 60)) + _orbit(Q(-11, 60))
          + [Q(0), Q(3, 60), Q(57, 60)]),
         (3, [Q(1, 6) + Q(1, 10), Q(1, 6) - Q(1, 10), Q(2, 3) + Q(1, 7),
              Q(2, 3) - Q(1, 7)])]),
    "mirror_inside_half_turn": (
        "cases/discrepancies/family-mirror-inside-half-turn.toml",
        [(1, [Q(1, 4), Q(1, 20), Q(9, 20)]),
         (2, [Q(0), Q(1, 10), Q(1, 4), Q(1, 2), Q(3, 5), Q(3, 4)])]),
    "two_gon_on_mirror": (
        "cases/family/two-gon-on-mirror.toml",
        [(1, [Q(0), Q(1, 2)]), (2, [Q(0), Q(2, 5), Q(3, 5)])]),
    "collinear_five": (
        "cases/discrepancies/family-collinear-five.toml",
        [(1, [Q(0)]), (2, [Q(0)]), (4, [Q(1, 2)]), (6, [Q(0), Q(1, 2)])]),
    "chiral_c3": (
        "cases/discrepancies/family-chiral-c3-ring.toml", None),   # read from the case
}


def _points(name):
    case, spec = WITNESSES[name]
    if spec is None:
        import tomllib
        root = Path(__file__).resolve().parent.parent
        with open(root / case, "rb") as fh:
            data = tomllib.load(fh)
        return [(Q(p["r"]), Q(p["turn"])) for p in data["points"]]
    return R.points_of(spec)


def _name(reading) -> str:
    return (f"{reading['pair']}, {'containing' if reading['containing'] else 'literal'}, "
            f"singleton {reading['singleton']}")


def refutations() -> dict:
    """statement -> {reading name -> [witness names refuting it under that reading]}."""
    out: dict = {}

    def add(statement, reading, witness):
        out.setdefault(statement, {}).setdefault(_name(reading), []).append(witness)

    for name in WITNESSES:
        pts = _points(name)
        G = R.levels(pts)
        in_os = R.in_O_S(pts)
        orderable = R.orderable_about_centre(pts)
        for reading in R.READINGS:
            g_sym = R.family_symmetric(G, reading)
            if g_sym != in_os:
                add("Psym-Gsym", reading, name)
            if orderable == g_sym:
                add("cor-Pasym-Pord", reading, name)
            if orderable == in_os:
                add("Pasym-Pord", reading, name)
            for i in range(len(G)):
                for j in range(i + 1, len(G)):
                    sub = [p for p in pts if R.frac(p[0]) in
                           (_radius(pts, G[i]), _radius(pts, G[j]))]
                    if R.family_symmetric([G[i], G[j]], reading) and \
                            R.orderable_about_centre(sub) and len(sub) > 2:
                        add("lem-sym-notord", reading, name)
                        # a pair of two single robots is orderable about C but not as a
                        # free point set: only pairs of more than two robots count here
            if name == "merge_within_hypotheses":
                A, B, Gk = G
                S = R.project(A, B)
                hyp = (len(A) % 2 == 1 and len(B) % 2 == 1 and len(B) % len(A) != 0
                       and _gcd(len(A), len(B)) > 1
                       and R.family_symmetric([A, B], reading))
                if hyp and R.polygon_type(S) == "type-4":
                    common = R.straight_lines(A, reading) & R.straight_lines(B, reading)
                    if not R.straight_lines(S, reading) <= common:
                        add("lem-los-gij", reading, name)
                    if R.family_symmetric([S, Gk], reading) != R.family_symmetric(G, reading):
                        add("Gprime-equiG", reading, name)
                    if len(common) != _gcd(len(A), len(B)):
                        add("obs-gcd", reading, name)
    return out


def _radius(pts, polygon):
    """The radius of the level whose turns are ``polygon``."""
    by_r: dict = {}
    for r, t in pts:
        by_r.setdefault(R.frac(r), set()).add(R.norm(R.frac(t)))
    return next(r for r, ts in by_r.items() if ts == set(polygon))


def _gcd(a, b):
    while b:
        a, b = b, a % b
    return a


def facts() -> dict:
    """The ground facts of each witness (every reading agrees on them)."""
    out = {}
    for name in WITNESSES:
        pts = _points(name)
        out[name] = {"n": len(pts), "sec_centre_is_C": R.sec_centre_is_origin(pts),
                     "in_O_S": R.in_O_S(pts), "orderable": R.orderable_about_centre(pts)}
    return out


def check() -> dict:
    return {"facts": facts(), "refutations": refutations(),
            "readings": [_name(r) for r in R.READINGS]}


if __name__ == "__main__":
    result = check()
    for name, f in result["facts"].items():
        print(f"{name}: {f}")
    for statement, per in sorted(result["refutations"].items()):
        print(f"{statement}: refuted under {len(per)} of {len(result['readings'])} readings")
        for reading, ws in sorted(per.items()):
            print(f"    {reading}: {', '.join(sorted(set(ws)))}")
