"""A corrected gathering algorithm (issue 11 point 9): ``--algorithm corrected``.

Not the paper's algorithm (that is :mod:`.robot`, which stays as printed); a variant that
repairs what the simulator finds wrong with it, held to the same invariants I1-I10.
Like :func:`.robot.decide` it is a pure function of one snapshot (every robot computes
the same decision; oblivious, no chirality: every choice is made by distances and dot
products, never by a sense of rotation of the observer's frame).

1. **The centre C, fixed once a robot occupies it.**  For every robot k, the largest
   valid partial pattern about k's position (:func:`.pattern.recognise`, k at the
   centre); M its largest size.  M = 1 (no two robots touch): C is the SEC centre of all
   robots.  M >= 2: among the robots with a pattern of M robots, the one whose farthest
   robot outside its pattern is nearest (``f(k)``; this is the SEC centre's own
   property while the SEC's support is outside the pattern, and it stays with the robot
   at C when the SEC changes at the end); two minimisers: stay ("ambiguous centre").
   Patterns of 2, 3 and 4 robots have several possible centres (an equilateral triangle;
   a chain of three about C has its middle robot as another centre), so the choice of
   the mover below keeps the minimiser during the move.
2. **P** = the pattern about C, **R** = the others; R empty: terminated.
3. **The mover**: the robot of R nearest to C (the paper's gather-min-distance, so I4
   holds); several equally near: the first, in order of distance to its target slot
   (nearest first), whose path exists; still tied: preferring movers after whose move
   the robots left in R have pairwise different profiles (sorted squared distances to
   the others), the one whose own profile is lexicographically smallest (needs no
   handedness); equal profiles: stay (no asymmetry is used).
   A mover is allowed only if C cannot change during its move: when M = 1 the SEC of the
   other robots must be the SEC of all (the mover is not needed to support it); when
   M >= 2 and several robots tie for the centre, for every other candidate k the robots
   of R that stay must keep ``f(k) > f(C)`` (a strict exact inequality on squared
   distances), or, when the mover is the last robot of R, every point of its path must be
   nearer to C than to k.
4. **The target**: C when nobody is at C; else, with l the last layer of P, the radial
   point at 2 when P is the robot at C alone, the point at 2(l + 1) on the ray of the
   robot of layer l nearest in angle when layer l is full (a lone robot starts the next
   layer), or the
   free slot next to an end of layer l's chain: while P has at most 4 robots, the one
   farther from the robots of R that stay (so the centre stays unique in f), else the
   one nearer to the mover in angle (the larger dot product; a tie: stay).  Robots
   within 2 of an empty C other than the nearest: the farthest of them first moves
   radially out to distance 2 (C cannot be taken while two robots are that close).
5. **Collision-free paths** (distances to C never grow, so I4 holds along the path):
   to C: the segment, or else a detour -- an arc about C on the mover's circle by a
   rational rotation (tan of the half angle 1/16, 1/8, ..., 1; the sense away from the
   blocking robot, both senses when robots block on both sides), then the segment to C;
   to a point of a layer: the paths of :func:`_to_slot_paths` (along the mover's own
   circle then radially in; a segment to the target's ray outside the layer then
   radially in; the straight segment), each of which a fresh Look finds again from any
   of its points.  The paper's path along the layer's own circle is not used: a mover
   there beside a chain of one robot makes two chains tie, and P shrinks while it
   moves.  The first path free of every other robot (closer than 2 nowhere, touching
   allowed) that keeps C is taken; none: stay.
6. **The final robots**: no leader election at all -- the rule above is the same for
   two or three robots left as for many (nearest to C, ties by the slot geometry), so
   an asymmetric triangle of three (where the paper's Elect_Leader_Asym elects nobody)
   is no obstacle.

What it does not handle (the sweep shows where): exact ties (equidistant robots with
the same slot distance, a mover on the bisector of its two slots), a radial move into a
new layer that is blocked, and a tie of the centre rule with no allowed mover.
"""

