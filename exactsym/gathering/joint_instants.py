"""The critical instants of a joint motion: several robots move at once (a ``step``).

:mod:`.instants` lists the instants of one robot's motion while the others stand still.
In a step (``World.advance_together``) every mover is at ``piece.at(tau)`` at the common
time ``tau`` in [0, 1]: affine in ``tau`` on a segment, rational in it on an arc
(:func:`.motion.motion_of`, denominator ``1 + T^2 tau^2 > 0``), and a robot standing
still is a constant motion.  Each relation between robots below is, denominators
cleared (positive factors: no sign changes), a polynomial in ``tau``
(:mod:`.joint_relations`); its roots in
(0, 1) are isolated exactly (:mod:`~exactsym.exact.algebraic.roots`).  Families, each
over the relations that
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
(:func:`.moving_centre.about_moving_sec`, shared with one mover; the roots in
that stretch).

A superset of the events above: a candidate where nothing happens costs a Look.
:func:`joint_look_points` gives, as :func:`.instants.look_points` does, each instant
whose value the kernel holds and one rational instant in each open stretch between
consecutive instants (strictly inside (0, 1)); an instant that needs a nested radical
is a point in a tower of quadratic extensions
(:mod:`~exactsym.exact.algebraic.tower_numbers`), one at a root of a cubic or quartic
factor a point of ``K(alpha)`` (:mod:`~exactsym.exact.algebraic.algebraic_numbers`); only
the roots that module leaves without a value are seen on both sides only (``sided``).
``invariants.Checker`` checks I3, I4 and I6 at
every Look, I9 at those of the ``sec`` and ``symmetry`` instants and beside them.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations

from flint import fmpq

from ..exact.algebraic.algebraic_numbers import is_algebraic
from ..exact.algebraic.polynomials import pmul, pscale, psub
from ..exact.algebraic.roots import roots_of
from ..exact.multiquadratic import MQ
from . import geometry as g
from .instant_balls import MotionBall, incircle_clear
from .motion import may_be_at, may_leave, motion_of
from .point_sets import hull_indices
from .joint_relations import (const, contact_poly, incircle_poly, ray_poly, rel, right_poly,
                              sq, still, tie_poly)
from .joint_symmetry import symmetry_polys
from .moving_centre import about_moving_sec, pairs_about
from .run_home import instant_or_none, mixes


# -- the families --------------------------------------------------------------------------
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
    balls = _balls(motions, cand)
    for quad in combinations(cand, 4):
        if set(quad) & movers:
            # balls first (:mod:`.instant_balls`): a determinant they prove rootless in
            # the interval is left out, as its exact roots would be (none)
            if balls is not None and incircle_clear([balls[k] for k in quad]):
                continue
            out.append((incircle_poly([motions[k] for k in quad]),
                        ("sec", f"{tag}: robots {', '.join(map(str, quad))} on one circle")))
    return out


def _balls(motions: dict, cand) -> dict | None:
    """The :class:`.instant_balls.MotionBall` of each candidate, or None (numbers
    without balls: every relation is built exactly)."""
    try:
        return {k: MotionBall(motions[k]) for k in cand}
    except (AttributeError, TypeError, ValueError):
        return None


def joint_critical_roots(pieces: dict, world, sec_r: bool = False) -> list:
    """Every critical instant strictly inside the step's interval, as separated
    :class:`~exactsym.exact.algebraic.roots.Root`\\ s (``pieces``: mover -> the piece it
    moves along)."""
    movers = set(pieces)
    motions = {k: motion_of(pieces[k]) if k in movers else still(r.pos)
               for k, r in enumerate(world.robots)}
    polys: list = []
    centres = {world.robots[i].centre for i in movers} - {None}
    n = len(world.robots)
    top = max(L for L in range(1, n + 1) if 1 + 3 * L * (L - 1) < n) if n > 1 else 0
    for c in sorted(centres, key=lambda p: (str(p[0]), str(p[1]))):
        polys += pairs_about(motions, movers, c, "C")
        for i in movers:
            for L in range(1, top + 1):
                if may_be_at(pieces[i], c, MQ.rational(4 * L * L)):
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
                    polys += pairs_about(sub, movers, c_r, "the centre of R's SEC")
                known.add(c_r)
            if movers & set(sub) and (c_r is None or any(
                    may_leave(sub[i], c_r, r2_r) for i in movers & set(sub))):
                # a mover of R can be a support of R's SEC: its centre moves
                sec_roots = roots_of((p, t) for p, t in sec_r_polys if p)
                more, found = about_moving_sec(sub, movers & set(sub), sec_roots, known)
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
    """A look point of a joint motion; ``root_from``: at the point just after an instant,
    the low end of the instant's isolating interval (the instant lies strictly between
    it and ``tau``), else None."""
    tau: MQ
    where: str
    families: frozenset
    exact: bool
    root_from: object = None


def joint_look_points(pieces: dict, world, sec_r: bool = False, roots=None) -> tuple:
    """``(points, sided)`` as :func:`.instants.look_points`, over the common time (an
    exact root may be a tower number); ``roots``: :func:`joint_critical_roots` of the
    same motion when the caller holds them (:func:`.stops.motion_roots`, shared by the
    stops a step resolves: an exact instant is then the very object a stop names)."""
    if roots is None:
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
        tau = instant_or_none(r.exact, pieces.values()) if not (apart and is_algebraic(r.exact)
            and mixes(world, pieces.values(), r.exact)) else None
        if tau is not None:
            out.append(JointPoint(tau, what, fams, True))
        else:
            sided += 1
        out.append(JointPoint(MQ.rational(r.hi), f"just after: {what}", fams, False, r.lo))
    return out, sided


__all__ = ["still", "tie_poly", "ray_poly", "contact_poly", "right_poly", "incircle_poly",
           "joint_critical_roots", "joint_look_points", "JointPoint"]
