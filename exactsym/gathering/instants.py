"""The critical instants of a motion: where a fresh Look can change (spec section 4).

A robot moves along one piece (segment or arc) while the others stand still.  What a
fresh Look sees changes only where some relation between the mover and the others
changes; each such relation is a polynomial in the piece's parameter ``f`` (``f`` as in
``piece.at(f)``; on an arc the rational rotation's parameter, so a point at a rational
``f`` stays in the field), and the instants are its roots (:mod:`~exactsym.exact.algebraic.roots`).

Families (each root carries a tag naming the family and the robots):

* ``ray``      -- the mover crosses the line through C and another robot (angular
  orders about C, the levels' polygons and their mirror lines change there);
* ``distance`` -- its distance to C equals another robot's (the levels change; a
  rotation or a reflection about C can swap the mover with that robot there, so every
  such root is tagged ``symmetry`` too, as for a joint step); where that tie vanishes
  all along (an arc about C at the robot's distance), :func:`on_circle_candidates`;
* ``pattern``  -- the mover is on the circle of a layer of the gathering pattern about C
  (``|p - C| = 2L``) or touches another robot (the recognised pattern P, hence R, can
  change there);
* ``sec``      -- the SEC's support changes: the mover crosses the SEC of the others;
  and, where it lies outside it (it is then a support), the others' hull robot ``q``
  crosses the circle on the diameter mover-``a``, the mover crosses the circle through
  three hull robots that encloses the others, a support triangle becomes right-angled
  (at a hull robot, or at the mover: the circle on the diameter ``a b`` that encloses
  the others).  The SEC of every robot (A1 = sec-all); with A1 = sec-r, also of R.
* ``symmetry`` -- a symmetry can appear: the mover crosses a mirror line of the others
  (through C -- of all the others, and of the rest of R -- and through their centroid),
  passes through C, reaches the mirror image of one robot in a
  mirror line of the remaining ones, or the centroid of all the robots meets the SEC's
  centre (necessary for a rotation; with the mover a support of the SEC as well).

About R's own SEC centre (the paper layer orders R about it), when the pattern holds
robots or A1 = sec-r: the ``ray`` and ``distance`` relations about the SEC centre of the
rest of R; and when the mover (of R) can leave that SEC -- it is then a support and the
centre moves with it -- on each stretch between two SEC-of-R instants (a fixed support)
the rays and ties of every pair of R about the moving centre of that support, as for a
joint step with one mover (:func:`.moving_centre.about_moving_sec`; the roots in that
stretch).

The list is a superset: a candidate where nothing happens costs a Look, a missed one would
be a missed check.  :func:`look_points` returns every root's exact point when the kernel
holds it, and one rational point in each open stretch between consecutive roots (before
the first, after the last; half way when there is none), strictly inside the piece: in a
stretch no relation above changes sign, so its Look stands for the whole stretch with
respect to them.  A root that needs a nested radical is exact too: a number of a tower of
quadratic extensions (:func:`~exactsym.exact.algebraic.roots.exact_root_hook`,
:mod:`~exactsym.exact.algebraic.tower_numbers`), and the mover's point there has tower
coordinates, on which the fresh Look (geometry, pattern, the paper layer) runs unchanged.
A root of an irreducible factor of degree 3 or more is exact too, a number of ``K(alpha)``
(:mod:`~exactsym.exact.algebraic.algebraic_numbers`: the polynomial factored over its
coefficients' field K, alpha's factor of odd degree or a quartic of group S4 or A4); a
root of a quartic factor of group D4, C4 or V4 is a nested radical, a tower number again
(:mod:`~exactsym.exact.algebraic.quartic`, Ferrari over K).  Only the other roots (other
even degrees, a norm or gcd too large, a radicand whose root needs an integer of more than
160 bits that the bounded split of :mod:`~exactsym.exact.mq_closure` cannot tell) are seen
on both sides only (``sided``).  Not enumerated: relations that involve neither C, nor an
SEC (R's SEC centre, moving or not, included), a symmetry or a contact (the corrected
variant's distance profiles, for example).
"""

