"""The critical instants of a joint motion: several robots move at once (a ``step``).

:mod:`.instants` lists the instants of one robot's motion while the others stand still.
In a step (``World.advance_together``) every mover is at ``piece.at(tau)`` at the common
time ``tau`` in [0, 1]: affine in ``tau`` on a segment, rational in it on an arc
(:func:`.instants.motion_of`, denominator ``1 + T^2 tau^2 > 0``), and a robot standing
still is a constant motion.  Each relation between robots below is, denominators
cleared (positive factors: no sign changes), a polynomial in ``tau``
(:mod:`.joint_relations`); its roots in
(0, 1) are isolated exactly (:mod:`.polyroots`).  Families, each over the relations that
involve at least one mover (the others do not change during the step):

* ``distance`` -- two robots as far from C (mover-mover, mover-still);
* ``ray``      -- two robots on one line through C;
* ``pattern``  -- a mover on the circle of a layer (``|p - C| = 2L``), or two robots
  2 apart (a contact: P can change);
* ``sec``      -- the SEC's support changes: a robot on the circle on the diameter of
  two others (also: a support triangle turns right-angled) or four robots on one
  circle, among the SEC candidates: every mover and the hull vertices of the robots
  standing still (a still robot inside the still robots' hull is never on the hull,
  so never a support); of all robots, and of R when R is not all of them (A1 = sec-r,
  or the pattern holds robots);
* ``symmetry`` -- a symmetry of all the robots, or of R, can appear
  (:mod:`.joint_symmetry`: a mover on a mirror line of the robots standing still or
  two movers mirror images in it, a mover at the centre of a rotation of the robots
  standing still or the image of another mover in it, a mover and a still robot as far
  from the SEC centre of the robots standing still -- or from the moving centroid where
  a mover can leave that SEC or keeps the robot's distance from its centre; with fewer
  than two robots standing still, or a mover keeping a still robot's distance from
  both centres, the hypotheses on images of :func:`.joint_symmetry.image_polys`); every
  ``distance`` root is tagged ``symmetry`` too (a rotation or a reflection about that
  centre can swap the two robots).  Necessary
  conditions only: a superset of the instants where a symmetry appears.

About R's own SEC centre (the paper layer orders R about it), when R is not every
robot or A1 = sec-r: the ``ray`` and ``distance`` relations among R's robots about the
SEC centre of R's robots standing still, as :mod:`.instants` does for one mover; and
when a mover of R can leave that SEC (it is then a support, and the centre moves), on
each stretch between two SEC-of-R instants (a fixed support there) the rays and ties of
every pair of R about the moving centre of that support, a rational function of tau
(:func:`_about_moving_sec`; the roots in that stretch).

A superset of the events above: a candidate where nothing happens costs a Look.
:func:`joint_look_points` gives, as :func:`.instants.look_points` does, each instant
whose value the kernel holds and one rational instant in each open stretch between
consecutive instants (strictly inside (0, 1)); an instant that needs a nested radical
is a point in a tower of quadratic extensions (:mod:`.tower_numbers`), one at a root of a
cubic or quartic factor a point of ``K(alpha)`` (:mod:`.algebraic_instants`); only the
roots that module leaves without a value are seen on both sides only (``sided``).  ``invariants.Checker`` checks I3, I4 and I6 at
every Look, I9 at those of the ``sec`` and ``symmetry`` instants and beside them.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations

from flint import fmpq

from ..exact.multiquadratic import MQ
from . import geometry as g
from .algebraic_instants import is_algebraic, mixes
from .instants import _reach, hull_indices, motion_of
from .joint_relations import (circumcentre_motion, const, contact_poly, incircle_poly,
                              midpoint_motion, ray_about, ray_poly, rel, right_poly,
                              seen_from, sq, still, tie_about, tie_poly)
from .joint_symmetry import _may_leave, symmetry_polys
from .polyroots import peval, pmul, pscale, psub, roots_in_unit, roots_of


# -- the families --------------------------------------------------------------------------
def _about(motions: dict, movers, c, name: str) -> list:
    out = []
    for x, i in enumerate(sorted(motions)):
        for k in sorted(motions)[x + 1:]:
            if i not in movers and k not in movers:
                continue
            out.append((ray_poly(motions[i], motions[k], c),
                        ("ray", f"robots {i} and {k} on one line through {name}")))
            out.append((tie_poly(motions[i], motions[k], c),
                        ("distance", f"robots {i} and {k} as far from {name}")))
    return out


def _sec(motions: dict, movers, tag: str) -> list:
    """SEC support changes among the candidates (movers, hull of the still robots)."""
    still_pts = {k: const(m) for k, m in motions.items() if k not in movers}
    cand = sorted(set(movers) | set(hull_indices(still_pts) if len(still_pts) > 2
                                     else still_pts))
    out = []
    for a, b in combinations(cand, 2):
        for q in cand:
            if q not in (a, b) and {a, b, q} & movers:
                out.append((right_poly(motions[q], motions[a], motions[b]),
                            ("sec", f"{tag}: robot {q} on the circle on the diameter "
                                    f"{a}-{b}")))
    for quad in combinations(cand, 4):
        if set(quad) & movers:
            out.append((incircle_poly([motions[k] for k in quad]),
                        ("sec", f"{tag}: robots {', '.join(map(str, quad))} on one circle")))
    return out


def _at(m, t):
    return (peval(m.nx, t) / peval(m.d, t), peval(m.ny, t) / peval(m.d, t))


def _about_moving_sec(sub: dict, movers: set, sec_roots: list, known: set) -> tuple:
    """``(polys, roots)``: the ``ray`` and ``distance`` relations of R's robots about
    R's SEC centre while a mover of R may support that SEC (the centre moves).  Between
    two consecutive roots of the SEC of R family (``sec_roots``: its support changes
    there) the support is fixed: read exactly at one rational instant of each stretch,
    the centre there is the moving midpoint of two supports or the moving circumcentre
    of three, a rational function of tau (:func:`.joint_relations.midpoint_motion`,
    :func:`.joint_relations.circumcentre_motion`); every pair of R (two robots standing
    still too: the centre moves) gets its ray and its tie about it, denominators cleared
    (:func:`.joint_relations.tie_about`: the centre's denominator, of constant sign on
    the stretch, divided out), and only their roots in that stretch are kept (``roots``; a root whose
    interval still straddles the stretch's end after refining is kept: a superset).  A
    support whose centre stays put (three robots standing still, a mover sliding on the
    circle of the others) is a constant centre: the relations that involve a mover
    about it (``polys``), unless ``known`` holds it already."""
    if len(sub) < 3:
        return [], []          # two robots: on one line through their midpoint, as far
    half = MQ.rational(fmpq(1, 2))
    samples = ([MQ.rational(sec_roots[0].lo)] + [MQ.rational(r.hi) for r in sec_roots]
               if sec_roots else [half])
    ends = [fmpq(0)] + [r.lo for r in sec_roots], [r.hi for r in sec_roots] + [fmpq(1)]
    centres: dict = {}
    polys: list = []
    for k, t in enumerate(samples):
        pts = {j: _at(m, t) for j, m in sub.items()}
        c, r2 = g.smallest_enclosing_circle(list(pts.values()))
        on = sorted((j for j in pts if g.dist2(pts[j], c) == r2),
                    key=lambda j: (j in movers, j))
        pair = next(((a, b) for a, b in combinations(on, 2)
                     if g.scale(g.add(pts[a], pts[b]), half) == c), None)
        sup = pair if pair is not None and len([j for j in on if j not in movers]) < 3 \
            else tuple(on[:3])
        m = midpoint_motion(*(sub[j] for j in sup)) if len(sup) == 2 else \
            circumcentre_motion(*(sub[j] for j in sup))
        if not (psub(m.nx, pscale(m.d, c[0])) or psub(m.ny, pscale(m.d, c[1]))):
            if c not in known:                   # it stays put on this stretch
                known.add(c)
                polys += _about(sub, movers, c, "the centre of R's SEC")
            continue
        centres.setdefault(sup, (m, []))[1].append((ends[0][k], ends[1][k]))
    roots: list = []
    ks = sorted(sub)
    for sup, (m, windows) in centres.items():
        name = f"the centre of R's SEC (supports {', '.join(map(str, sup))})"
        seen = {a: seen_from(sub[a], m) for a in ks}
        for x, a in enumerate(ks):
            for b in ks[x + 1:]:
                pair = (seen[a], seen[b])
                for poly, tag in ((ray_about(sub[a], sub[b], m, pair),
                                   ("ray", f"robots {a} and {b} on one line through {name}")),
                                  (tie_about(sub[a], sub[b], m, pair),
                                   ("distance", f"robots {a} and {b} as far from {name}"))):
                    roots += [r for r in roots_in_unit(poly, tag) if _in_windows(r, windows)]
    return polys, roots


def _in_windows(r, windows, rounds: int = 48) -> bool:
    """Can root ``r`` lie in one of the closed ``windows`` (refined until its interval
    is inside one or outside all; still straddling after ``rounds``: kept)."""
    for _ in range(rounds):
        if any(lo <= r.lo and r.hi <= hi for lo, hi in windows):
            return True
        if all(r.hi <= lo or r.lo >= hi for lo, hi in windows):
            return False
        r.refine()
    return True


def joint_critical_roots(pieces: dict, world, sec_r: bool = False) -> list:
    """Every critical instant strictly inside the step's interval, as separated
    :class:`.polyroots.Root`\\ s (``pieces``: mover -> the piece it moves along)."""
    movers = set(pieces)
    motions = {k: motion_of(pieces[k]) if k in movers else still(r.pos)
               for k, r in enumerate(world.robots)}
    polys: list = []
    centres = {world.robots[i].centre for i in movers} - {None}
    n = len(world.robots)
    top = max(L for L in range(1, n + 1) if 1 + 3 * L * (L - 1) < n) if n > 1 else 0
    for c in sorted(centres, key=lambda p: (str(p[0]), str(p[1]))):
        polys += _about(motions, movers, c, "C")
        for i in movers:
            lo, hi = _reach(pieces[i], c)
            for L in range(1, top + 1):
                if lo <= 2 * L <= hi:
                    u, v = rel(motions[i], c)
                    d2 = pmul(motions[i].d, motions[i].d)
                    polys.append((psub(sq(u, v), pscale(d2, MQ.rational(4 * L * L))),
                                  ("pattern", f"robot {i} on the circle of layer {L}")))
    for i in movers:
        for k in motions:
            if k != i and (k not in movers or k > i):
                polys.append((contact_poly(motions[i], motions[k], MQ.rational(4)),
                              ("pattern", f"robots {i} and {k} touching")))
    extra: list = []
    polys += _sec(motions, movers, "SEC of all")
    polys += symmetry_polys(motions, movers, sorted(motions), "all robots", centres)
    rsets = {world.robots[i].r_set for i in movers}
    for rset in sorted(rsets, key=sorted):
        if rset and (sec_r or len(rset) < n):
            sub = {k: m for k, m in motions.items() if k in rset}
            sec_r_polys = _sec(sub, movers & set(sub), "SEC of R")
            # the paper layer orders R about R's own SEC centre: the rays and ties about
            # it (the centre of R's robots standing still: it moves only where a mover
            # of R is a support, at the SEC of R instants above), as instants.py does
            known = set(centres)
            stills = [const(m) for k, m in sub.items() if k not in movers]
            c_r = None
            if len(stills) >= 2 and movers & set(sub):
                c_r, r2_r = g.smallest_enclosing_circle(stills)
                if c_r not in centres:
                    polys += _about(sub, movers, c_r, "the centre of R's SEC")
                known.add(c_r)
            if movers & set(sub) and (c_r is None or any(
                    _may_leave(sub[i], c_r, r2_r) for i in movers & set(sub))):
                # a mover of R can be a support of R's SEC: its centre moves
                sec_roots = roots_of((p, t) for p, t in sec_r_polys if p)
                more, found = _about_moving_sec(sub, movers & set(sub), sec_roots, known)
                polys += more
                extra += sec_roots + found
            else:
                polys += sec_r_polys
            polys += symmetry_polys(motions, movers, sorted(sub), "R", known)
    roots = roots_of(((poly, tag) for poly, tag in polys if poly), extra)
    for r in roots:
        # a rotation or a reflection about that centre can swap two robots as far from
        # it (joint_symmetry, case B): the ties are symmetry candidates too (the same
        # description: a Look's text names the tie once)
        r.tags += [("symmetry", w) for f, w in list(r.tags) if f == "distance"]
    return roots


@dataclass(frozen=True)
class JointPoint:
    tau: MQ
    where: str
    families: frozenset
    exact: bool


def joint_look_points(pieces: dict, world, sec_r: bool = False) -> tuple:
    """``(points, sided)`` as :func:`.instants.look_points`, over the common time (an
    exact root may be a tower number)."""
    roots = joint_critical_roots(pieces, world, sec_r)
    if not roots:
        return [JointPoint(MQ.rational(fmpq(1, 2)), "half way, no critical instant",
                           frozenset(), False)], 0
    out, sided = [], 0
    apart = mixes(world, pieces.values())
    for k, r in enumerate(roots):
        fams = frozenset(t[0] for t in r.tags)
        what = "; ".join(sorted({t[1] for t in r.tags}))
        if k == 0:
            out.append(JointPoint(MQ.rational(r.lo), f"just before: {what}", fams, False))
        if r.exact is not None and not (apart and is_algebraic(r.exact)):
            out.append(JointPoint(r.exact, what, fams, True))
        else:
            sided += 1
        out.append(JointPoint(MQ.rational(r.hi), f"just after: {what}", fams, False))
    return out, sided


__all__ = ["still", "tie_poly", "ray_poly", "contact_poly", "right_poly", "incircle_poly",
           "joint_critical_roots", "joint_look_points", "JointPoint"]
