"""The witness of a group certificate: what the checker needs to prove the group.

Generators with their permutations, a reference point on the sparsest level, and, for each
candidate isometry outside the group, one point whose image is not a point of P
(``docs/certificates.md``); for the ordering, the frame of a least reading.  Found with the
project's exact numbers and certified balls (a ball only chooses which point to name: the
checker re-checks every claim exactly).
"""

from __future__ import annotations

import itertools

from flint import arb, ctx, fmpq

from ..exact.sparse_cyclotomic import SparseCyclotomic
from ..geometry.predicates import enclosure_of
from .encoder import CertificateError, rational_text

def _centroid(points):
    n = len(points)
    centre = (sum((p[0] for p in points), points[0][0] * 0) / n,
              sum((p[1] for p in points), points[0][1] * 0) / n)
    # in the sparse Q(zeta_N) a rational centroid is a sum of hundreds of cosines: held as
    # the rational, it leaves the vectors p - centroid sums of two
    return tuple(c.reduced() if isinstance(c, SparseCyclotomic) else c for c in centre)


def _sparsest(distances: list, centre_value) -> int:
    """A point on the level (equal distance from the centre) with fewest points, off the centre."""
    groups: dict = {}
    for i, d in enumerate(distances):
        if d != centre_value:
            groups.setdefault(d, []).append(i)
    return min(groups.values(), key=len)[0]


def _levels_by_balls(norm_balls: list, exact_norm) -> list[list[int]]:
    """The levels (points at one distance from the centre, the centre itself left out), in
    the order of their first point, as :func:`_sparsest` groups them: balls whose
    intervals meet no other ball are levels of one point (and, excluding 0, off the
    centre); only the points of a cluster of overlapping balls are compared exactly, by
    ``exact_norm(i)`` (a squared distance; 0 at the centre).  In a tower over the sparse
    Q(zeta_N) the centroid is a sum of hundreds of cosines on every level, and one exact
    squared distance costs seconds."""
    order = sorted(range(len(norm_balls)), key=lambda i: norm_balls[i].lower())
    clusters, top = [], None
    for i in order:                             # a sweep over the intervals by lower end
        ball = norm_balls[i]
        if clusters and not ball.lower() > top:
            clusters[-1].append(i)
            top = max(top, ball.upper())
        else:
            clusters.append([i])
            top = ball.upper()
    groups = []
    for cluster in clusters:
        if len(cluster) == 1 and not norm_balls[cluster[0]].contains(0):
            groups.append(cluster)
            continue
        zero, by_norm = None, {}
        for i in sorted(cluster):
            d = exact_norm(i)
            if zero is None:
                zero = d * 0
            if d != zero:
                by_norm.setdefault(d, []).append(i)
        groups += by_norm.values()
    return sorted(groups, key=lambda g: g[0])


def _orbits(ref: int, rot, mir) -> tuple[set, set]:
    """The images of ``ref`` under the rotations and under the reflections of the group."""
    orbit, j = [ref], (rot[ref] if rot else ref)
    while j != ref:
        orbit.append(j)
        j = rot[j]
    return set(orbit), ({mir[i] for i in orbit} if mir else set())


def _refutations(n, ref, level, rot, mir, image, surely_out=None) -> dict:
    """For each candidate outside the group, one point whose image is not a point of P.
    ``image(kind, b)`` returns a function mapping a point index to "is its image in P";
    ``surely_out(kind, b)``, when given, one telling from balls that an image is no point
    of P (certified enclosures apart from every point's: the witness is found without
    exact products; the checker re-checks it exactly), else None (then ``image`` says)."""
    in_rot, in_ref = _orbits(ref, rot, mir)
    out = {"rotation": [], "reflection": []}
    for kind, inside in (("rotation", in_rot), ("reflection", in_ref)):
        for b in level:
            if b in inside:
                continue
            maps_in = image(kind, b)
            apart = surely_out(kind, b) if surely_out is not None else None
            # the image of ref is b, a point of P; a point whose image the balls put apart
            # from every point first (in a C7 set a reflection maps whole orbits onto
            # points: the exact images of those, before one of another orbit, made the
            # certificate of 98 robots in a sparse Q(zeta_N) take 55 s)
            others = [w for w in itertools.chain(level, range(n)) if w != ref]
            found = next((w for w in others if apart(w)), None) if apart is not None \
                else None
            if found is None:
                found = next((w for w in others if not maps_in(w)), None)
            if found is None:
                raise CertificateError(f"the {kind} taking point {ref} to point {b} is a "
                                       "symmetry missing from the group (bug)")
            out[kind].append([b, found])
    return out