from __future__ import annotations

from dataclasses import dataclass

from flint import ctx, fmpq

from ..exact.algebraic.algebraic_numbers import is_algebraic
from ..exact.algebraic.polynomials import padd, pgcd, pmul, pscale, psub
from ..exact.algebraic.roots import bracket, roots_in_unit, roots_of
from ..exact.algebraic.sturm import surely_no_root_in_unit
from ..exact.multiquadratic import MQ
from . import geometry as g
from . import instant_balls as B
from . import moving_centre
from .instant_balls import MotionBall
from .joint_relations import still as still_motion
from .joint_symmetry import centroid_tie
from .motion import (Motion, cross_poly, dist2_poly, dot_poly, may_leave, motion_of,
                     point_param, may_be_at, may_come_within)
from .point_sets import centroid, hull_indices, mirror_lines, reflect
from .run_home import instant_or_none, mixes

ONE = MQ.rational(1)


# -- the families ------------------------------------------------------------------------
def _sec_family(m: Motion, static: dict, tag: str, sec=None) -> list:
    """``[(poly, description)]`` for the SEC of the static robots plus the mover
    (``sec``: the static robots' SEC when the caller has it)."""
    pts = list(static.values())
    if len(pts) < 2:
        return []
    c0, r20 = sec or g.smallest_enclosing_circle(pts)
    e0 = dist2_poly(m, c0, r20)
    out = [(e0, f"{tag}: the mover crosses the SEC of the others")]
    if not e0:
        return out          # on that circle all along: the SEC does not change
    # the mover is a support only where it is outside the others' SEC: ends or roots
    ends = [sum(c for c in e0).sign(), e0[0].sign()]
    if max(ends) <= 0 and not roots_in_unit(e0):
        return out
    hull = hull_indices(static)
    H = [(k, static[k]) for k in hull]
    # balls first (:mod:`.instant_balls`): a relation they prove rootless inside the
    # piece, or a circle they prove not enclosing, is left out as the exact test would
    try:
        mb = MotionBall(m)
        HB = [B.point_ball(p) for _, p in H]
    except (AttributeError, TypeError, ValueError):     # numbers without balls
        mb = HB = None

    def encloses(c, r2):
        return all((g.dist2(c, p) - r2).sign() <= 0 for _, p in H)

    def rootless(kind, x, y) -> bool:
        if mb is None:
            return False
        try:
            xb = B.point_ball(x)
            if kind == "dot":
                return mb.dot_clear(xb, B.point_ball(y))
            return mb.dist2_clear(xb, y.enclosure(B.PREC))
        except (AttributeError, TypeError, ValueError):
            return False

    for ia, (a_i, a) in enumerate(H):
        for q_i, q in H:
            if q_i != a_i:
                qa = g.sub(q, a)
                if not rootless("dot", q, qa):
                    out.append((dot_poly(m, q, qa), f"{tag}: robot {q_i} on the circle on "
                                f"the diameter mover-{a_i}"))
                if not rootless("dot", a, qa):
                    out.append((dot_poly(m, a, qa), f"{tag}: right angle at robot {a_i} "
                                f"(mover, {a_i}, {q_i})"))
        for ib, (b_i, b) in enumerate(H[ia + 1:], ia + 1):
            if HB is not None:
                with ctx.workprec(B.PREC):
                    ab, bb = HB[ia], HB[ib]
                    mid_b = ((ab[0] + bb[0]) / 2, (ab[1] + bb[1]) / 2)
                    r2_b = B.dist2_ball(ab, bb) / 4
                if B.surely_outside(mid_b, r2_b, HB):
                    continue
            mid = g.scale(g.add(a, b), MQ.rational(fmpq(1, 2)))
            r2 = g.dist2(a, b) / 4
            if encloses(mid, r2) and not rootless("dist2", mid, r2):
                out.append((dist2_poly(m, mid, r2),
                            f"{tag}: right angle at the mover (diameter {a_i}-{b_i})"))
    for x in range(len(H)):
        for y in range(x + 1, len(H)):
            for z in range(y + 1, len(H)):
                if HB is not None:
                    circle = B.circle3_ball(HB[x], HB[y], HB[z])
                    if circle is not None and B.surely_outside(*circle, HB):
                        continue        # not collinear (exactly), and not enclosing
                a, b, c = H[x][1], H[y][1], H[z][1]
                if g.cross(g.sub(b, a), g.sub(c, a)).is_zero():
                    continue
                cc, r2 = g.circumcircle(a, b, c)
                if encloses(cc, r2) and not rootless("dist2", cc, r2):
                    out.append((dist2_poly(m, cc, r2), f"{tag}: the mover on the circle "
                                f"through robots {H[x][0]}, {H[y][0]}, {H[z][0]}"))
    return out


