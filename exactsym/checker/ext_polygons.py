"""Checker extension: refutations of the statements about the polygons of G_P (standard library
only; docs/certificates.md, "Refutations"), reached through ``dispatch.REFUTATIONS``.

The polygons of G_P are the levels of P about the centre c of its SEC.  They are checked on
rational polar certificates only, where c is the origin (verified by the group certificate) and
a level is the set of points with one r2.  A part -- a level, a pair of levels, the merged
polygon G_ij -- comes with a group certificate of its own, whose points must be exactly those
the checker computes from P.  Lines of symmetry of a polygon with >= 3 vertices on a circle
about c (no reading of "common line" differs there: no line holds every vertex, none a single
vertex): its mirrors, and when it has the half-turn about c every line through c (skew lines).
"""

from __future__ import annotations

from fractions import Fraction
from math import isqrt

from .groups import verify_certificate
from .numbers import frac, need
from .refutations import not_orderable


def _keys(config) -> list:
    """(r2, turn mod 1) of each point: a rational polar configuration."""
    need(config["coordinates"] == "polar" and config.get("field") is None,
         "this refutation is checked on rational polar certificates only")
    return [(frac(r), frac(t) % 1 if frac(r) else Fraction(0)) for r, t in config["points"]]


def _levels(keys) -> dict:
    out: dict = {}
    for r2, t in keys:
        if r2:
            out.setdefault(r2, set()).add((r2, t))
    return out


def _part(cert, expected: set, what: str) -> tuple:
    """Verify a part's group certificate and that its points are ``expected``; returns
    (group name, number of rotations k, mirror axes as turns mod 1/2)."""
    ok, why = verify_certificate(cert)
    need(ok, f"{what}: the certificate is invalid: {why}")
    keys = _keys(cert["configuration"])
    need(set(keys) == expected and len(keys) == len(expected),
         f"{what}: its points are not the ones the checker computes from P")
    name = cert["claim"]["group"]
    need(name != "O2", f"{what}: one point")
    k = int(name[1:])
    axes = set()
    if name.startswith("D"):                   # reflections t -> 2a - t + j/k: axes a + j/2k
        a = frac(cert["witness"]["mirror"]["turn"])
        axes = {(a + Fraction(j, 2 * k)) % Fraction(1, 2) for j in range(k)}
    return name, k, axes


def _no_line(name: str, k: int) -> bool:
    """The polygon has no line of symmetry: no mirror and no half-turn (k odd)."""
    return name.startswith("C") and k % 2 == 1


def _level_part(obj, levels, what="level") -> tuple:
    r2 = frac(obj["parts"][what]["configuration"]["points"][0][0])
    need(r2 in levels and len(levels[r2]) >= 3, f"{what}: not a level of P with >= 3 points")
    return levels[r2], _part(obj["parts"][what], levels[r2], what)


def _asymmetric_pair(obj, levels) -> tuple:
    """The two levels of ``parts.pair`` form an asymmetric pair under every reading: no
    half-turn in either (no skew line) and no common mirror.  Returns their point sets."""
    pair = obj["parts"]["pair"]
    need(isinstance(pair, list) and len(pair) == 2, "parts.pair: two certificates")
    sets, axes = [], []
    for i, cert in enumerate(pair):
        level, (name, k, ax) = _level_part({"parts": {"pair": cert}}, levels, "pair")
        need(k % 2 == 1, f"pair {i}: group {name} has the half-turn: every line through c "
             "is a skew line of it")
        sets.append(level)
        axes.append(ax)
    need(sets[0] != sets[1], "the pair names one level twice")
    need(not axes[0] & axes[1], "the pair has a common mirror: it is symmetric")
    return sets[0], sets[1]


def _points(obj) -> set:
    return set(_keys(obj["certificate"]["configuration"]))


def asymmetric_level(obj, name: str, k: int, n: int, orderable: bool) -> str:
    """cor-Pasym-Pord, lem-one-pair-asym-ord: a level of P (parts.level) has no mirror and no
    half-turn -- an asymmetric polygon, so no line is common to every polygon and G_P is in
    O_A -- and P is not orderable."""
    _, (lname, lk, _) = _level_part(obj, _levels(_points(obj)))
    need(_no_line(lname, lk), f"the premise fails: the level has group {lname}, it is "
         "symmetric")
    return not_orderable(f"a level of P has group {lname} (no mirror, no half-turn): an "
                         "asymmetric polygon, so no line is common to every polygon and G_P "
                         "is in O_A", name, k, orderable)


