"""The corrected variant's paths (``--algorithm corrected``, ``docs/gathering-corrected.md``):
the candidate paths to C and to a slot, the radial points they need, and the clearance
test every path must pass.

**Clearance (no graze).**  A path is *clear* (:func:`path_is_clear`) when every robot
other than the mover stays strictly farther than 2 from every point of it, except that
the final point may touch (distance exactly 2) the robots of ``allowed`` -- the robots of
P next to the mover's slot, or the robots at distance 2 of an empty C.  Before
(issue 31) touching anywhere was allowed: a path to C that grazed a robot B made the
mover and B a two-robot pattern whose centre is not C at that instant (I6), and a Look
there ended in an overlap.  With clearance, two robots come to touch only when a mover
arrives at its target (``proofs/gathering-corrected.md``, lemma "contacts").  Every
final piece is a segment; along a segment the squared distance to a robot is a convex
quadratic, so a touch at the end with no overlap on the segment (``piece_hits`` false)
is a touch at the end only (the quadratic's derivative there is <= 0).

Each path can be found again from any of its points (a fresh Look on the way plans the
same target, I3): ``docs/gathering.md``, "The corrected variant".
"""

from __future__ import annotations

from flint import fmpq

from ..exact.algebraic.run_tower import sqrt_exact
from ..exact.multiquadratic import MQ, sqrt_rational
from . import geometry as g
from .robot import radial_point

#: How far beyond 2l + 2, 2l + 4, 2l + 6 (in robot radii) the detours to a slot turn:
#: the circle of radius exactly 2l + 2 touches every robot of layer l it passes, so a
#: detour on it is never clear; 1/16 keeps it clear of them, as the rational points
#: "less than 1/8 beyond" did before (issue 31), and is the same in every frame.
DETOUR_MARGIN = fmpq(1, 16)

#: tan(angle / 2) of the detour rotations tried, smallest first.
DETOUR_TANGENTS = tuple(fmpq(1, 2 ** k) for k in range(4, -1, -1))


def segment_within(a, b, q, d2) -> bool:
    """Does some point of segment ``ab`` lie at squared distance ``<= d2`` from ``q``
    (touching included; :func:`.geometry.segment_min_dist2_less` is the strict test)?"""
    ab = g.sub(b, a)
    aq = g.sub(q, a)
    t_num = g.dot(aq, ab)
    den = g.dot(ab, ab)
    if den.is_zero() or t_num.sign() <= 0:
        return (g.dist2(a, q) - d2).sign() <= 0
    if (t_num - den).sign() >= 0:
        return (g.dist2(b, q) - d2).sign() <= 0
    return (g.dot(aq, aq) * den - t_num * t_num - d2 * den).sign() <= 0


def arc_within(arc, q, d2) -> bool:
    """Does some point of ``arc`` lie at squared distance ``<= d2`` from ``q``?  The
    nearest point of the circle to ``q`` is its radial projection; the arc holds it when
    it holds that direction (:meth:`.geometry.Arc.contains_direction`), else an end is
    the nearest: (rho - |w|)^2 <= d2 iff r2 + w2 - d2 <= 2 rho |w|."""
    if (g.dist2(arc.start, q) - d2).sign() <= 0 or (g.dist2(arc.end, q) - d2).sign() <= 0:
        return True
    w = g.sub(q, arc.centre)
    if w[0].is_zero() and w[1].is_zero():
        return False
    if not arc.contains_direction(w):
        return False
    r2 = g.dist2(arc.start, arc.centre)
    w2 = g.dot(w, w)
    lhs = r2 + w2 - d2
    if lhs.sign() <= 0:
        return True
    return (lhs * lhs - 4 * r2 * w2).sign() <= 0


def piece_within(piece, q, d2) -> bool:
    if isinstance(piece, g.Segment):
        return segment_within(piece.start, piece.end, q, d2)
    return arc_within(piece, q, d2)


def _filter_radius(unit2) -> float:
    """2 robot radii as a float no smaller than the exact value (rounded up by a relative
    1e-12, far above sqrt's rounding): the filter may only keep too many robots, never
    leave out one the exact test would find within 2."""
    return 2 * float(unit2) ** 0.5 * (1 + 1e-12)