def cartesian_witness(config, group, enc):
    pts = list(config.points)
    n = len(pts)
    cx, cy = _centroid(pts)
    rel = [(x - cx, y - cy) for x, y in pts]
    # balls of the points and of the vectors from the centroid: the levels and a
    # candidate's image of a point that is no point of P are found without exact products
    # (in a sparse Q(zeta_N) the centroid is a sum of hundreds of cosines, and an exact
    # squared distance or image costs seconds)
    with ctx.workprec(_REFUTE_PREC):
        point_balls = [(_ball(x), _ball(y)) for x, y in pts]
        rel_balls = [(_ball(x), _ball(y)) for x, y in rel]
        centre_ball = (_ball(cx), _ball(cy))
        norm_balls = [x * x + y * y for x, y in rel_balls]
    if not all(b.is_finite() for b in norm_balls):
        norm_balls = [arb(0, "inf")] * n         # no balls: every point compared exactly
    levels = _levels_by_balls(norm_balls, lambda i: rel[i][0] ** 2 + rel[i][1] ** 2)
    level = min(levels, key=len)
    ref = level[0]
    ux, uy = rel[ref]
    where = {p: i for i, p in enumerate(pts)}
    inverse: list = []                          # [1 / s], when an exact image is first asked

    def image(kind, b):
        # the exact matrix only when balls cannot tell (in a tower over the sparse base its
        # products cost a second each)
        matrix: list = []

        def maps_in(w):
            if not matrix:
                if not inverse:
                    inverse.append(1 / (ux * ux + uy * uy))
                inv, (vx, vy) = inverse[0], rel[b]
                if kind == "rotation":
                    dot, cross = (ux * vx + uy * vy) * inv, (ux * vy - uy * vx) * inv
                    matrix.append(((dot, -cross), (cross, dot)))
                else:
                    c, s2 = (ux * vx - uy * vy) * inv, (ux * vy + uy * vx) * inv
                    matrix.append(((c, s2), (s2, -c)))
            m = matrix[0]
            return (cx + m[0][0] * rel[w][0] + m[0][1] * rel[w][1],
                    cy + m[1][0] * rel[w][0] + m[1][1] * rel[w][1]) in where
        return maps_in

    def isometry(iso):
        if iso is None:
            return None
        if enc.sparse is not None:
            return {"centre": [enc.text(cx), enc.text(cy)], **enc.sparse_matrix(iso.matrix),
                    "permutation": list(iso.permutation)}
        return {"centre": [enc.text(cx), enc.text(cy)],
                "matrix": [[enc.text(e) for e in row] for row in iso.matrix],
                "permutation": list(iso.permutation)}

    def surely_out(kind, b):
        with ctx.workprec(_REFUTE_PREC):
            (ax, ay), (bx, by) = rel_balls[ref], rel_balls[b]
            norm = ax * ax + ay * ay
            if kind == "rotation":
                dot, cross = (ax * bx + ay * by) / norm, (ax * by - ay * bx) / norm
                m = ((dot, -cross), (cross, dot))
            else:
                c, s2 = (ax * bx - ay * by) / norm, (ax * by + ay * bx) / norm
                m = ((c, s2), (s2, -c))

        def apart(w):
            with ctx.workprec(_REFUTE_PREC):
                wx, wy = rel_balls[w]
                ix = centre_ball[0] + m[0][0] * wx + m[0][1] * wy
                iy = centre_ball[1] + m[1][0] * wx + m[1][1] * wy
                return ix.is_finite() and iy.is_finite() and \
                    not any(ix.overlaps(px) and iy.overlaps(py) for px, py in point_balls)
        return apart

    rot = group.rotation_generator.permutation if group.rotation_generator else None
    mir = group.mirror.permutation if group.mirror else None
    return {"reference": ref, "rotation": isometry(group.rotation_generator),
            "mirror": isometry(group.mirror),
            "refutations": _refutations(n, ref, level, rot, mir, image, surely_out)}