def asymmetric_pair(obj, name: str, k: int, n: int, orderable: bool) -> str:
    """lem-asym-pair-ord (P is the pair), lem-all-pair-asym-ord: two levels of P form an
    asymmetric pair (no half-turn, no common mirror), and P is not orderable."""
    P = _points(obj)
    a, b = _asymmetric_pair(obj, _levels(P))
    if obj["label"] == "lem-asym-pair-ord":
        need(a | b == P, "the premise fails: P is not the union of the pair")
    return not_orderable("two levels of P form an asymmetric pair (no half-turn, no common "
                         "mirror)", name, k, orderable)


def sym_regular(obj, name: str, k: int, n: int, orderable: bool) -> str:
    """lemma-sym-regular: one polygon (points on one circle: convex) whose k > 1 lines of
    symmetry are all mirrors (k odd) through vertices, yet its rotations have order k < n."""
    P = _points(obj)
    need(len(_levels(P)) == 1 and len(P) == n >= 3, "the premise fails: not one polygon "
         "with >= 3 vertices (points on one circle: a convex polygon)")
    axes = _part(obj["certificate"], P, "P")[2]
    need(name.startswith("D") and k >= 2 and k % 2 == 1, f"the premise fails: group "
         f"{name} does not have more than one line of symmetry, all mirrors (k odd)")
    turns = {t for _, t in P}
    need(all(any((t - x) % Fraction(1, 2) == 0 for t in turns) for x in axes),
         "the premise fails: a mirror passes through no vertex")
    need(k < n, f"the conclusion holds: the rotation of order {k} = n makes it regular")
    return (f"one polygon of {n} vertices with group {name}: {k} mirrors, each through a "
            f"vertex, yet its rotations have order {k} < {n}")


def no_type(obj, name: str, k: int, n: int, orderable: bool) -> str:
    """obs-exh-poly: P is one straight symmetric polygon (group Dk, k mirrors) that fits
    none of the types, each decided from n, k and the mirrors through vertices: 0 regular
    (k = n); 1 n even, k = 2, no mirror through a vertex; 2 n even, k = 1 (one mirror of an
    even polygon fixes 0 or 2 vertices: it passes through two vertices or two edges); 3 n
    odd, k = 1 (it fixes one vertex: a vertex and an edge); 4 n odd and not prime, 1 < k < n."""
    P = _points(obj)
    axes = _part(obj["certificate"], P, "P")[2]
    need(len(_levels(P)) == 1 and n >= 3, "the premise fails: not one polygon with >= 3 "
         "vertices")
    need(name.startswith("D"), f"the premise fails: group {name} has no mirror")
    through = {x for x in axes if any((t - x) % Fraction(1, 2) == 0 for _, t in P)}
    prime = n > 1 and all(n % d for d in range(2, isqrt(n) + 1))
    types = {0: k == n, 1: n % 2 == 0 and k == 2 and not through,
             2: n % 2 == 0 and k == 1, 3: n % 2 == 1 and k == 1,
             4: n % 2 == 1 and not prime and 1 < k < n}
    fits = [t for t, holds in types.items() if holds]
    need(not fits, f"the conclusion holds: it is of type {fits[0] if fits else ''}")
    return (f"one polygon of {n} vertices with group {name}: {k} mirrors "
            f"({len(through)} through a vertex), not regular, fits none of the types 0-4")


def merged_pair(obj, name: str, k: int, n: int, orderable: bool) -> str:
    """obs-merg-asym-pair: the pair is asymmetric, and G_ij -- G_i projected radially onto
    G_j's circle, with G_j (the checker builds it) -- has a mirror or the half-turn."""
    a, b = _asymmetric_pair(obj, _levels(_points(obj)))
    rj = next(iter(b))[0]
    merged = {(rj, t) for _, t in a} | b
    need(len(merged) == len(a) + len(b), "G_i projected onto G_j meets a vertex of G_j")
    mname, mk, _ = _part(obj["parts"]["merged"], merged, "merged")
    need(not _no_line(mname, mk), f"the conclusion holds: G_ij has group {mname}")
    return (f"an asymmetric pair whose merged polygon G_ij has group {mname}: it is "
            "symmetric")