def path_is_clear(pieces, pts, mover, unit2, allowed=frozenset(), approx=None) -> bool:
    """Every robot but the mover stays strictly farther than 2 from the path, except that
    robots of ``allowed`` may touch its final point (and only there: the last piece is a
    segment, see the module docstring).  ``approx`` (:func:`.geometry.approx_points`): a
    certified filter leaves out the robots certainly farther than 2 from a piece."""
    d2 = 4 * unit2
    last = len(pieces) - 1
    for k, piece in enumerate(pieces):
        near = range(len(pts)) if approx is None else \
            g.robots_near_piece(piece, approx, _filter_radius(unit2))
        for j in near:
            if j == mover:
                continue
            q = pts[j]
            if k == last and j in allowed and isinstance(piece, g.Segment) and \
                    g.dist2(piece.end, q) == d2:
                if g.piece_hits(piece, q, d2):
                    return False                 # closer than 2 before the end
                continue                         # convex: touches at the end only
            if piece_within(piece, q, d2):
                return False
    return True


def path_blockers(pieces, pts, mover, unit2, allowed=frozenset(), approx=None) -> set:
    """The robots that make the path not clear (:func:`path_is_clear` asks whether this
    set is empty)."""
    d2 = 4 * unit2
    last = len(pieces) - 1
    out = set()
    for k, piece in enumerate(pieces):
        near = range(len(pts)) if approx is None else \
            g.robots_near_piece(piece, approx, _filter_radius(unit2))
        for j in near:
            if j == mover or j in out:
                continue
            q = pts[j]
            if k == last and j in allowed and isinstance(piece, g.Segment) and \
                    g.dist2(piece.end, q) == d2:
                if g.piece_hits(piece, q, d2):
                    out.add(j)
                continue
            if piece_within(piece, q, d2):
                out.add(j)
    return out


def rotate_about(centre, p, t, sense):
    """``p`` turned about ``centre`` by the rational rotation of half-angle tangent ``t``."""
    den = 1 + t * t
    c, s = (1 - t * t) / den, 2 * t / den
    return g.add(centre, g.rotate(g.sub(p, centre), MQ.rational(c), MQ.rational(s * sense)))


def paths_to_centre(p, centre, pts, mover, unit2):
    """The segment to C, then detours: an arc about C on the mover's circle, then the
    segment (senses away from the robots that block the segment)."""
    yield [g.Segment(p, centre)]
    v = g.sub(p, centre)
    senses = set()
    for j, q in enumerate(pts):
        if j != mover and segment_within(p, centre, q, 4 * unit2) and \
                g.dist2(centre, q) != 4 * unit2:
            side = g.cross(v, g.sub(q, centre)).sign()     # the blocker's side of the ray
            senses.add(-side if side else 0)
    if 0 in senses or len(senses) != 1:
        senses = {1, -1}
    for t in DETOUR_TANGENTS:
        turned = [(sense, rotate_about(centre, p, t, sense)) for sense in senses]
        if len(turned) == 2:
            # both senses: the one whose turned point is farther from its nearest robot
            # first (a choice by distances alone, the same in a mirrored frame); equal:
            # neither (choosing would need a handedness)
            room = [min((g.dist2(q, r) for j, r in enumerate(pts) if j != mover),
                        key=_Key) for _, q in turned]
            c = (room[0] - room[1]).sign()
            if c == 0:
                continue
            if c < 0:
                turned.reverse()
        for sense, q in turned:
            yield g.arc_path(centre, p, q, sense) + [g.Segment(q, centre)]


class _Key:
    __slots__ = ("x",)

    def __init__(self, x):
        self.x = x

    def __lt__(self, other):
        return (self.x - other.x).sign() < 0


def ray_direction(centre, p):
    """The primitive integer direction of the ray from C through ``p`` (the same from
    every point of the ray), or None when C is irrational or the slope is.  Used only to
    *write* the point of layer 1 (:func:`layer_one_point`), whose place does not depend
    on it; never to place a point (issue 31: a radius built from it depends on the
    frame)."""
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


