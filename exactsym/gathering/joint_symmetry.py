"""The ``symmetry`` family of a joint step: where a symmetry of the robots can appear while
several robots move at once (spec section 4, "a symmetry appears").

In a step (``World.advance_together``) the movers ``M`` are at ``piece.at(tau)`` at the
common time ``tau`` (:func:`.motion.motion_of`), the other robots stand still.  Let
``X`` be a set of robots whose symmetry the algorithm reads (every robot; R, the robots
outside the pattern, which the paper layer orders about R's own SEC centre), ``S`` its
robots standing still, ``M_X`` its movers.  A symmetry ``s`` of X at time ``tau`` (a
rotation or a reflection that maps X onto itself) permutes X and fixes the centre of
X's SEC and X's centroid.  Either

* **A** -- ``s`` maps ``M_X`` onto itself: then it maps ``S`` onto itself, so it is a
  symmetry of S, fixing S's centroid ``z_S``:

  - a reflection in a mirror line ``l`` of S (finitely many, exact:
    :func:`.instants.mirror_lines`): one chosen mover ``m`` is on ``l``, or is the mirror
    image in ``l`` of another mover ``j`` (two polynomials, their gcd: ``(p_j - p_m).u``
    and ``cross(p_j + p_m - 2 z_S, u)``);
  - a rotation about ``z_S`` that maps S onto itself (finitely many, exact): ``m`` is
    at ``z_S``, or another mover is its image (the gcd of the two components);

* **B** -- ``s`` maps some mover ``i`` to a robot ``q`` standing still: then ``i`` and
  ``q`` are as far from every fixed point of ``s``.  When no mover of X leaves the SEC of
  S during the step, the SEC of X is S's (a constant centre ``c_S``): a tie about
  ``c_S``; when ``c_S`` is a centre whose ties the step already enumerates (C, or R's
  SEC centre: the ``distance`` family, whose roots :mod:`.joint_instants` tags
  ``symmetry`` too) nothing new, else those ties.  When a mover may leave it, the SEC
  centre moves, and when ``i`` keeps ``q``'s distance from ``c_S`` all the time (an arc
  about it: the tie says nothing): a tie about X's centroid, which moves too
  (``z_X = (sum S + sum p_m(tau)) / |X|``).

So each family below is a **necessary condition only** (a superset of the instants where
a symmetry appears: a candidate where nothing happens costs a Look); for case A only one
mover's relations are listed (every mover must satisfy one), the first mover none of
whose relations holds all the time (the case-A relations are exact for the given line
or rotation: if every mover keeps one all the time, they pair the movers, and that
symmetry holds over the whole step: it appears at no instant).  Degrees: with ``W`` the
product of the movers' denominators (1 on segments, ``1 + T^2 tau^2`` on an arc), a
mirror or rotation relation has degree at most 4, a tie about ``c_S`` at most 4, a tie
about the moving centroid at most ``2 + 2 deg W`` (2 on segments; 4 per mover on an arc).

A set X with fewer than two robots standing still (its symmetries are tied to no fixed
line), and in case B a mover ``i`` that keeps a still robot ``q``'s distance from both
the SEC centre and the moving centroid all the time (both ties vanish identically), get
the **hypotheses on images** instead (:func:`image_polys`): a symmetry permutes X and
preserves distances, so with ``s(i) = q`` assumed (or, with no hypothesis, for X's first
robot and each possible image), each other robot ``c`` goes to some ``d`` with
``|c - z| = |d - z|`` and ``|c - i| = |d - q|``: polynomials in tau; where all of them
vanish for some ``d`` that pair is assumed too, until every robot is mapped (then the
map preserves every distance all along: a symmetry all along, appearing at no instant).
"""

from __future__ import annotations

from ..exact.algebraic.polynomials import padd, pgcd, pmul, pscale, psub
from ..exact.multiquadratic import MQ
from . import geometry as g
from .motion import Motion, dist2_poly, may_leave
from .point_sets import centroid, mirror_lines, smallest_distance_group
from .joint_relations import (centroid_motion, collinear_poly, const, crossv, diff, dotv,
                              pair_tie, rel, tie_about, tie_poly)


