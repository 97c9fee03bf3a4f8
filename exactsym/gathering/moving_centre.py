"""Rays and distance ties about a centre that may move: R's SEC centre while a mover of R
supports that SEC.

The paper layer orders R about R's own SEC centre, so the ``ray`` and ``distance``
relations among R's robots about that centre are critical instants of a motion.  While
no mover of R can leave the SEC of R's robots standing still, that centre is theirs and
stays put; while one can, it is a support, and the centre moves with it.  Both the
motion of one robot (:func:`.instants.critical_roots`, the other robots standing still)
and a joint step (:func:`.joint_instants.joint_critical_roots`) list these relations
with :func:`about_moving_sec`: the one-robot case is the joint case with one mover, the
parameter of the piece as the common time.
"""

from __future__ import annotations

from itertools import combinations

from flint import fmpq

from ..exact.algebraic.polynomials import peval, pscale, psub
from ..exact.algebraic.roots import roots_in_unit
from ..exact.multiquadratic import MQ
from . import geometry as g
from .joint_relations import (circumcentre_motion, midpoint_motion, ray_about, ray_poly,
                              seen_from, tie_about, tie_poly)


def pairs_about(motions: dict, movers, c, name: str) -> list:
    """``[(poly, (family, description))]``: the ``ray`` and ``distance`` relations about
    the fixed point ``c`` of every two robots of ``motions`` of which at least one moves
    (the others do not change)."""
    out = []
    ks = sorted(motions)
    for x, i in enumerate(ks):
        for k in ks[x + 1:]:
            if i not in movers and k not in movers:
                continue
            out.append((ray_poly(motions[i], motions[k], c),
                        ("ray", f"robots {i} and {k} on one line through {name}")))
            out.append((tie_poly(motions[i], motions[k], c),
                        ("distance", f"robots {i} and {k} as far from {name}")))
    return out


def _at(m, t):
    return (peval(m.nx, t) / peval(m.d, t), peval(m.ny, t) / peval(m.d, t))


def about_moving_sec(sub: dict, movers: set, sec_roots: list, known: set) -> tuple:
    """``(polys, roots)``: the ``ray`` and ``distance`` relations of R's robots (``sub``:
    index -> motion, the movers of R among them) about R's SEC centre while a mover of R
    may support that SEC (the centre moves).  Between two consecutive roots of the SEC
    of R family (``sec_roots``: its support changes there) the support is fixed: read
    exactly at one rational instant of each stretch, the centre there is the moving
    midpoint of two supports or the moving circumcentre of three, a rational function of
    the time (:func:`.joint_relations.midpoint_motion`,
    :func:`.joint_relations.circumcentre_motion`); every pair of R (two robots standing
    still too: the centre moves) gets its ray and its tie about it, denominators cleared
    (:func:`.joint_relations.tie_about`: the centre's denominator, of constant sign on
    the stretch, divided out), and only their roots in that stretch are kept
    (``roots``; a root whose interval still straddles the stretch's end after refining
    is kept: a superset).  A support whose centre stays put (three robots standing
    still, a mover sliding on the circle of the others) is a constant centre: the
    relations that involve a mover about it (``polys``), unless ``known`` holds it
    already (``known`` gains it)."""
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
                polys += pairs_about(sub, movers, c, "the centre of R's SEC")
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
                    roots += [r for r in roots_in_unit(poly, tag) if in_windows(r, windows)]
    return polys, roots


def in_windows(r, windows, rounds: int = 48) -> bool:
    """Can root ``r`` lie in one of the closed ``windows`` (refined until its interval
    is inside one or outside all; still straddling after ``rounds``: kept)."""
    for _ in range(rounds):
        if any(lo <= r.lo and r.hi <= hi for lo, hi in windows):
            return True
        if all(r.hi <= lo or r.lo >= hi for lo, hi in windows):
            return False
        r.refine()
    return True


__all__ = ["pairs_about", "about_moving_sec", "in_windows"]