def layer_one_point(centre, p, unit, tower=None):
    """The point of layer 1 on the mover's ray, ``C + 2 unit (p - C) / |p - C|``: the same
    point in every frame (its distance to C is 2 unit, its direction that of the ray).
    Written with the ray's integer direction when it has one (its square root is then
    that of a rational, whatever ``|p - C|^2`` is), else by its radius (a nested radical
    when ``|p - C|^2`` is irrational: a point of the snapshot's ``tower``,
    :func:`.robot.radial_point`)."""
    e = ray_direction(centre, p)
    if e is None:
        return radial_point(centre, p, 2 * unit, tower)
    k = sqrt_rational(fmpq(1, e[0] * e[0] + e[1] * e[1])) * (2 * unit)
    return (centre[0] + k * e[0], centre[1] + k * e[1])


def ray_point(centre, p, h, rho):
    """The point of the ray from C through ``p`` at distance exactly ``h`` from C (``rho
    = |p - C|``, exact): ``C + (p - C) h / rho``.  Found alike from every point of the
    ray and in every frame (a distance and a direction; issue 31: the earlier rational
    point just beyond h, built from the ray's integer direction in the observer's
    coordinates, had a radius that changed with the frame)."""
    return g.add(centre, g.scale(g.sub(p, centre), h / rho))


def tie_senses(p, centre, target, pts, mover):
    """The senses of the arcs from ``p`` to the target's ray when that ray is opposite
    to the mover's (both ways equally long: choosing by the observer's clockwise would be
    a handedness): the sense whose quarter point ``Q = C + sense * quarter(p - C)``
    (scaled to the target's radius) has the lexicographically larger sorted squared
    distances to the other robots first -- a choice by distances alone, the same in a
    mirrored frame; equal: none (no handedness is used)."""
    w = g.sub(target, centre)
    keys = {}
    for sense in (1, -1):
        # quarter(p - C, sense) has the direction of -quarter(w, sense): p is opposite
        q = g.sub(centre, g.quarter(w, sense))
        keys[sense] = sorted((g.dist2(q, r) for j, r in enumerate(pts) if j != mover),
                             key=_Key)
    c = 0
    for x, y in zip(keys[1], keys[-1]):
        c = (x - y).sign()
        if c:
            break
    if c == 0:
        return ()
    return (1, -1) if c > 0 else (-1, 1)


def to_slot_paths(p, centre, target, l, unit, limit2=None, tower=None, pts=None,
                  mover=None, long_way=False):
    """Paths to a point of layer l (``|target - C| = 2l unit``) that the mover finds
    again from any point of them (so a fresh Look on the way plans the same target):

    * on the target's ray: the segment;
    * along the mover's own circle about C, the shorter way, to the target's ray, then
      radially in (the radius a nested radical when ``|p - C|^2`` is a square in no
      multiquadratic field: a number of ``tower`` or of a new run tower); left out only
      when that root cannot be built (the kernel's limits);
    * for h = 2l + 2, 2l + 4, 2l + 6 with h^2 < ``limit2`` (the squared distance of R's
      next robot to C: the mover stays the nearest): radially in to the point of the
      mover's ray at distance h + 1/16 (:data:`DETOUR_MARGIN` robot radii beyond h,
      :func:`ray_point`), along that circle to the target's ray, radially in; then the
      segment to the target's ray at radius h and radially in;
    * the segment to the target.

    Every point and radius is built from distances and directions from C, so the paths
    are the same in every frame (issue 31).  The arcs go the shorter way (the sign of
    ``cross(v, w)``, which a reflection flips together with the arcs' sense); when the
    target's ray is opposite to the mover's both ways are equally long, and the order of
    the two senses is :func:`tie_senses`'s (distances only; none on a tie, and none
    without ``pts``).  ``long_way`` (the end was chosen by static tests, not by angle):
    after the shorter arc on the mover's own circle, the longer one (the rest of it is
    found again from every point: before the target's antipodal ray as the longer way,
    after it as the shorter).  The mover's distance to C stays below ``limit2`` along
    them (I4)."""
    v = g.sub(p, centre)
    w = g.sub(target, centre)                          # |w| = 2l unit
    if g.cross(v, w).is_zero() and g.dot(v, w).sign() > 0:
        yield [g.Segment(p, target)]                   # already on the target's ray
        return
    side = g.cross(v, w).sign()
    if side:
        senses = (side,)
    elif pts is None:
        senses = ()
    else:
        senses = tie_senses(p, centre, target, pts, mover)
    r2 = g.dot(v, v)
    two_l = 2 * l * unit
    rho = radius_of(r2, tower)
    if rho is not None:
        b = g.add(centre, g.scale(w, rho / two_l))
        for sense in senses:
            yield g.arc_path(centre, p, b, sense) + [g.Segment(b, target)]
        if long_way and side:
            yield g.arc_path(centre, p, b, -side) + [g.Segment(b, target)]
    for h in (two_l + 2 * unit, two_l + 4 * unit, two_l + 6 * unit):
        if limit2 is not None and (limit2 - h * h).sign() <= 0:
            continue            # I4: the mover stays strictly nearer to C than R's others
        hd = h + DETOUR_MARGIN * unit   # beyond h: a circle of radius 2l + 2 touches layer l
        if rho is not None and (r2 - hd * hd).sign() >= 0:
            a = ray_point(centre, p, hd, rho)
            b = g.add(centre, g.scale(w, fmpq(hd) / two_l))
            for sense in senses:
                pieces = ([g.Segment(p, a)] if a != p else []) + \
                    g.arc_path(centre, a, b, sense)
                yield pieces + [g.Segment(b, target)]
        b = g.add(centre, g.scale(w, fmpq(h) / two_l))
        yield [g.Segment(p, b), g.Segment(b, target)]
    yield [g.Segment(p, target)]