def _mover_may_support(m: Motion, static: dict, centre, sec) -> bool:
    """False when the mover stays inside the others' SEC or on its circle (it leaves it
    at no instant) and C is that SEC's centre: the SEC of all is then that circle, every
    symmetry of the robots fixes C, so it maps the mover to a robot as far from C (a
    ``distance`` instant), or fixes it on a mirror line through C, or the mover is at C."""
    if sec is None:
        return True
    c0, r20 = sec
    if centre is None or c0 != centre:
        return True
    return may_leave(m, c0, r20)           # False on the others' SEC circle all along


def _symmetry_family(piece, m: Motion, static: dict, centre, full: bool = True, sec=None):
    """``([(poly, description)], [(f, description)])``: lines the mover crosses and exact
    parameters where it reaches a candidate point (``full``: also the families that the
    ``distance`` instants cover when C is the SEC centre and the mover inside it)."""
    polys, params = [], []
    pts = list(static.values())
    n = len(pts) + 1
    if centre is not None:
        for u in mirror_lines(pts, centre):
            polys.append((cross_poly(m, centre, u), "symmetry: a mirror line of the others "
                          "through C"))
        polys.append((dist2_poly(m, centre, MQ()), "symmetry: the mover at C"))
    if not full:
        return polys, params
    z = centroid(pts)
    for u in mirror_lines(pts, z):
        polys.append((cross_poly(m, z, u), "symmetry: a mirror line of the others"))
    total = (sum((p[0] for p in pts), MQ()), sum((p[1] for p in pts), MQ()))
    for q_i, q in static.items():
        rest = [p for k, p in static.items() if k != q_i]
        zq = centroid(rest)
        for u in mirror_lines(rest, zq):
            f = point_param(piece, reflect(q, zq, u))
            if f is not None:
                params.append((f, f"symmetry: the mirror image of robot {q_i}"))
    # rotations: the centroid of all meets the SEC centre
    c0, _ = sec or g.smallest_enclosing_circle(pts)
    cands = [(g.sub(g.scale(c0, MQ.rational(n)), total), "the others' SEC centre")]
    hull = hull_indices(static)
    for a_i in hull:
        a = static[a_i]
        # SEC on the diameter mover-a: (p + a)/2 = (total + p)/n
        cands.append((g.scale(g.sub(g.scale(total, 2), g.scale(a, MQ.rational(n))),
                              1 / MQ.rational(n - 2)), f"the SEC on the diameter mover-{a_i}"))
    for p_star, what in cands:
        f = point_param(piece, p_star)
        if f is not None:
            params.append((f, f"symmetry: the centroid meets the SEC centre ({what})"))
    # SEC through the mover and hull robots a, b: the centroid equidistant from a, b, p
    # n D m = total D + N;  |m-a|^2 - |m-b|^2 = 2 m.(b-a) + |a|^2 - |b|^2
    mx = padd(pscale(m.d, total[0]), m.nx)
    my = padd(pscale(m.d, total[1]), m.ny)
    for x, a_i in enumerate(hull):
        for b_i in hull[x + 1:]:
            a, b = static[a_i], static[b_i]
            ba = g.sub(b, a)
            e1 = padd(pscale(padd(pscale(mx, ba[0]), pscale(my, ba[1])), 2),
                      pscale(m.d, (g.dot(a, a) - g.dot(b, b)) * n))
            # the gcd's roots are roots of e1 and of e2: none inside the piece when e1 is
            # zero or a ball proves it has none there (its roots are all that is read),
            # so e2 is not built then
            if not e1 or surely_no_root_in_unit(e1):
                continue
            # |m-a|^2 - |m-p|^2 with nD m, nD a, n N: (nDm - nDa)^2 - (nDm - nN)^2
            ax, ay = pscale(m.d, a[0] * n), pscale(m.d, a[1] * n)
            px, py = pscale(m.nx, MQ.rational(n)), pscale(m.ny, MQ.rational(n))
            e2 = psub(padd(pmul(psub(mx, ax), psub(mx, ax)), pmul(psub(my, ay), psub(my, ay))),
                      padd(pmul(psub(mx, px), psub(mx, px)), pmul(psub(my, py), psub(my, py))))
            common = pgcd(e1, e2) if e2 and not surely_no_root_in_unit(e2) else ()
            if len(common) > 1:
                polys.append((common, f"symmetry: the centroid meets the SEC centre (SEC "
                              f"through the mover, {a_i} and {b_i})"))
    return polys, params