from __future__ import annotations

from functools import lru_cache
from math import isqrt

from flint import fmpq

from ..exact.multiquadratic import MQ, sqrt_rational
from . import geometry as g
from .pattern import Pattern, capacity, recognise, slot
from .robot import Decision, Move, Readings, decide, radial_point
from ..exact.algebraic.run_tower import sqrt_exact
from .run_home import snapshot_key

ALGORITHMS = ("paper", "corrected")

#: tan(angle / 2) of the detour rotations tried, smallest first.
DETOUR_TANGENTS = tuple(fmpq(1, 2 ** k) for k in range(4, -1, -1))


def _pattern_sizes(pts, readings, unit, approx):
    """``(M, {k: pattern})``: the largest size M of the pattern about a robot's position,
    and the patterns of every robot reaching it.  A robot touching d < 6 others (layer 1
    not full) has a pattern of at most 1 + d robots; it is recognised only when that
    bound reaches the largest size found among the robots touching 6 (so the result is
    that of recognising every robot); a robot touching nobody has only itself about it.
    The degrees counted are of the pairs a certified float filter cannot separate from
    touching (:func:`.geometry.maybe_touching_pairs`): a superset, so the bounds hold,
    and :func:`.pattern.recognise` decides exactly."""
    degree = [0] * len(pts)
    for i, j in g.maybe_touching_pairs(pts, unit):
        degree[i] += 1
        degree[j] += 1
    pats = {}
    for k, d in enumerate(degree):
        if d >= capacity(1):
            pats[k] = _recognise(pts, pts[k], readings.lone, unit, approx)
    best = max((len(p.robots) for p in pats.values()), default=1)
    for k, d in enumerate(degree):
        if k in pats or 1 + d < best:
            continue
        pats[k] = _recognise(pts, pts[k], readings.lone, unit, approx) if d else \
            Pattern(pts[k], k, (), True)
        best = max(best, len(pats[k].robots))
    return best, {k: p for k, p in pats.items() if len(p.robots) == best}


def _recognise(pts, centre, lone, unit, approx):
    """:func:`.pattern.recognise` about ``centre`` on the robots a certified filter finds
    possibly at C or on a layer's circle (:func:`.geometry.maybe_on_layers`), mapped back
    to the snapshot's indices: the same pattern, without exact distances to the rest."""
    keep = g.maybe_on_layers(approx, centre, unit)
    if len(keep) == len(pts):
        return recognise(pts, centre, lone, unit)
    pat = recognise([pts[k] for k in keep], centre, lone, unit)
    return Pattern(pat.centre, None if pat.centre_robot is None else keep[pat.centre_robot],
                   tuple(tuple(keep[k] for k in layer) for layer in pat.layers), pat.valid,
                   pat.defects)


def _far2(pts, k_pos, others, approx=None):
    """Largest squared distance from ``k_pos`` to the robots ``others`` (None if empty);
    ``approx`` (:func:`.geometry.approx_points`): only the robots a certified filter
    cannot rule out are compared exactly."""
    if approx is not None:
        others = g.farthest_candidates(approx, k_pos, others)
    best = None
    for j in others:
        d = g.dist2(pts[j], k_pos)
        if best is None or (d - best).sign() > 0:
            best = d
    return best