def radius_of(r2, tower):
    """The non-negative root of the squared radius ``r2``: rational, multiquadratic or
    nested (``tower``'s); None when the kernel cannot build it."""
    if r2.is_rational():
        return sqrt_rational(r2.to_fmpq())
    try:
        return sqrt_exact(r2, tower)
    except ValueError:
        return None


def outward_point(centre, p, r2_to, tower=None):
    """The point of the ray from C through ``p`` at squared distance ``r2_to`` from C
    (the symmetry-avoiding move of ``corrected.decide_corrected``: out to the next
    robot's distance); None when the kernel cannot build the roots."""
    v = g.sub(p, centre)
    # one root of the ratio: two roots built apart (no run tower) lie in two fields
    ratio = radius_of(r2_to / g.dot(v, v), tower)
    if ratio is None:
        return None
    return g.add(centre, g.scale(v, ratio))


#: The via points of :func:`slot_approach_paths`: ``(k, t)``, the slot plus ``k`` times the
#: outward vector turned by the rational rotation of half-angle tangent ``t`` (0: not
#: turned); nearest to the slot and least turned first.
VIA_POINTS = tuple((k, t) for k in (fmpq(1, 4), fmpq(1, 2))
                   for t in (fmpq(0), fmpq(1, 4), fmpq(1, 2)))