def _about(piece, m: Motion, centre, static: dict, name: str, mover: int = -1,
           groups=()) -> tuple:
    """``(polys, params)``: the ``ray`` and ``distance`` polynomials about ``centre``;
    where a tie vanishes identically (the mover on an arc about ``centre`` at robot k's
    distance), for each of ``groups`` (``[(robots standing still, name)]``) that holds
    k, the ``symmetry`` candidates of :func:`on_circle_candidates` instead."""
    polys, params = [], []
    for k, q in static.items():
        w = g.sub(q, centre)
        if w[0].is_zero() and w[1].is_zero():
            continue
        polys.append((cross_poly(m, centre, w), ("ray", f"on the line through {name} and "
                                                        f"robot {k}")))
        if may_be_at(piece, centre, g.dot(w, w)):
            tie = dist2_poly(m, centre, g.dot(w, w))
            if tie:
                polys.append((tie, ("distance", f"as far from {name} as robot {k}")))
                continue
            for members, who in groups:
                if k in members:
                    more, at = on_circle_candidates(piece, m, mover, members, k, centre,
                                                    f"{who}, on robot {k}'s circle about "
                                                    f"{name}")
                    polys += [(p, ("symmetry", w)) for p, w in more]
                    params += [(f, ("symmetry", w)) for f, w in at]
    return polys, params


def on_circle_candidates(piece, m: Motion, mover: int, still: dict, q: int, centre,
                         what: str) -> tuple:
    """``([(poly, description)], [(f, description)])``: where a symmetry of X (the mover
    and the robots ``still``, ``{index: point}``, q among them) can map the mover p to
    q while p moves on q's circle about ``centre`` (the tie about it vanishes all along:
    an epsilon move along the SEC's circle is one).  Necessary conditions:

    * a symmetry s of a finite set is affine and permutes it, so it fixes X's centroid
      z, which moves with p: if s(p) = q then ``|p - z| = |s(p) - s(z)| = |q - z|``
      (the polynomial; degree 2 on a segment, 6 on an arc,
      :func:`.joint_symmetry.centroid_tie` with one mover);
    * a reflection is an involution: s(p) = q gives s(q) = p, so it maps the rest
      (X without p and q) onto itself: p is the mirror image of q in a mirror line of
      the rest (through the rest's centroid, or through ``centre`` when s fixes it);
    * a rotation about ``centre`` (a fixed point of every symmetry when ``centre`` is
      the SEC's centre and the mover is no support) with s(p) = q: either s(q) = p (a
      half turn, p = 2 centre - q) or s(q) = r, a robot of the rest on q's circle, and
      s is the rotation taking q to r, so p = s^-1(q);

    the last two are exact points (their parameters on the piece).  The centroid tie
    alone can vanish all along too (when the rest's centroid is ``centre``), the exact
    points cannot."""
    motions = {k: still_motion(p) for k, p in still.items()}
    motions[mover] = m
    tie = centroid_tie(motions, sorted(motions), {mover}, mover, q)
    polys = [(tie, f"symmetry: as far from the centroid of {what}")] if len(tie) > 1 else []
    qp = still[q]
    rest = [p for k, p in still.items() if k != q]
    cands = [(g.sub(g.scale(centre, 2), qp), "a half turn about the centre")]
    for z, zname in ((centroid(rest), "the rest's centroid"), (centre, "the centre")):
        if rest:
            cands += [(reflect(qp, z, u), f"the mirror image in a mirror line through "
                                           f"{zname}") for u in mirror_lines(rest, z)]
    w = g.sub(qp, centre)
    r2 = g.dot(w, w)
    for r in rest:
        v = g.sub(r, centre)
        if g.dot(v, v) == r2:
            c, s = g.dot(w, v) / r2, g.cross(w, v) / r2
            cands.append((g.add(centre, g.rotate(w, c, -s)), "a rotation about the "
                          "centre"))
    params = []
    for p_star, how in cands:
        f = point_param(piece, p_star)
        if f is not None:
            params.append((f, f"symmetry: robot {q}'s image ({how}; {what})"))
    return polys, params