def choose_centre(pts, readings: Readings, unit, approx=None):
    """``(C, pattern, candidates, detail)``; C None when the rule is ambiguous.
    ``candidates``: the robots whose patterns tie for the largest (M >= 2)."""
    M, sizes = _pattern_sizes(pts, readings, unit, approx)
    if M == 1:
        centre, _ = g.smallest_enclosing_circle(list(pts))
        return (centre, _recognise(pts, centre, readings.lone, unit, approx), (),
                "C: SEC centre")
    cands = sorted(sizes)
    scored = []
    for k in cands:
        pat = sizes[k]
        members = pat.robots                 # a property: a new set at each call
        outside = [j for j in range(len(pts)) if j not in members]
        scored.append((k, _far2(pts, pts[k], outside, approx)))
    if any(f is None for _, f in scored):               # a complete pattern
        k = next(k for k, f in scored if f is None)
        return pts[k], sizes[k], tuple(cands), "C: the complete pattern's centre"
    best = scored[0]
    for item in scored[1:]:
        if (item[1] - best[1]).sign() < 0:
            best = item
    ties = [k for k, f in scored if f == best[1]]
    if len(ties) > 1:
        return None, None, tuple(cands), (f"ambiguous centre: robots {ties} tie for the "
                                           f"centre of a pattern of {M}")
    k = best[0]
    return pts[k], sizes[k], tuple(cands), f"C: robot {k}, the centre of {M} robots"


def _free(pieces, pts, mover, unit2, approx=None) -> bool:
    """No robot but the mover comes closer than 2 to the path.  ``approx``
    (:func:`.geometry.approx_points` of ``pts``): a certified filter leaves out the
    robots certainly far from a piece; the others are tested exactly."""
    d2 = 4 * unit2
    for piece in pieces:
        near = range(len(pts)) if approx is None else \
            g.robots_near_piece(piece, approx, 2 * float(unit2) ** 0.5)
        for j in near:
            if j != mover and g.piece_hits(piece, pts[j], d2):
                return False
    return True


def _keeps_centre(pieces, pts, mover, centre, cands, R, pat, approx=None) -> bool:
    """C cannot change while ``mover`` follows ``pieces``, nor at its arrival (point 3
    of the module docstring).  ``cands`` empty (M = 1): the SEC must not need the
    mover."""
    stay = [j for j in R if j != mover]
    fc = _far2(pts, centre, R, approx)                # f(C) now: never grows (radii fall)
    if not cands:
        # C is the SEC centre of all; a mover strictly inside the SEC is in no support
        # set, so the others have the same SEC; on the circle: compute it
        r2 = _far2(pts, centre, range(len(pts)), approx)
        if (g.dist2(pts[mover], centre) - r2).sign() >= 0:
            others = [pts[j] for j in range(len(pts)) if j != mover]
            c2 = g.smallest_enclosing_circle(others)
            if not (c2[0] == centre and c2[1] == r2):
                return False
    # on arrival the mover itself may tie for the centre of a small pattern
    target = pieces[-1].final
    small = pat.centre_robot is not None and len(pat.robots) + 1 <= 4
    others = [k for k in cands if pts[k] != centre]
    if not others and not small:
        return True
    for k, where in [(k, pts[k]) for k in others] + ([(None, target)] if small else []):
        fk = _far2(pts, where, stay, approx)
        if fk is not None and (fk - fc).sign() > 0:
            continue
        if stay or k is None:
            return False
        # the last robot: every point of its path nearer to C than to k
        for piece in pieces:
            # |p - k|^2 - |p - C|^2 is linear in p: on a segment its ends decide; on an arc
            # about C, |p - C| is constant and the nearest point to k decides
            if isinstance(piece, g.Segment):
                for p in (piece.start, piece.end):
                    if (g.dist2(p, where) - g.dist2(p, centre)).sign() <= 0:
                        return False
            else:
                r2 = g.dist2(piece.start, centre)
                if g.arc_min_dist2_less(piece, where, r2) or \
                        g.dist2(piece.start, where) == r2 or g.dist2(piece.end, where) == r2:
                    return False
    return True


def _rotate_about(centre, p, t, sense):
    den = 1 + t * t
    c, s = (1 - t * t) / den, 2 * t / den
    return g.add(centre, g.rotate(g.sub(p, centre), MQ.rational(c), MQ.rational(s * sense)))


