"""The checker of refutation certificates (standard library only; see exactsym.checker).

A refutation certificate (docs/certificates.md, "Refutations") wraps a group certificate: once
that proves G (the group of P) and its orderability, the premise "P is in O_A" and the
conclusion "P is orderable" are facts about G, derived here and nowhere else.
"""

from __future__ import annotations

from fractions import Fraction
from math import isqrt

from .groups import verify_certificate
from .numbers import Invalid, frac, is_int, need

REFUTABLE = {"Pasym-Pord": "P is orderable if P is in O_A",
             "lem-asym-ord": "an asymmetric polygon is orderable",
             "cor-Pasym-Pord": "P is orderable if G_P is in O_A",
             "lem-one-pair-asym-ord": "if G_P contains an asymmetric polygon, P is orderable",
             "lem-asym-pair-ord": "an asymmetric pair is orderable",
             "lem-all-pair-asym-ord": "if G_P has an asymmetric pair, P is orderable",
             "obs-merg-asym-pair": "if <G_i, G_j> is an asymmetric pair, G_ij is asymmetric",
             "lemma-sym-regular": "a convex polygon with more than one line of symmetry, "
                                  "each through a vertex, is regular",
             "obs-exh-poly": "every straight symmetric polygon is of type 0, 1, 2, 3 or 4"}


def _one_level(config) -> bool:
    """All points at one distance from c (rational coordinates only)."""
    pts = config["points"]
    need(all(isinstance(v, (str, int)) for p in pts for v in p),
         "one level: only rational coordinates are supported")
    if config["coordinates"] == "polar":
        return len({frac(p[0]) for p in pts}) == 1
    xs, ys = [frac(p[0]) for p in pts], [frac(p[1]) for p in pts]
    cx, cy = sum(xs) / len(xs), sum(ys) / len(ys)
    return len({(x - cx) ** 2 + (y - cy) ** 2 for x, y in zip(xs, ys)}) == 1


# The other refutations speak of the polygons of G_P: the levels of P about the centre c of
# its SEC.  They are checked on rational polar certificates only, where c is the origin
# (verified by the group certificate) and a level is the set of points with one r2.  A
# part -- a level, a pair of levels, the merged polygon G_ij -- comes with a group
# certificate of its own, whose points must be exactly those the checker computes from P.
# Lines of symmetry of a polygon with >= 3 vertices on a circle about c (none of the
# readings of "common line" differ there: no line holds every vertex, no single vertex):
# its mirrors, and when it has the half-turn about c every line through c (skew lines).

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


def _premise(label, obj, P: set, name: str, k: int, n: int) -> str:
    """Check the premise of ``label`` on P (its group ``name`` is proved); returns it in
    words.  The shared conclusion, except for obs-merg-asym-pair, is "P is orderable"."""
    levels = _levels(P)
    if label in ("cor-Pasym-Pord", "lem-one-pair-asym-ord"):
        _, (lname, lk, _) = _level_part(obj, levels)
        need(_no_line(lname, lk), f"the premise fails: the level has group {lname}, it is "
             "symmetric")
        return (f"a level of P has group {lname} (no mirror, no half-turn): an asymmetric "
                "polygon, so no line is common to every polygon and G_P is in O_A")
    if label in ("lem-asym-pair-ord", "lem-all-pair-asym-ord"):
        a, b = _asymmetric_pair(obj, levels)
        if label == "lem-asym-pair-ord":
            need(a | b == P, "the premise fails: P is not the union of the pair")
        return "two levels of P form an asymmetric pair (no half-turn, no common mirror)"
    if label == "lemma-sym-regular":
        need(len(levels) == 1 and len(P) == n >= 3, "the premise fails: not one polygon "
             "with >= 3 vertices (points on one circle: a convex polygon)")
        axes = _part(obj["certificate"], P, "P")[2]
        need(name.startswith("D") and k >= 2 and k % 2 == 1, f"the premise fails: group "
             f"{name} does not have more than one line of symmetry, all mirrors (k odd)")
        turns = {t for _, t in P}
        need(all(any((t - x) % Fraction(1, 2) == 0 for t in turns) for x in axes),
             "the premise fails: a mirror passes through no vertex")
        return f"one polygon of {n} vertices with group {name}: {k} mirrors, each through a vertex"
    raise Invalid(f"no refutation by symmetry facts for {label!r}")