def critical_roots(piece, world, mover: int, centre, sec_r: bool = False) -> list:
    """Every critical instant strictly inside ``piece`` as separated :class:`Root`\\ s
    (tags: ``(family, description)``)."""
    m = motion_of(piece)
    static = {k: r.pos for k, r in enumerate(world.robots) if k != mover}
    sec = g.smallest_enclosing_circle(list(static.values())) if len(static) >= 2 else None
    polys: list = []
    rset = world.robots[mover].r_set
    sub_r = {k: p for k, p in static.items() if k in rset}
    proper_r = bool(rset) and len(sub_r) < len(static)
    # the symmetries the algorithm reads: of all the robots, and of R (the paper layer
    # decides on R) when the pattern holds robots or A1 = sec-r
    groups = [(static, "all robots")] + ([(sub_r, "R")] if sec_r or proper_r else [])
    about_params: list = []
    if centre is not None:
        more, at = _about(piece, m, centre, static, "C", mover, groups)
        polys, about_params = polys + more, about_params + at
        # the pattern: the mover on a layer's circle (|p - C| = 2L), or touching a robot;
        # layer L holds a robot of P only when the inner layers are full: 1 + 3L(L - 1)
        # robots at least (capacity of layer l >= 6l), so no larger L matters
        n = len(world.robots)
        top = max(L for L in range(1, n + 1) if 1 + 3 * L * (L - 1) < n) if n > 1 else 0
        for L in range(1, top + 1):
            if may_be_at(piece, centre, MQ.rational(4 * L * L)):
                polys.append((dist2_poly(m, centre, MQ.rational(4 * L * L)),
                              ("pattern", f"on the circle of layer {L}")))
    # the paper layer orders R about R's own SEC centre: when the pattern holds robots,
    # R's SEC (its support changes) and the lines and ties about its centre too
    extra: list = []
    if sec_r or proper_r:
        sec_r_polys = [(poly, ("sec", what)) for poly, what in
                       _sec_family(m, sub_r, "SEC of R")]
        c_r = None
        if len(sub_r) >= 2:
            c_r, r2_r = g.smallest_enclosing_circle(list(sub_r.values()))
            if centre is None or c_r != centre:
                more, at = _about(piece, m, c_r, sub_r, "the centre of R's SEC", mover,
                                  [(sub_r, "R")])
                polys, about_params = polys + more, about_params + at
        if mover in rset and (c_r is None or may_leave(m, c_r, r2_r)):
            # the mover can be a support of R's SEC: its centre moves with the mover, on
            # each stretch between two SEC-of-R instants as a joint step's does
            sub = {k: still_motion(p) for k, p in sub_r.items()}
            sub[mover] = m
            sec_roots = roots_of((p, t) for p, t in sec_r_polys if p)
            known = {centre, c_r} - {None}
            more, found = moving_centre.about_moving_sec(sub, {mover}, sec_roots, known)
            polys += more
            extra += sec_roots + found
        else:
            polys += sec_r_polys
    for k, q in static.items():
        if may_come_within(piece, q, MQ.rational(4)):
            polys.append((dist2_poly(m, q, MQ.rational(4)),
                          ("pattern", f"touching robot {k}")))
    for poly, what in _sec_family(m, static, "SEC of all", sec):
        polys.append((poly, ("sec", what)))
    sym_polys, sym_params = _symmetry_family(
        piece, m, static, centre, full=_mover_may_support(m, static, centre, sec), sec=sec)
    polys += [(p, ("symmetry", w)) for p, w in sym_polys]
    # the paper decides on R (the robots outside the pattern) about C: mirror lines of
    # the rest of R through C too, when the pattern holds robots
    if centre is not None and proper_r:
        for u in mirror_lines(list(sub_r.values()), centre):
            polys.append((cross_poly(m, centre, u), ("symmetry", "a mirror line of the rest "
                                                     "of R through C")))
    roots = roots_of(polys, [bracket((), f, ("symmetry", what)) for f, what in sym_params]
                     + [bracket((), f, tag) for f, tag in about_params] + extra)
    for r in roots:
        # a rotation or a reflection about that centre can swap the mover with a robot as
        # far from it: the ties are symmetry candidates too (as for a joint step)
        r.tags += [("symmetry", w) for f, w in list(r.tags) if f == "distance"]
    return roots