def _paths_to_centre(p, centre, pts, mover, unit2):
    """The segment to C, then detours: an arc about C on the mover's circle, then the
    segment (senses away from the robots that block the segment)."""
    yield [g.Segment(p, centre)]
    v = g.sub(p, centre)
    senses = set()
    for j, q in enumerate(pts):
        if j != mover and g.piece_hits(g.Segment(p, centre), q, 4 * unit2):
            side = g.cross(v, g.sub(q, centre)).sign()     # the blocker's side of the ray
            senses.add(-side if side else 0)
    if 0 in senses or len(senses) != 1:
        senses = {1, -1}
    for t in DETOUR_TANGENTS:
        for sense in sorted(senses):
            q = _rotate_about(centre, p, t, sense)
            yield g.arc_path(centre, p, q, sense) + [g.Segment(q, centre)]


def _ray_direction(centre, p):
    """The primitive integer direction of the ray from C through ``p`` (the same from
    every point of the ray), or None when C is irrational or the slope is."""
    v = g.sub(p, centre)
    if not (centre[0].is_rational() and centre[1].is_rational()):
        return None
    if v[1].is_zero():
        return (1 if v[0].sign() > 0 else -1, 0)
    ratio = v[0] / v[1]
    if not ratio.is_rational():
        return None
    q = ratio.to_fmpq()
    e = (int(q.p), int(q.q))
    if (v[1].sign() < 0) == (e[1] > 0):
        e = (-e[0], -e[1])
    return e


def _layer_one_point(centre, p, unit, tower=None):
    """The point of layer 1 on the mover's ray: by the ray's integer direction when it has
    one (so a robot stopped on its way finds the same point), else by its radius (a
    nested radical when ``|p - C|^2`` is irrational: a point of the snapshot's
    ``tower``, :func:`.robot.radial_point`)."""
    e = _ray_direction(centre, p)
    if e is None:
        return radial_point(centre, p, 2 * unit, tower)
    k = sqrt_rational(fmpq(1, e[0] * e[0] + e[1] * e[1])) * (2 * unit)
    return (centre[0] + k * e[0], centre[1] + k * e[1])