def slot_approach_paths(p, centre, target, pts, mover, unit2, limit2=None, other=None):
    """Two-segment paths to a slot through a *via point* beside it (issue 31,
    ``corrected-blocked-slots-stall``: the slot lies in a gap between a robot of P and a
    robot of R that every path of :func:`to_slot_paths` grazes).  The slot touches the
    robots of P next to it; ``u``, the sum of the vectors from them to the slot, points
    out of the free cone's middle.  The via points are ``target + k u`` turned about the
    slot by the rational rotations of :data:`VIA_POINTS` in both senses (the sense with
    more room at its via point first -- the sorted squared distances to the other
    robots, lexicographically larger; equal: neither: the sorted squared distances compared lexicographically), each kept only when it is nearer to C than R's next robot (``limit2``:
    the mover stays the nearest, I4; a segment's squared distance to C is convex).
    Every via point is built from the slot and the robots that touch it, which stand
    still, so the same points are offered from every point of the mover's way and in
    every frame (a reflection maps the two senses onto each other with their rooms).
    ``other``: the chain's other end, when the end is chosen by angle -- a via point is
    kept only when it is strictly nearer in angle to ``target`` (``(q - C).(target -
    other) > 0``, an open half-plane through C that holds the mover and the slot, so
    both segments stay in it and a Look on the way picks the same end)."""
    d2 = 4 * unit2
    touch = [q for j, q in enumerate(pts) if j != mover and g.dist2(q, target) == d2]
    if not touch:
        return
    u = g.sub(target, touch[0])
    for q in touch[1:]:
        u = g.add(u, g.sub(target, q))
    if u[0].is_zero() and u[1].is_zero():
        return
    seen = []
    for k, t in VIA_POINTS:
        vec = g.scale(u, k)
        if t == 0:
            turned = [g.add(target, vec)]
        else:
            turned = [rotate_about(target, g.add(target, vec), t, s) for s in (1, -1)]
            # the robots touching the slot are placed alike about u: compare the whole
            # sorted squared distances to the other robots, lexicographically
            room = [sorted((g.dist2(q, r) for j, r in enumerate(pts) if j != mover),
                           key=_Key) for q in turned]
            c = next(((x - y).sign() for x, y in zip(*room) if (x - y).sign()), 0)
            if c == 0:
                continue
            if c < 0:
                turned.reverse()
        for q in turned:
            if limit2 is not None and (g.dist2(q, centre) - limit2).sign() >= 0:
                continue
            if other is not None and \
                    g.dot(g.sub(q, centre), g.sub(target, other)).sign() <= 0:
                continue
            if q == p or q in seen:
                continue
            seen.append(q)
            yield [g.Segment(p, q), g.Segment(q, target)]


def _ccw_before(a, b, c) -> bool:
    """Is direction ``c`` in the closed counter-clockwise arc from direction ``a`` to
    direction ``b`` (all non-zero vectors; exact signs of cross and dot products)?"""
    def half(v):
        x = g.cross(a, v).sign()
        return 0 if x > 0 or (x == 0 and g.dot(a, v).sign() > 0) else 1
    hb, hc = half(b), half(c)
    if g.cross(a, c).is_zero() and g.dot(a, c).sign() > 0:
        return True                                   # c is a's direction
    if hc != hb:
        return hc < hb
    return g.cross(c, b).sign() >= 0


def spokes(centre, pts, mover, unit, limit2):
    """The directions from C of the robots that wall C's neighbourhood off radially
    (issue 31, ``corrected-roots-12-five-stall``): a robot q other than the mover with
    ``|q - C| <= 4`` and ``|q - C| + 2 > L`` (``L^2 = limit2``, the squared distance of
    R's next robot: a leader path stays nearer to C than L).  The closed discs of radius 2
    about the robot at C and about q cover q's ray from C out to ``|q - C| + 2``, so a
    mover that keeps clear of every robot and nearer to C than L never crosses that ray.
    Exact: squared distances only.  None of them without an L (the last robot of R)."""
    out = []
    if limit2 is None:
        return out
    for j, q in enumerate(pts):
        if j == mover:
            continue
        d2 = g.dist2(q, centre)
        if d2.is_zero() or (d2 - 16 * unit * unit).sign() > 0:
            continue
        if (limit2 - d2).sign() > 0:
            # |q - C| + 2 > L  iff  L^2 - d^2 - 4 < 4 d  (d = |q - C|, both sides >= 0)
            lhs = limit2 - d2 - 4 * unit * unit
            if lhs.sign() >= 0 and (lhs * lhs - 16 * unit * unit * d2).sign() >= 0:
                continue
        out.append(g.sub(q, centre))
    return out


def walled_off(p, centre, target, walls) -> bool:
    """Are ``p`` and ``target`` separated by the spokes ``walls`` (:func:`spokes`) on both
    ways round C?  Read from the directions only, with no sense preferred (both arcs are
    asked), so the answer is the same in a mirrored frame; and it does not change while
    the mover keeps clear and nearer to C than L, since its direction from C then never
    crosses a spoke."""
    a, b = g.sub(p, centre), g.sub(target, centre)
    ccw = any(_ccw_before(a, b, w) for w in walls)
    cw = any(_ccw_before(b, a, w) for w in walls)
    return ccw and cw