def mirror_pair_poly(a: Motion, b: Motion, z, u) -> tuple:
    """Zero where ``p_b`` is the mirror image of ``p_a`` in the line through ``z`` along
    ``u``: the gcd of ``D_a D_b (p_b - p_a).u`` (same foot on the line) and ``D_a D_b
    cross(p_a + p_b - 2 z, u)`` (midpoint on the line); ``()`` when both vanish all the
    time (mirror images all along), ``(1,)``-like constants when never."""
    along = dotv(diff(b, a), u)
    s = (padd(pmul(a.nx, b.d), pmul(b.nx, a.d)), padd(pmul(a.ny, b.d), pmul(b.ny, a.d)))
    dd2 = pscale(pmul(a.d, b.d), MQ.rational(2))
    mid = (psub(s[0], pscale(dd2, z[0])), psub(s[1], pscale(dd2, z[1])))
    across = crossv(mid, u)
    if not along:
        return across
    if not across:
        return along
    return pgcd(along, across)


def centroid_tie(motions: dict, members, movers, i: int, q: int) -> tuple:
    """Zero where mover ``i`` and robot ``q`` are as far from the centroid of
    ``members`` (which moves with the movers): ``(p_i - q) . (p_i + q - 2 z)`` times
    ``D_i W |X|`` with ``W`` the product of the movers' denominators."""
    n = MQ.rational(len(members))
    mov = sorted(movers)

    def others_d(m):                    # W / D_m
        out: tuple = (MQ.rational(1),)
        for k in mov:
            if k != m:
                out = pmul(out, motions[k].d)
        return out

    W = pmul(others_d(mov[0]), motions[mov[0]].d)
    # n W z = W sum(still) + sum_m N_m W / D_m
    zx, zy = (), ()
    for k in members:
        if k in movers:
            od = others_d(k)
            zx, zy = padd(zx, pmul(motions[k].nx, od)), padd(zy, pmul(motions[k].ny, od))
        else:
            x, y = const(motions[k])
            zx, zy = padd(zx, pscale(W, x)), padd(zy, pscale(W, y))
    a, b = motions[i], motions[q]
    first = diff(a, b)                              # D_i (p_i - q) (q still: D_q = 1)
    odi = others_d(i)
    # n W (p_i + q - 2 z) = n N_i W/D_i + n W q - 2 n W z
    sx = psub(padd(pscale(pmul(a.nx, odi), n), pscale(pmul(W, b.nx), n)), pscale(zx, 2))
    sy = psub(padd(pscale(pmul(a.ny, odi), n), pscale(pmul(W, b.ny), n)), pscale(zy, 2))
    return padd(pmul(first[0], sx), pmul(first[1], sy))


def rotations_of(pts: list, z) -> list:
    """``[(cos, sin)]``: every rotation about ``z`` other than the identity that maps
    ``pts`` onto itself (exact: the candidates take one robot of the smallest distance
    group to each other one of that group; each is tested on every point)."""
    group = smallest_distance_group(pts, z)
    if not group:
        return []
    y0 = g.sub(group[0], z)
    r2 = g.dot(y0, y0)
    have = set(pts)
    out = []
    for y in group[1:]:
        v = g.sub(y, z)
        c, s = g.dot(y0, v) / r2, g.cross(y0, v) / r2
        if all(g.add(z, g.rotate(g.sub(p, z), c, s)) in have for p in pts):
            out.append((c, s))
    return out


