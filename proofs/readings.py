"""The paper's Section-3 notions under named readings, for polar configurations with
rational turns: an independent witness checker for the ledger (standard library only;
it shares no code with exactsym, so a witness it confirms is confirmed twice).

A configuration is a list of points ``(r, turn)`` about the centre C = origin, ``r`` and
``turn`` rationals (``Fraction``); a polygon is the set of turns of one level.  A line
through C is named by ``s`` in [0, 1): the reflection in it maps turn x to ``s - x``
(the line itself is at turn s/2 modulo 1/2).

Readings (docs/interpretations.md, "The ledger's re-grading"):

* ``pair``: ``"mixed"`` -- a common line of symmetry is a line of symmetry (straight or
  skew) of each polygon, of either kind (the reading lem-3-pair-sym's proof needs); or
  ``"same-kind"`` -- straight for both, or skew for both.
* ``containing``: ``False`` (literal, ``def-straight-symmetric-conf``: a line containing
  all points of a polygon is not a line of straight symmetry of it) or ``True``.
* ``singleton``: the line through C and a single vertex (the note after
  ``def-asymmetric-poly``) is of kind ``"both"`` (the point is its own straight and
  skewed mirror image) or ``"straight"`` only.

Skew symmetry of a polygon is the half-turn about C (``skmirrorimage`` with m = C), so a
skew symmetric polygon has every line through C as a line of skew symmetry
(``lem-skew-los``).
"""

from __future__ import annotations

from fractions import Fraction as Q
from itertools import product

ALL = "all"          # every line through C

READINGS = tuple(
    {"pair": p, "containing": c, "singleton": s}
    for p, c, s in product(("mixed", "same-kind"), (False, True), ("both", "straight")))


def frac(x) -> Q:
    return x if isinstance(x, Q) else Q(x)


