"""The critical instants of a joint motion: several robots move at once (a ``step``).

:mod:`.instants` lists the instants of one robot's motion while the others stand still.
In a step (``World.advance_together``) every mover is at ``piece.at(tau)`` at the common
time ``tau`` in [0, 1]: affine in ``tau`` on a segment, rational in it on an arc
(:func:`.instants.motion_of`, denominator ``1 + T^2 tau^2 > 0``), and a robot standing
still is a constant motion.  Each relation between robots below is, denominators
cleared (positive factors: no sign changes), a polynomial in ``tau``; its roots in
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
  standing still or two movers as far from it, a mover and a still robot as far from
  the SEC centre of the robots standing still -- or from the moving centroid where a
  mover can leave that SEC); every ``distance`` root is tagged ``symmetry`` too (a
  rotation or a reflection about that centre can swap the two robots).  Necessary
  conditions only: a superset of the instants where a symmetry appears.

About R's own SEC centre (the paper layer orders R about it), when R is not every
robot or A1 = sec-r: the ``ray`` and ``distance`` relations among R's robots about the
SEC centre of R's robots standing still, as :mod:`.instants` does for one mover (that
centre moves only where a mover of R is a support: the SEC-of-R instants; the ties
about the moving centre are not enumerated, only the symmetry family's centroid ties).

A superset of the events above: a candidate where nothing happens costs a Look.
:func:`joint_look_points` gives, as :func:`.instants.look_points` does, each instant
whose value the kernel holds and one rational instant in each open stretch between
consecutive instants (strictly inside (0, 1)); an instant that needs a nested radical
is seen on both sides only (``sided``).  ``invariants.Checker`` checks I3, I4 and I6 at
every Look, I9 at those of the ``sec`` and ``symmetry`` instants and beside them.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations

from flint import fmpq

from ..exact.multiquadratic import MQ
from . import geometry as g
from .instants import Motion, _reach, hull_indices, motion_of
from .joint_symmetry import symmetry_polys
from .polyroots import padd, pmul, pscale, psub, roots_of

ONE = MQ.rational(1)


def still(p) -> Motion:
    return Motion((p[0],), (p[1],), (ONE,))


def _rel(m: Motion, c):
    """``D (p - c)``."""
    return psub(m.nx, pscale(m.d, c[0])), psub(m.ny, pscale(m.d, c[1]))


def _sq(u, v):
    return padd(pmul(u, u), pmul(v, v))


def _diff(a: Motion, b: Motion):
    """``D_a D_b (p_a - p_b)``."""
    return (psub(pmul(a.nx, b.d), pmul(b.nx, a.d)), psub(pmul(a.ny, b.d), pmul(b.ny, a.d)))


def tie_poly(a: Motion, b: Motion, c) -> tuple:
    """``D_a^2 D_b^2 (|p_a - c|^2 - |p_b - c|^2)``."""
    return psub(pmul(pmul(b.d, b.d), _sq(*_rel(a, c))), pmul(pmul(a.d, a.d), _sq(*_rel(b, c))))


def ray_poly(a: Motion, b: Motion, c) -> tuple:
    """``D_a D_b cross(p_a - c, p_b - c)``: zero where both are on one line through c."""
    (ua, va), (ub, vb) = _rel(a, c), _rel(b, c)
    return psub(pmul(ua, vb), pmul(va, ub))


def contact_poly(a: Motion, b: Motion, r2) -> tuple:
    """``D_a^2 D_b^2 (|p_a - p_b|^2 - r2)``."""
    dd = pmul(a.d, b.d)
    return psub(_sq(*_diff(a, b)), pscale(pmul(dd, dd), r2))


def right_poly(q: Motion, a: Motion, b: Motion) -> tuple:
    """``dot(p_q - p_a, p_q - p_b)`` times ``D_q^2 D_a D_b``: zero where ``q`` is on the
    circle on the diameter ``a b`` (the angle at ``q`` is right)."""
    (ux, uy), (wx, wy) = _diff(q, a), _diff(q, b)
    return padd(pmul(ux, wx), pmul(uy, wy))


def incircle_poly(ms) -> tuple:
    """The in-circle determinant of four moving points, homogenised (rows
    ``(X D, Y D, X^2 + Y^2, D^2)`` with ``p = (X, Y) / D``): zero where they are on one
    circle (or one line)."""
    rows = [(pmul(m.nx, m.d), pmul(m.ny, m.d), _sq(m.nx, m.ny), pmul(m.d, m.d)) for m in ms]
    return _det(rows)


def _det(rows) -> tuple:
    if len(rows) == 1:
        return rows[0][0]
    out: tuple = ()
    for j in range(len(rows)):
        minor = [r[:j] + r[j + 1:] for r in rows[1:]]
        term = pmul(rows[0][j], _det(minor))
        out = padd(out, term) if j % 2 == 0 else psub(out, term)
    return out


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
    still_pts = {k: _const(m) for k, m in motions.items() if k not in movers}
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


def _const(m: Motion):
    return (m.nx[0] if m.nx else MQ(), m.ny[0] if m.ny else MQ())


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
                    u, v = _rel(motions[i], c)
                    d2 = pmul(motions[i].d, motions[i].d)
                    polys.append((psub(_sq(u, v), pscale(d2, MQ.rational(4 * L * L))),
                                  ("pattern", f"robot {i} on the circle of layer {L}")))
    for i in movers:
        for k in motions:
            if k != i and (k not in movers or k > i):
                polys.append((contact_poly(motions[i], motions[k], MQ.rational(4)),
                              ("pattern", f"robots {i} and {k} touching")))
    polys += _sec(motions, movers, "SEC of all")
    polys += symmetry_polys(motions, movers, sorted(motions), "all robots", centres)
    rsets = {world.robots[i].r_set for i in movers}
    for rset in sorted(rsets, key=sorted):
        if rset and (sec_r or len(rset) < n):
            sub = {k: m for k, m in motions.items() if k in rset}
            polys += _sec(sub, movers & set(sub), "SEC of R")
            # the paper layer orders R about R's own SEC centre: the rays and ties about
            # it (the centre of R's robots standing still: it moves only where a mover
            # of R is a support, at the SEC of R instants above), as instants.py does
            known = set(centres)
            stills = [_const(m) for k, m in sub.items() if k not in movers]
            if len(stills) >= 2 and movers & set(sub):
                c_r = g.smallest_enclosing_circle(stills)[0]
                if c_r not in centres:
                    polys += _about(sub, movers, c_r, "the centre of R's SEC")
                known.add(c_r)
            polys += symmetry_polys(motions, movers, sorted(sub), "R", known)
    roots = roots_of((poly, tag) for poly, tag in polys if poly)
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
    """``(points, sided)`` as :func:`.instants.look_points`, over the common time."""
    roots = joint_critical_roots(pieces, world, sec_r)
    if not roots:
        return [JointPoint(MQ.rational(fmpq(1, 2)), "half way, no critical instant",
                           frozenset(), False)], 0
    out, sided = [], 0
    for k, r in enumerate(roots):
        fams = frozenset(t[0] for t in r.tags)
        what = "; ".join(sorted({t[1] for t in r.tags}))
        if k == 0:
            out.append(JointPoint(MQ.rational(r.lo), f"just before: {what}", fams, False))
        if r.exact is not None:
            out.append(JointPoint(r.exact, what, fams, True))
        else:
            sided += 1
        out.append(JointPoint(MQ.rational(r.hi), f"just after: {what}", fams, False))
    return out, sided


__all__ = ["still", "tie_poly", "ray_poly", "contact_poly", "right_poly", "incircle_poly",
           "joint_critical_roots", "joint_look_points", "JointPoint"]