def rotation_pair_poly(a: Motion, b: Motion, z, rot) -> tuple:
    """Zero where ``p_b`` is the image of ``p_a`` under the rotation ``rot = (cos, sin)``
    about ``z``: the gcd of the two components of ``D_a D_b ((p_b - z) - rot(p_a - z))``;
    ``()`` when that holds all the time."""
    (ax, ay), (bx, by) = rel(a, z), rel(b, z)
    ax, ay, bx, by = pmul(ax, b.d), pmul(ay, b.d), pmul(bx, a.d), pmul(by, a.d)
    c, s = rot
    ex = psub(bx, psub(pscale(ax, c), pscale(ay, s)))
    ey = psub(by, padd(pscale(ax, s), pscale(ay, c)))
    if not ex:
        return ey
    if not ey:
        return ex
    return pgcd(ex, ey)


def symmetry_polys(motions: dict, movers: set, members, name: str,
                   known_centres=()) -> list:
    """``[(poly, ("symmetry", description))]``: the necessary conditions above for a
    symmetry of the robots ``members`` (indices into ``motions``) to hold at time tau;
    ``known_centres``: points whose ``distance`` ties over ``members`` the caller
    enumerates already (tagged ``symmetry`` by it)."""
    M = sorted(set(members) & set(movers))
    still_pts = {k: const(motions[k]) for k in members if k not in movers}
    if not M:
        return []
    if len(still_pts) < 2:
        # no fixed lines or rotations to start from: the hypotheses on images below
        return _distinct([(p, ("symmetry", f"{name}: {w}")) for p, w in
                          image_polys(motions, members, set(M), [])])
    S = list(still_pts.values())
    z = centroid(S)
    out: list = []

    def first_usable(rels):
        """The relations of the first mover none of whose relations holds all along."""
        for m in M:
            polys = rels(m)
            if all(p for p, _ in polys):
                return polys
        return []

    for u in mirror_lines(S, z):
        def rels(m, u=u):
            own = [(crossv(rel(motions[m], z), u),
                    f"{name}: robot {m} on a mirror line of the robots standing still")]
            return own + [(mirror_pair_poly(motions[m], motions[j], z, u),
                           f"{name}: robots {m} and {j} mirror images in a mirror line of "
                           f"the robots standing still") for j in M if j != m]
        out += [(p, ("symmetry", w)) for p, w in first_usable(rels) if len(p) > 1]
    for rot in rotations_of(S, z):
        def rels(m, rot=rot):
            return [(dist2_poly(motions[m], z, MQ()),
                     f"{name}: robot {m} at the centre of a rotation of the robots "
                     f"standing still")] + \
                [(rotation_pair_poly(motions[m], motions[j], z, rot),
                  f"{name}: robot {j} the image of robot {m} in a rotation of the robots "
                  f"standing still") for j in M if j != m]
        out += [(p, ("symmetry", w)) for p, w in first_usable(rels) if len(p) > 1]
    # B: a mover mapped to a robot standing still
    c_s, r2_s = g.smallest_enclosing_circle(S)
    inside = not any(may_leave(motions[i], c_s, r2_s) for i in M)
    swaps: list = []
    for i in M:
        for q in still_pts:
            tie = tie_poly(motions[i], motions[q], c_s) if inside else ()
            if tie and c_s in set(known_centres):
                continue                     # the caller's distance tie, tagged symmetry
            if tie:
                out.append((tie, ("symmetry", f"{name}: robots {i} and {q} as far from the "
                                              f"SEC centre of the robots standing still")))
            else:
                # the SEC moves, or robot i keeps q's distance from its centre all along
                # (an arc about it): the centroid is fixed by every symmetry too
                ct = centroid_tie(motions, list(members), set(M), i, q)
                if ct:
                    out.append((ct, ("symmetry", f"{name}: robots {i} and {q} as far from "
                                                 f"the centroid")))
                else:
                    # as far from both centres all along: what the images of the other
                    # robots need if s(i) = q (the joint analogue of instants'
                    # on_circle_candidates: its swap images are these ties' roots)
                    swaps += [(p, ("symmetry", f"{name}: if robot {i}'s image is robot "
                                               f"{q}, {w}"))
                              for p, w in image_polys(motions, members, set(M), [(i, q)])]
    return [(p, tag) for p, tag in out if len(p) > 1] + _distinct(swaps)