def _no_type(P: set, name: str, k: int, n: int, axes: set) -> str:
    """obs-exh-poly: P is one straight symmetric polygon (group Dk, k mirrors) that fits
    none of the types, each decided from n, k and the mirrors through vertices: 0 regular
    (k = n); 1 n even, k = 2, no mirror through a vertex; 2 n even, k = 1 (one mirror of an
    even polygon fixes 0 or 2 vertices: it passes through two vertices or two edges); 3 n
    odd, k = 1 (it fixes one vertex: a vertex and an edge); 4 n odd and not prime, 1 < k < n."""
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


def _merged_asymmetric(obj, P: set) -> str:
    """obs-merg-asym-pair: the pair is asymmetric, and G_ij -- G_i projected radially onto
    G_j's circle, with G_j (the checker builds it) -- has a mirror or the half-turn."""
    a, b = _asymmetric_pair(obj, _levels(P))
    rj = next(iter(b))[0]
    merged = {(rj, t) for _, t in a} | b
    need(len(merged) == len(a) + len(b), "G_i projected onto G_j meets a vertex of G_j")
    name, k, _ = _part(obj["parts"]["merged"], merged, "merged")
    need(not _no_line(name, k), f"the conclusion holds: G_ij has group {name}")
    return (f"an asymmetric pair whose merged polygon G_ij has group {name}: it is "
            "symmetric")


def verify_refutation(obj) -> tuple[bool, str]:
    """``(True, summary)`` when the refutation certificate shows a configuration meeting the
    premise of ``obj["label"]`` whose conclusion is false, all derived from the groups its
    embedded certificates prove (docs/certificates.md, "Refutations"): for Pasym-Pord and
    lem-asym-ord P in O_A (at least two points, no mirror that moves a point, no half-turn;
    for lem-asym-ord also one level) and P not orderable; for the others the premise
    about the polygons of G_P in :func:`_premise` and P not orderable, or, for
    obs-merg-asym-pair, an asymmetric pair whose merged polygon is symmetric."""
    try:
        need(isinstance(obj, dict) and obj.get("format") == "exactsym-refutation"
             and is_int(obj.get("version")) and obj["version"] == 1,
             "not an exactsym refutation of version 1")
        label = obj.get("label")
        need(label in REFUTABLE, f"no refutation by symmetry facts for {label!r}")
        need(obj.get("statement") == REFUTABLE[label], "the statement is not the label's")
        cert = obj["certificate"]
        ok, why = verify_certificate(cert)
        need(ok, f"the embedded certificate is invalid: {why}")
        name, orderable = cert["claim"]["group"], cert["claim"]["orderable"]
        n = len(cert["configuration"]["points"])
        k = 1 if name == "O2" else int(name[1:])
        if label == "obs-merg-asym-pair":
            return True, f"{label} refuted: " + _merged_asymmetric(
                obj, set(_keys(cert["configuration"])))
        if label == "obs-exh-poly":
            P = set(_keys(cert["configuration"]))
            return True, f"{label} refuted: " + _no_type(P, name, k, n,
                                                         _part(cert, P, "P")[2])
        if label in ("Pasym-Pord", "lem-asym-ord"):
            # A reflection in G moves a point unless G = D1 fixes every point (orderable); a
            # half-turn is in G iff k is even.
            no_moving_mirror = name.startswith("C") or (name == "D1" and orderable)
            need(n >= 2 and no_moving_mirror and k % 2 == 1,
                 f"the premise fails: group {name} on {n} point(s) is in O_S")
            if label == "lem-asym-ord":
                need(_one_level(cert["configuration"]), "the premise fails: not one polygon")
            premise = "group {name} has no mirror moving a point and no half-turn".format(
                name=name)
        else:
            premise = _premise(label, obj, set(_keys(cert["configuration"])), name, k, n)
        if label == "lemma-sym-regular":
            need(k < n, f"the conclusion holds: the rotation of order {k} = n makes it "
                 "regular")
            return True, f"{label} refuted: {premise}, yet its rotations have order {k} < {n}"
        need(orderable is False, f"the conclusion holds: group {name} is orderable")
        mover = f"its rotation of order {k}" if k > 1 else "its mirror"
        return True, (f"{label} refuted: {premise}, yet P (group {name}) is not "
                      f"orderable: {mover} moves a point")
    except Invalid as err:
        return False, str(err)
    except (KeyError, TypeError, ValueError, IndexError, AttributeError) as err:
        return False, f"malformed refutation ({type(err).__name__}: {err})"