@dataclass(frozen=True)
class LookPoint:
    f: object               # MQ, a tower number (nested radical), or K(alpha)'s number
    point: tuple
    where: str
    families: frozenset
    exact: bool             # the instant itself (False: a point between two instants)


def look_points(piece, world, mover: int, centre, sec_r: bool = False) -> tuple:
    """``(points, sided)``: the :class:`LookPoint`\\ s to check, in order along the piece
    -- one rational point in each open stretch between consecutive instants (the first
    before the first instant, the last after the last) and each instant itself when the
    kernel holds it (a nested radical: a point with tower coordinates; a root of a cubic
    or quartic factor: a point of ``K(alpha)``; a nested root re-homed into the piece's
    run tower first, :func:`.run_home.instant_in`) -- and the number of instants checked
    only on both sides (the roots :mod:`~exactsym.exact.algebraic.algebraic_numbers`
    leaves without a value, or that the piece's tower cannot re-home)."""
    roots = critical_roots(piece, world, mover, centre, sec_r)
    if not roots:             # one stretch: the whole open piece
        half = MQ.rational(fmpq(1, 2))
        return [LookPoint(half, piece.at(half), "half way, no critical instant",
                          frozenset(), False)], 0
    out, sided = [], 0
    # K(alpha)'s numbers do not mix with a run's tower numbers (run_home.mixes)
    apart = mixes(world, [piece])
    for k, r in enumerate(roots):
        fams = frozenset(t[0] for t in r.tags)
        what = "; ".join(sorted({t[1] for t in r.tags}))
        if k == 0:
            lo = MQ.rational(r.lo)
            out.append(LookPoint(lo, piece.at(lo), f"just before: {what}", fams, False))
        f = instant_or_none(r.exact, [piece]) if not (apart and is_algebraic(r.exact) and mixes(
            world, [piece], r.exact)) else None
        if f is not None:
            out.append(LookPoint(f, piece.at(f), what, fams, True))
        else:
            sided += 1
        # the stretch up to the next instant: its families change too at its end
        nxt = roots[k + 1] if k + 1 < len(roots) else None
        hi = MQ.rational(r.hi)
        fams_after = fams | (frozenset(t[0] for t in nxt.tags) if nxt else frozenset())
        out.append(LookPoint(hi, piece.at(hi), f"just after: {what}", fams_after, False))
    return out, sided


__all__ = ["critical_roots", "look_points", "LookPoint", "on_circle_candidates"]