def _distinct(polys: list) -> list:
    """The non-constant polynomials, each once up to a constant factor (the first
    description kept): the hypotheses on images meet the same relation in many
    branches, and equal roots cost refinements before they merge."""
    seen, out = set(), []
    for p, tag in polys:
        if len(p) > 1:
            key = tuple(pscale(p, 1 / p[-1]))
            if key not in seen:
                seen.add(key)
                out.append((p, tag))
    return out


def image_polys(motions: dict, members, movers: set, hyp: list, _z=None) -> list:
    """``[(poly, description)]``: necessary conditions for a symmetry ``s`` (not the
    identity) of the robots ``members`` at time tau with ``s(x) = y`` for every pair of
    ``hyp``; needs no robot standing still.

    ``s`` is an isometry that permutes the robots and fixes their centroid ``z`` (which
    moves with the movers), so for a robot ``c`` with ``s(c) = d``: ``|c - z| = |d - z|``
    and ``|c - x| = |d - y|`` for every ``(x, y)`` of ``hyp``.  For one robot ``c`` (the
    first not yet mapped, robots standing still first) and every candidate image ``d``
    (not already an image) the first of these relations that does not vanish
    identically is listed (a nonzero constant: ``d`` is impossible); when all of them
    vanish for some ``d`` (``c -> d`` is consistent all along: ``d = c`` under the empty
    hypothesis, a swap whose ties vanish) that ``d`` is assumed in turn.  Two fixed
    robots ``x, y`` make ``s`` the reflection in the line ``xy`` (not the identity): then
    ``z`` is on it (one polynomial), and ``c`` fixed means ``c`` on it.  A hypothesis
    that maps every robot, each relation vanishing identically, preserves every
    distance all along (each robot's relations include its distance to every robot
    mapped before it): a symmetry all along, or the identity; it appears at no instant.
    So the list is a superset, with no depth bound, and the search stays small: once
    three assumed robots are not collinear, a robot's distances to them fix its image
    as a point, so a branch goes on with one image at most (two while they are
    collinear)."""
    members = sorted(members, key=lambda k: (k in movers, k))
    if len(members) < 3:
        return []              # two points are always symmetric (a half turn swaps them)
    mo = {k: motions[k] for k in members}
    z = _z if _z is not None else centroid_motion(motions, members)
    fixed = [x for x, y in hyp if x == y]
    line = fixed[:2] if len(fixed) >= 2 else None
    if line:
        on = collinear_poly(mo[line[0]], mo[line[1]], z)
        if on:
            return [(on, f"the centroid on the line through robots {line[0]} and "
                         f"{line[1]} (a reflection fixing both)")]
    mapped, images = {x for x, _ in hyp}, {y for _, y in hyp}
    todo = [c for c in members if c not in mapped]
    if not todo:
        return []
    c = todo[0]
    out, consistent = [], []
    for d in members:
        if d in images:
            continue
        if line and d == c:
            rels = [(collinear_poly(mo[line[0]], mo[line[1]], mo[c]),
                     f"robot {c} on the line through robots {line[0]} and {line[1]}")]
        else:
            rels = [(lambda d=d: tie_about(mo[c], mo[d], z),
                     f"robots {c} and {d} as far from the centroid")]
            rels += [(lambda d=d, x=x, y=y: pair_tie(mo[c], mo[x], mo[d], mo[y]),
                      f"|{c} - {x}| = |{d} - {y}|") for x, y in hyp]
        for make, what in rels:
            p = make() if callable(make) else make
            if p:
                if len(p) > 1:
                    out.append((p, what))
                break
        else:
            consistent.append(d)
    for d in consistent:
        out += image_polys(motions, members, movers, hyp + [(c, d)], z)
    return out


__all__ = ["symmetry_polys", "mirror_pair_poly", "rotation_pair_poly", "centroid_tie",
           "rotations_of", "image_polys"]