def _ray_point(centre, p, h):
    """A rational point on the ray from C through ``p`` at distance at least ``h``, less
    than 1/8 beyond (the first of ``C + e m/den``, ``e`` the ray's primitive integer
    direction, ``den = 8 (isqrt|e|^2 + 1)``, m = 1, 2, ...), found alike from every point
    of the ray; None when C is irrational or the ray's slope is."""
    e = _ray_direction(centre, p)
    if e is None:
        return None
    e2 = e[0] * e[0] + e[1] * e[1]
    den = 8 * (isqrt(e2) + 1)                       # steps of |e|/den < 1/8 along the ray
    need = den * den * fmpq(h) * fmpq(h) / e2       # m^2 >= den^2 h^2 / |e|^2
    m = max(1, isqrt(int(need.p) // int(need.q)))
    while m * m < need:
        m += 1
    k = fmpq(m, den)
    return (centre[0] + k * e[0], centre[1] + k * e[1])


def _to_slot_paths(p, centre, target, l, unit, limit2=None, tower=None):
    """Paths to a point of layer l (``|target - C| = 2l unit``) that the mover finds
    again from any point of them (so a fresh Look on the way plans the same target):

    * on the target's ray: the segment;
    * along the mover's own circle about C, the shorter way, to the target's ray, then
      radially in (every point of the arc has the mover's radius, and the radial part is
      on the target's ray); the radius is a nested radical when ``|p - C|^2`` is a square
      in no multiquadratic field (a number of ``tower``, the snapshot's, or of a new run
      tower: :func:`~exactsym.exact.algebraic.run_tower.sqrt_exact`); the path is left out
      only when that root cannot be built (the kernel's limits);
    * for h = 2l + 2, 2l + 4, 2l + 6 with h^2 < ``limit2`` (the squared distance of R's
      next robot to C: the mover stays the nearest; the condition does not change on the
      way): radially in to the rational point of the mover's ray just beyond radius h
      (:func:`_ray_point`, the same from every point of the ray), along that circle to
      the target's ray, radially in; then the segment to the target's ray at radius h
      and radially in (a point of the segment finds the same path);
    * the segment to the target.

    The mover's distance to C stays below ``limit2`` along them (I4)."""
    v = g.sub(p, centre)
    w = g.sub(target, centre)                          # |w| = 2l unit
    if g.cross(v, w).is_zero() and g.dot(v, w).sign() > 0:
        yield [g.Segment(p, target)]                   # already on the target's ray
        return
    r2 = g.dot(v, v)
    two_l = 2 * l * unit
    rho = _radius(r2, tower)
    if rho is not None:
        b = g.add(centre, g.scale(w, rho / two_l))
        sense = 1 if g.cross(v, w).sign() > 0 else -1
        yield g.arc_path(centre, p, b, sense) + [g.Segment(b, target)]
    for h in (two_l + 2 * unit, two_l + 4 * unit, two_l + 6 * unit):
        if limit2 is not None and (limit2 - h * h).sign() <= 0:
            continue            # I4: the mover stays strictly nearer to C than R's others
        a = _ray_point(centre, p, h)
        if a is not None and (r2 - g.dist2(a, centre)).sign() >= 0:
            ra = sqrt_rational(g.dist2(a, centre).to_fmpq())
            b = g.add(centre, g.scale(w, ra / two_l))
            sense = 1 if g.cross(v, w).sign() > 0 else -1
            pieces = ([g.Segment(p, a)] if a != p else []) + g.arc_path(centre, a, b, sense)
            yield pieces + [g.Segment(b, target)]
        b = g.add(centre, g.scale(w, fmpq(h) / two_l))
        yield [g.Segment(p, b), g.Segment(b, target)]
    yield [g.Segment(p, target)]


def _radius(r2, tower):
    """The non-negative root of the squared radius ``r2``: rational, multiquadratic or
    nested (``tower``'s); None when the kernel cannot build it."""
    if r2.is_rational():
        return sqrt_rational(r2.to_fmpq())
    try:
        return sqrt_exact(r2, tower)
    except ValueError:
        return None


def _target(p, centre, pat, pts, unit, stay, tower=None):
    """``(target, layer, kind)``: C, a new layer's radial point, or a chain end's slot;
    target None on an exact tie.  The slot: while the pattern has at most 4 robots (its
    centre is not unique), the end slot farther from the robots that stay (so that C
    stays the centre, point 1), then the nearer in angle; else the nearer in angle (the
    larger dot product with the mover's direction)."""
    if pat.centre_robot is None:
        return centre, 0, "centre"
    l = pat.last_layer
    v = g.sub(p, centre)
    if pat.last_full():
        if l == 0:
            return _layer_one_point(centre, p, unit, tower), 1, "new-layer"
        # a lone robot starts layer l + 1 on the ray of the robot of layer l nearest in
        # angle (a point that does not depend on where the mover is on its way)
        ring = pat.layers[-1]
        dots = [(g.dot(v, g.sub(pts[k], centre)), k) for k in ring]
        top = max((d for d, _ in dots), key=_Key)
        nearest = [k for d, k in dots if d == top]
        if len(nearest) > 1:
            return None, l + 1, "slot"
        ray = g.sub(pts[nearest[0]], centre)
        return g.add(centre, g.scale(ray, fmpq(l + 1, l))), l + 1, "slot"
    chain = pat.layers[-1]
    s_ccw = slot(centre, pts[chain[-1]], l, 1)
    s_cw = slot(centre, pts[chain[0]], l, -1)
    if s_ccw == s_cw:
        return s_ccw, l, "slot"
    if len(pat.robots) <= 4 and stay:
        c = (_far2(pts, s_ccw, stay) - _far2(pts, s_cw, stay)).sign()
        if c:
            return (s_ccw if c > 0 else s_cw), l, "slot"
    a, b = g.dot(v, g.sub(s_ccw, centre)), g.dot(v, g.sub(s_cw, centre))
    c = (a - b).sign()
    if c == 0:
        return None, l, "slot"
    return (s_ccw if c > 0 else s_cw), l, "slot"


def _profile(pts, i):
    """The squared distances from robot i to the others, sorted: a tie-break that needs
    no handedness (equal profiles: no choice without asymmetry)."""
    return sorted((g.dist2(pts[i], q) for j, q in enumerate(pts) if j != i), key=_Key)


def _distinct_after(pts, option, R) -> bool:
    """After ``option`` = (robot, path) is made, do the other robots of R have pairwise
    different distance profiles?"""
    i, path = option
    after = list(pts)
    after[i] = path[-1].final
    rest = [_profile(after, j) for j in R if j != i]
    return all(_profile_less(a, b) != 0 for k, a in enumerate(rest) for b in rest[k + 1:])


def _profile_less(a, b) -> int:
    for x, y in zip(a, b):
        c = (x - y).sign()
        if c:
            return c
    return 0


def decide_corrected(snapshot: tuple, readings: Readings = Readings(), unit=fmpq(1)) -> Decision:
    """The corrected algorithm's decision on one snapshot (see the module docstring).  As
    :func:`.robot.decide`: a snapshot whose coordinates come from several towers of
    nested radicals is first re-homed into one (:func:`.run_home.common_tower`), a
    radial target whose distance is a nested radical is built in that tower
    (:func:`.robot.radial_point`), and decisions are cached per snapshot and per tower
    (numbers of two towers are never compared, not even as cache keys)."""
    return _decide_corrected(snapshot_key(snapshot), readings, unit)


@lru_cache(maxsize=4096)
def _decide_corrected(key: tuple, readings: Readings, unit) -> Decision:
    # key: run_home.snapshot_key (towers and epochs first)
    towers, _epochs, snapshot = key
    tower = towers[0] if towers else None
    pts = list(snapshot)
    approx = g.approx_points(pts)
    centre, pat, cands, detail = choose_centre(pts, readings, unit, approx)
    if centre is None:
        sec, _ = g.smallest_enclosing_circle(pts)
        return Decision("stay", (), sec, recognise(pts, sec, readings.lone, unit), None, detail)
    members = pat.robots
    R = [i for i in range(len(pts)) if i not in members]
    if not R:
        return Decision("terminated", (), centre, pat, None, "R is empty")
    d = {i: g.dist2(pts[i], centre) for i in R}
    if pat.centre_robot is None:
        clear = _clear_centre(pts, centre, R, d, unit, cands, pat, approx, tower)
        if clear is not None:
            return clear
    near = min(d.values(), key=_Key)
    tied = [i for i in R if d[i] == near]
    options = []
    try:
        for i in tied:
            stay = [j for j in R if j != i]
            target, l, kind = _target(pts[i], centre, pat, pts, unit, stay, tower)
            if target is not None:
                options.append((g.dist2(pts[i], target), i, target, l, kind))
    except ValueError as err:           # a radial point the field cannot hold
        return Decision("undecided", (), centre, pat, None, str(err))
    options.sort(key=lambda o: _Key(o[0]))
    chosen, why = None, "a tie" if tied and not options else "no collision-free path that keeps C"
    k = 0
    while k < len(options) and chosen is None:
        group = [o for o in options[k:] if o[0] == options[k][0]]
        k += len(group)
        found = [(o[1], p) for o in group
                 if (p := _first_path(o, pts, centre, cands, R, unit, pat,
                                      len(tied) > 1, approx, tower)) is not None]
        if len(found) > 1:
            # the smallest profile of distances to the others; equal profiles: stay
            # ... preferring a mover after whose move the robots left in R still have
            # pairwise different profiles (ties can still be broken then)
            breakable = [f for f in found if _distinct_after(pts, f, R)]
            found = breakable or found
            profiles = {f[0]: _profile(pts, f[0]) for f in found}
            best = found[0]
            for f in found[1:]:
                if _profile_less(profiles[f[0]], profiles[best[0]]) < 0:
                    best = f
            if sum(1 for f in found if _profile_less(profiles[f[0]],
                                                     profiles[best[0]]) == 0) > 1:
                why = f"robots {[f[0] for f in found]} tie (no asymmetry is used)"
                break
            found = [best]
        if found:
            chosen = found[0]
    if chosen is None:
        return Decision("stay", (), centre, pat, None,
                        f"corrected: {why} for the nearest robots {tied} ({detail})")
    i, path = chosen
    return Decision("move", (Move(i, path, "leader"),), centre, pat, i, detail)


def _clear_centre(pts, centre, R, d, unit, cands, pat, approx, tower=None):
    """Nobody is at C but two or more robots are within 2 of it: C cannot be taken.  The
    farthest of them from C moves radially out to distance 2 (then it is in layer 1
    once the nearest reaches C).  A tie for the farthest: stay."""
    unit2 = unit * unit
    close = [j for j in R if (d[j] - 4 * unit2).sign() < 0]
    if len(close) < 2:
        return None
    far = max((d[j] for j in close), key=_Key)
    top = [j for j in close if d[j] == far]
    if len(top) > 1 or pts[top[0]] == centre:
        return Decision("stay", (), centre, pat, None,
                        f"corrected: robots {top} tie to clear C")
    j = top[0]
    try:
        target = radial_point(centre, pts[j], 2 * unit, tower)
    except ValueError as err:
        return Decision("undecided", (), centre, pat, None, str(err))
    path = [g.Segment(pts[j], target)]
    if _free(path, pts, j, unit2, approx) and \
            _keeps_centre(path, pts, j, centre, cands, R, pat, approx):
        return Decision("move", (Move(j, tuple(path), "clear"),), centre, pat, None,
                        f"corrected: robot {j} clears C (robots {close} within 2 of it)")
    return Decision("stay", (), centre, pat, None,
                    f"corrected: robot {j} cannot clear C (robots {close} within 2 of it)")


def _first_path(option, pts, centre, cands, R, unit, pat, tied_start, approx, tower=None):
    """The first free path of ``option`` = (dist, robot, target, layer, kind) that keeps
    C, as a tuple of pieces; None.  ``tower``: the snapshot's tower of nested radicals
    (the own-circle path's radius, :func:`_to_slot_paths`)."""
    _dist, i, target, l, kind = option
    unit2 = unit * unit
    if kind == "centre":
        paths = _paths_to_centre(pts[i], centre, pts, i, unit2)
    elif kind == "new-layer":
        paths = iter([[g.Segment(pts[i], target)]])
    else:
        others = [g.dist2(pts[j], centre) for j in R if j != i]
        limit2 = min(others, key=_Key) if others else None
        paths = _to_slot_paths(pts[i], centre, target, l, unit, limit2, tower)
    for path in paths:
        if not path or (tied_start and isinstance(path[0], g.Arc)):
            continue                    # tied at the Look: the first piece must go in (I4)
        if _free(path, pts, i, unit2, approx) and \
                _keeps_centre(path, pts, i, centre, cands, R, pat, approx):
            return tuple(path)
    return None


class _Key:
    """Sort key of exact numbers."""
    __slots__ = ("x",)

    def __init__(self, x):
        self.x = x

    def __lt__(self, other):
        return (self.x - other.x).sign() < 0


def decide_for(algorithm: str):
    """The decision function of ``algorithm`` ("paper" or "corrected")."""
    if algorithm == "corrected":
        return decide_corrected
    if algorithm == "paper":
        return decide
    raise ValueError(f"unknown algorithm {algorithm!r} (choices: {', '.join(ALGORITHMS)})")


decide_corrected.cache_clear = _decide_corrected.cache_clear   # the benchmarks time cold Looks