#: precision of the balls that find a refuting point (only a filter: see _refutations)
_REFUTE_PREC = 128


def _ball(x):
    return enclosure_of(x, _REFUTE_PREC)


def polar_witness(config, group):
    polar = config.polar
    n = len(polar)
    keys = [(r2, t if r2 != 0 else fmpq(0)) for r2, t in polar]
    where = {k: i for i, k in enumerate(keys)}
    ref = _sparsest([r2 for r2, _ in polar], 0)
    ra, ta = polar[ref]
    level = [i for i, (r2, _) in enumerate(polar) if r2 == ra]

    def key(r2, t):
        return (r2, fmpq(0)) if r2 == 0 else (r2, t - (t.p // t.q))

    def image(kind, b):
        tb = polar[b][1]
        if kind == "rotation":
            return lambda w: key(polar[w][0], polar[w][1] + tb - ta) in where
        return lambda w: key(polar[w][0], ta + tb - polar[w][1]) in where

    def isometry(iso):
        if iso is None:
            return None
        return {"turn": rational_text(iso.turn), "permutation": list(iso.permutation)}

    rot = group.rotation_generator.permutation if group.rotation_generator else None
    mir = group.mirror.permutation if group.mirror else None
    return {"reference": ref, "rotation": isometry(group.rotation_generator),
            "mirror": isometry(group.mirror),
            "refutations": _refutations(n, ref, level, rot, mir, image)}


def canonical_frame(config, group, polar: bool) -> dict | None:
    """witness.canonical: the frame ("ccw" or "cw") of a least reading -- read off the
    ordering: the frame in which its rays follow the counter-clockwise rays of the group's
    layout -- and, for D1 with no ordering and no point at the centre, the points sorted
    counter-clockwise (the leader is on the mirror)."""
    layout = getattr(group, "_layout", None)     # None: one point, or a hand-made group
    if layout is None:
        return None
    rays = [list(r) for r in layout.rays]
    if not group.orderable:
        if group.name != "D1" or layout.centre_index is not None:
            return None
        return {"orientation": "ccw", "order": [i for r in rays for i in r]}
    m = len(rays)
    order = [i for i in group.ordering if i != layout.centre_index]
    first = next(j for j, r in enumerate(rays) if r[0] == order[0])
    if m >= 3:
        nxt = order[len(rays[first])]
        return {"orientation": "ccw" if rays[(first + 1) % m][0] == nxt else "cw"}
    if m == 1:
        return {"orientation": "ccw"}
    # two rays: the ccw reading from R_first is least iff the angle to the other ray is the
    # smaller one (below half a turn)
    a, b = rays[first][0], rays[1 - first][0]
    if polar:
        turn = config.polar[b][1] - config.polar[a][1]     # an fmpq: no %, its floor
        below = turn - turn.floor() <= fmpq(1, 2)
    else:
        (cx, cy), (ax, ay), (bx, by) = group.centre, config.points[a], config.points[b]
        below = (ax - cx) * (by - cy) - (ay - cy) * (bx - cx) >= 0
    return {"orientation": "ccw" if below else "cw"}