def norm(x: Q) -> Q:
    return x - (x.numerator // x.denominator)


# ---------------------------------------------------------------- one polygon
def mirrors(turns) -> set:
    """Every s such that x -> s - x maps the set of turns onto itself."""
    ts = {norm(frac(t)) for t in turns}
    if not ts:
        return set()
    x0 = min(ts)
    return {s for s in {norm(x0 + x) for x in ts} if {norm(s - x) for x in ts} == ts}


def on_line(s: Q, x: Q) -> bool:
    """Turn x lies on the line s (x = s/2 or s/2 + 1/2)."""
    return norm(2 * x - s) == 0


def centrally_symmetric(turns) -> bool:
    ts = {norm(frac(t)) for t in turns}
    return len(ts) > 1 and {norm(x + Q(1, 2)) for x in ts} == ts


def straight_lines(turns, reading: dict) -> set:
    ts = {norm(frac(t)) for t in turns}
    if len(ts) == 1:
        (x,) = ts
        return {norm(2 * x)}
    out = set()
    for s in mirrors(ts):
        if reading["containing"] or not all(on_line(s, x) for x in ts):
            out.add(s)
    return out


def skew_lines(turns, reading: dict):
    ts = {norm(frac(t)) for t in turns}
    if len(ts) == 1:
        (x,) = ts
        return {norm(2 * x)} if reading["singleton"] == "both" else set()
    return ALL if centrally_symmetric(ts) else set()


def _meet(a, b):
    if a == ALL:
        return b
    if b == ALL:
        return a
    return a & b


def _join(a, b):
    if a == ALL or b == ALL:
        return ALL
    return a | b


def _nonempty(a) -> bool:
    return a == ALL or bool(a)


def family_symmetric(polygons, reading: dict) -> bool:
    """``def-sym-calG`` (and ``def-sym-pair`` for two polygons): a common line."""
    if reading["pair"] == "mixed":
        common = ALL
        for p in polygons:
            common = _meet(common, _join(straight_lines(p, reading), skew_lines(p, reading)))
        return _nonempty(common)
    st, sk = ALL, ALL
    for p in polygons:
        st = _meet(st, straight_lines(p, reading))
        sk = _meet(sk, skew_lines(p, reading))
    return _nonempty(st) or _nonempty(sk)


def is_regular(turns) -> bool:
    ts = sorted({norm(frac(t)) for t in turns})
    gaps = {norm(b - a) for a, b in zip(ts, ts[1:] + [ts[0] + 1])}
    return len(gaps) == 1


def _is_prime(n: int) -> bool:
    return n > 1 and all(n % d for d in range(2, int(n ** 0.5) + 1))


def polygon_type(turns) -> str | None:
    """The types 0-4 of Section 3 by their definitions, with the exact mirrors (lines of
    straight symmetry; literal reading: none contains every vertex).  None: no type."""
    ts = sorted({norm(frac(t)) for t in turns})
    n = len(ts)
    lines = straight_lines(ts, {"containing": False})
    symmetric = bool(lines) or centrally_symmetric(ts)
    if not symmetric:
        return None
    if is_regular(ts):
        return "type-0"
    through = {s: sum(on_line(s, x) for x in ts) for s in lines}
    if n % 2 == 0:
        if len(lines) == 2:
            a, b = sorted(lines)
            if norm(b - a) == Q(1, 2) and not any(through.values()):
                return "type-1"
        if len(lines) == 1:
            return "type-2"
        return None
    if len(lines) == 1:
        return "type-3"
    if not _is_prime(n) and 1 < len(lines) < n:
        return "type-4"
    return None


def project(inner, outer) -> set:
    """G_ij: the turns of both polygons, a vertex per ray (coincident rays merge)."""
    return {norm(frac(t)) for t in inner} | {norm(frac(t)) for t in outer}


# ---------------------------------------------------------------- configurations
def levels(points) -> list:
    """The polygons G_1, ..., G_t (nearest first) of points ``(r, turn)`` about C; a
    robot at C (r = 0) is a polygon of its own, recorded with turn None."""
    by_r: dict = {}
    for r, t in points:
        r = frac(r)
        by_r.setdefault(r, set()).add(None if r == 0 else norm(frac(t)))
    return [sorted(by_r[r], key=lambda x: (x is None, x)) for r in sorted(by_r)]


def symmetries(points) -> list:
    """Every isometry fixing C that maps the set onto itself, as ``(kind, q)``: rotation
    by q turns or the reflection x -> q - x; and whether each fixes every point."""
    pts = {(frac(r), None if frac(r) == 0 else norm(frac(t))) for r, t in points}
    ring = [p for p in pts if p[0] != 0]
    out = []
    if not ring:
        return [("rotation", Q(0), True)]
    r0, x0 = min(ring)
    for _, x in ring:
        if _ == r0:
            for kind, q in (("rotation", norm(x - x0)), ("reflection", norm(x + x0))):
                image = {(r, None if t is None else norm(t + q if kind == "rotation"
                                                         else q - t)) for r, t in pts}
                if image == pts:
                    fixes = all((r, None if t is None else norm(
                        t + q if kind == "rotation" else q - t)) == (r, t) for r, t in pts)
                    out.append((kind, q, fixes))
    return out


def orderable_about_centre(points) -> bool:
    """No isometry fixing C maps the set onto itself moving a point (C the SEC centre)."""
    return all(fixes for _, _, fixes in symmetries(points))


def in_O_S(points) -> bool:
    """``def-symmetric-conf`` about C: a singleton, a mirror not containing all points,
    or the half-turn about C (a line of symmetry passes through the SEC centre,
    ``lemma-LOS-Passes-CenterSECP``)."""
    pts = {(frac(r), None if frac(r) == 0 else norm(frac(t))) for r, t in points}
    if len(pts) == 1:
        return True
    for kind, q, fixes in symmetries(points):
        if kind == "reflection" and not fixes:
            return True
        if kind == "rotation" and q == Q(1, 2):
            return True
    return False


def sec_centre_is_origin(points) -> bool:
    """The outermost level is in no open half-plane through C (so C is the SEC centre)."""
    outer = levels(points)[-1]
    ts = sorted(outer)
    if None in ts or len(ts) < 2:
        return False
    gaps = [norm(b - a) for a, b in zip(ts, ts[1:])] + [norm(ts[0] - ts[-1]) or Q(1)]
    return max(gaps) <= Q(1, 2)


def points_of(spec) -> list:
    """``[(r, [turns...]), ...]`` -> points."""
    return [(frac(r), frac(t)) for r, turns in spec for t in turns]
