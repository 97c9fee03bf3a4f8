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
   free slot next to an end of layer l's chain: while P has at most 4 robots, an end
   that spokes wall off (:func:`.corrected_paths.walled_off`) is out of reach; else the one
   whose completion keeps C (the centre rule run on the configuration after the
   arrival) and a leader when only one does, else the one farther from the robots of R
   that stay (so the centre stays unique in f), else the one nearer to the mover in
   angle (the larger dot product; a tie: stay).  Robots
   within 2 of an empty C other than the nearest: the farthest of them first moves
   radially out to distance 2 (C cannot be taken while two robots are that close).
5. **Clear paths** (:mod:`.corrected_paths`; distances to C never grow, so I4 holds
   along the path): to C the segment, or a detour (an arc about C on the mover's circle
   by a rational rotation, then the segment); to a point of a layer the paths of
   :func:`.corrected_paths.to_slot_paths` (with the longer arc when the end was chosen
   by static tests) and the via-point approaches (:func:`_approaches`), each of which a
   fresh Look finds again from any of its points.  A path is taken only when it is clear
   (:func:`.corrected_paths.path_is_clear`): every other robot strictly farther than 2
   from every point, except that the final point may touch robots of P (or, for the
   target C, the robots at distance 2 of it) -- so two robots come to touch only at an
   arrival, and no graze makes a transient pattern whose centre is not C (issue 31).
   The first clear path that keeps C is taken; none: stay.
6. **Never into a symmetric configuration** (:mod:`.corrected_choice`): a move whose
   completion the ground truth finds symmetric while robots are left to move is not
   made (decided before any path, by the target and the robots that stand still: the
   same all along the move).  When the nearest robot alone is so blocked it steps
   aside: radially out to the distance of R's next robot (role ``asym``), where the
   tie-break leaves it out.
7. **The final robots**: no leader election at all -- the rule above is the same for
   two or three robots left as for many (nearest to C, ties by the slot geometry), so
   an asymmetric triangle of three (where the paper's Elect_Leader_Asym elects nobody)
   is no obstacle.

Under ``lone=reject`` (Def. 1 read literally) the moves are those of ``lone=accept``,
the two that start a layer with the role ``layer-start`` (:func:`_literal`).

8. **A D1 start with a leader on the mirror** (:mod:`.corrected_mirror`): when nothing
   above names a move, the leader goes in along the mirror and steps off it.

What it does not handle (``docs/gathering-corrected.md``): exact ties that only a
handedness could break (a tie of the centre rule; several nearest robots all of whose
moves end symmetric), a path blocked with no alternative, a symmetric start.
"""

from __future__ import annotations

from dataclasses import replace
from functools import lru_cache
from itertools import chain

from flint import fmpq

from . import geometry as g
from .corrected_choice import SortKey, distinct_after, ground_ranks, keeps_a_leader, \
    literal_pattern_exists, mirror_leader, no_leader, profile, profile_compare
from .corrected_mirror import mirror_step
from .corrected_paths import layer_one_point, outward_point, path_blockers, \
    path_is_clear, paths_to_centre, piece_within, slot_approach_paths, spokes, \
    to_slot_paths, walled_off
from .pattern import Pattern, capacity, recognise, slot
from .robot import Decision, Move, Readings, decide, radial_point
from .run_home import snapshot_key

ALGORITHMS = ("paper", "corrected")

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
    # the candidate at the SEC centre of all: the first robot went there (M = 1 above),
    # and the SEC stays while the robots that fix it stand still (they are the farthest
    # from C, and move last)
    sec, _ = g.smallest_enclosing_circle(list(pts))
    at_sec = [k for k in cands if pts[k] == sec]
    if at_sec:
        k = at_sec[0]
        return pts[k], sizes[k], tuple(cands), (f"C: robot {k}, at the SEC centre, the "
                                                f"centre of {M} robots")
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


def _keeps_centre(pieces, pts, mover, centre, cands, R, pat, approx=None, readings=None,
                  unit=fmpq(1)) -> bool:
    """C cannot change while ``mover`` follows ``pieces``, nor at its arrival (point 3
    of the module docstring).  ``cands`` empty (M = 1): the SEC must not need the
    mover."""
    stay = [j for j in R if j != mover]
    if cands:
        # C is the robot at the SEC centre and the mover is no support of the SEC: its
        # path (distance to C never above the SEC radius) leaves the SEC, hence C, as is
        sec, r2 = g.smallest_enclosing_circle(list(pts))
        if sec == centre and (g.dist2(pts[mover], centre) - r2).sign() < 0 and \
                all((g.dist2(p.final, centre) - r2).sign() <= 0 for p in pieces):
            return True
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
    # on arrival the pattern has at most 4 robots: its centre must still be C there
    # (every candidate's farthest robot outside its pattern, exactly, after the arrival)
    target = pieces[-1].final
    small = pat.centre_robot is not None and len(pat.robots) + 1 <= 4
    if small and stay and readings is not None and \
            not _arrival_keeps_centre(pts, mover, target, centre, readings, unit):
        return False
    others = [k for k in cands if pts[k] != centre]
    # f(C) along the way: at most fc and the mover's largest distance to C (at the end
    # points of its pieces: arcs about C keep it, along a segment it is convex)
    top = fc
    for piece in pieces:
        for q in (piece.start, piece.final):
            if (g.dist2(q, centre) - top).sign() > 0:
                top = g.dist2(q, centre)
    for k, where in [(k, pts[k]) for k in others]:
        fk = _far2(pts, where, stay, approx)
        if fk is not None and (fk - top).sign() > 0:
            continue
        if stay:
            # the mover is outside k's pattern until it arrives: f(k) is at least its
            # distance to k, which stays above every value f(C) takes
            if any(piece_within(piece, where, top) for piece in pieces):
                return False
            continue
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


def _arrival_keeps_centre(pts, mover, target, centre, readings, unit) -> bool:
    """With ``mover`` at ``target`` and the others where they are, is C still the centre
    the rule of :func:`choose_centre` names?  (Read only from the target and the robots
    that stand still: the same answer from every point of the mover's way.)"""
    after = list(pts)
    after[mover] = target
    got = choose_centre(after, readings if readings is not None else Readings(), unit,
                        g.approx_points(after))[0]
    return got is not None and got == centre


def _target(p, centre, pat, pts, unit, stay, tower=None, mover=None, readings=None):
    """``(target, layer, kind)``: C, a new layer's radial point, or a chain end's slot;
    target None on an exact tie.  The slot: while the pattern has at most 4 robots (its
    centre is not unique), the end whose completion keeps C and a leader when exactly
    one does (``mover`` given; both tests read the slot and the robots that stand still
    only), else the end farther from the robots that stay (so that C stays the centre
    when the SEC moves at the end), then the nearer in angle.  Larger patterns: the
    nearer in angle (the larger dot product with the mover's direction, monotone along
    its paths)."""
    if pat.centre_robot is None:
        return centre, 0, "centre"
    l = pat.last_layer
    v = g.sub(p, centre)
    if pat.last_full():
        if l == 0:
            return layer_one_point(centre, p, unit, tower), 1, "new-layer"
        # a lone robot starts layer l + 1 on the ray of the robot of layer l nearest in
        # angle (a point that does not depend on where the mover is on its way)
        ring = pat.layers[-1]
        dots = [(g.dot(v, g.sub(pts[k], centre)), k) for k in ring]
        top = max((d for d, _ in dots), key=SortKey)
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
        ends = (s_ccw, s_cw)
        # an end that spokes wall off from the mover on both ways round C is out of
        # reach (corrected_paths.spokes: static, so the same from every point of the way)
        limit2 = min((g.dist2(pts[j], centre) for j in stay), key=SortKey)
        walls = spokes(centre, pts, mover, unit, limit2) if mover is not None else []
        open_ends = [s for s in ends if not walled_off(p, centre, s, walls)]
        if len(open_ends) == 1:
            return open_ends[0], l, "slot-fixed"
        if mover is not None:
            # the ends whose completion keeps C and a leader (both read the target and
            # the robots that stand still only): a choice every point of the way repeats
            fine = [s for s in ends if _arrival_keeps_centre(pts, mover, s, centre,
                                                             readings, unit)
                    and keeps_a_leader(pts, mover, s)]
            if len(fine) == 1:
                return fine[0], l, "slot-fixed"
        c = (_far2(pts, s_ccw, stay) - _far2(pts, s_cw, stay)).sign()
        if c:
            return (s_ccw if c > 0 else s_cw), l, "slot-fixed"
    a, b = g.dot(v, g.sub(s_ccw, centre)), g.dot(v, g.sub(s_cw, centre))
    c = (a - b).sign()
    if c == 0:
        return None, l, "slot"
    return (s_ccw if c > 0 else s_cw), l, "slot"


def decide_corrected(snapshot: tuple, readings: Readings = Readings(), unit=fmpq(1)) -> Decision:
    """The corrected algorithm's decision on one snapshot (see the module docstring).  As
    :func:`.robot.decide`: a snapshot whose coordinates come from several towers of
    nested radicals is first re-homed into one (:func:`.run_home.common_tower`), a
    radial target whose distance is a nested radical is built in that tower
    (:func:`.robot.radial_point`), and decisions are cached per snapshot and per tower
    (numbers of two towers are never compared, not even as cache keys)."""
    if readings.lone == "reject":
        return _literal(snapshot, readings, unit)
    return _decide_corrected(snapshot_key(snapshot), readings, unit)


def _literal(snapshot, readings, unit) -> Decision:
    """The decision under ``lone=reject``.  The variant builds the same layers as under
    ``lone=accept`` -- one robot at a time, so the first robot of a layer is alone in it
    until the next arrives beside it, a state the literal reading calls no pattern -- and
    its P is that bookkeeping pattern; the gathered state is a literal pattern (a chain
    of two or more in the last layer) for every n but 8, 20, 38, ..., where the answer
    is ``not-possible`` with that reason.  A move that starts a layer alone has the role
    ``layer-start``, and so has the next move, which puts a robot beside it (the literal
    P grows by both at that arrival); the pattern reported is the literal one, so the
    robot alone in its layer is in R meanwhile (``docs/gathering-corrected.md``)."""
    pts = list(snapshot)
    d = _decide_corrected(snapshot_key(snapshot), replace(readings, lone="accept"), unit)
    if not literal_pattern_exists(len(pts)):
        return Decision("not-possible", (), d.centre, d.pattern, None,
                        f"corrected: Definition 1 read literally (lone=reject) has no "
                        f"pattern of {len(pts)} robots (one more than a robot at C and "
                        f"full layers: the last robot would be alone in its layer; "
                        f"docs/gathering-corrected.md)")
    if d.centre is None:
        return d
    literal = recognise(pts, d.centre, "reject", unit)
    waiting = literal.robots != d.pattern.robots        # a robot alone in its layer
    moves = []
    for m in d.moves:
        after = list(pts)
        after[m.robot] = m.path[-1].final
        alone = m.robot not in recognise(after, d.centre, "reject", unit).robots
        moves.append(replace(m, role="layer-start")
                     if m.role == "leader" and (alone or waiting) else m)
    return replace(d, moves=tuple(moves), pattern=literal)


@lru_cache(maxsize=4096)
def _decide_corrected(key: tuple, readings: Readings, unit) -> Decision:
    """The plain rule (:func:`_decide_plain`); when it names no move on a start with a
    mirror and a leader, the leader's step (:func:`.corrected_mirror.mirror_step`)."""
    d = _decide_plain(key, readings, unit)
    if d.status not in ("stay", "not-possible") or d.centre is None:
        return d
    towers, _epochs, snapshot = key
    tower = towers[0] if towers else None
    pts = list(snapshot)
    approx = g.approx_points(pts)
    centre, pat, cands, _detail = choose_centre(pts, readings, unit, approx)
    if centre is None:
        return d
    R = [i for i in range(len(pts)) if i not in pat.robots]
    step = mirror_step(
        pts, centre, pat, R, unit, approx, tower, readings,
        lambda after: _decide_plain(snapshot_key(tuple(after)), readings, unit),
        lambda path, m: _keeps_centre(path, pts, m, centre, cands, R, pat, approx,
                                      readings, unit))
    return d if step is None else step


@lru_cache(maxsize=4096)
def _decide_plain(key: tuple, readings: Readings, unit) -> Decision:
    # key: run_home.snapshot_key (towers and epochs first)
    towers, _epochs, snapshot = key
    tower = towers[0] if towers else None
    pts = list(snapshot)
    approx = g.approx_points(pts)
    centre, pat, cands, detail = choose_centre(pts, readings, unit, approx)
    if centre is None:
        sec, _ = g.smallest_enclosing_circle(pts)
        return _stay(pts, sec, recognise(pts, sec, readings.lone, unit), detail)
    members = pat.robots
    R = [i for i in range(len(pts)) if i not in members]
    if not R:
        return Decision("terminated", (), centre, pat, None, "R is empty")
    d = {i: g.dist2(pts[i], centre) for i in R}
    if pat.centre_robot is None:
        clear = _clear_centre(pts, centre, R, d, unit, cands, pat, approx, tower, readings)
        if clear is not None:
            return clear
    near = min(d.values(), key=SortKey)
    tied = [i for i in R if d[i] == near]
    sec, rho2 = g.smallest_enclosing_circle(pts)
    # C kept by the SEC for a mover strictly inside it (corrected._keeps_centre)
    inside = {i: sec == centre and (d[i] - rho2).sign() < 0 for i in R}
    options = []
    try:
        for i in tied:
            stay = [j for j in R if j != i]
            target, l, kind = _target(pts[i], centre, pat, pts, unit, stay, tower, i,
                                      readings)
            if target is not None:
                options.append((g.dist2(pts[i], target), i, target, l, kind))
    except ValueError as err:           # a radial point the field cannot hold
        return Decision("undecided", (), centre, pat, None, str(err))
    options.sort(key=lambda o: SortKey(o[0]))
    # never into a symmetric configuration while robots are left to move
    # (corrected_choice.keeps_a_leader): decided before any path, by the target alone
    blocked = []
    if len(R) > 1:
        kept = []
        for o in options:
            leader = keeps_a_leader(pts, o[1], o[2])
            if leader is None:
                return Decision("undecided", (), centre, pat, None,
                                "corrected: the symmetry test cannot hold the numbers")
            (kept if leader else blocked).append(o)
        options = kept
    chosen, why = None, "a tie" if tied and not options else "no clear path that keeps C"
    k = 0
    while k < len(options) and chosen is None:
        group = [o for o in options[k:] if o[0] == options[k][0]]
        k += len(group)
        found = [(o[1], p) for o in group
                 if (p := _first_path(o, pts, centre, cands, R, unit, pat,
                                      len(tied) > 1, approx, tower, readings)) is not None]
        if len(found) > 1:
            # the smallest profile of distances to the others; equal profiles: stay
            # ... preferring a mover after whose move the robots left in R still have
            # pairwise different profiles (ties can still be broken then)
            breakable = [f for f in found if distinct_after(pts, f, R)]
            found = breakable or found
            profiles = {f[0]: profile(pts, f[0]) for f in found}
            best = found[0]
            for f in found[1:]:
                if profile_compare(profiles[f[0]], profiles[best[0]]) < 0:
                    best = f
            level = [f for f in found if profile_compare(profiles[f[0]],
                                                         profiles[best[0]]) == 0]
            if len(level) > 1:
                # equal profiles on a configuration with a leader: the ground truth's
                # canonical order (the same in every frame); none: no asymmetry to use
                ranks = ground_ranks(pts)
                if ranks is None:
                    why = f"robots {[f[0] for f in found]} tie (no asymmetry is used)"
                    break
                best = min(level, key=lambda f: ranks[f[0]])
            found = [best]
        if found:
            chosen = found[0]
    if chosen is None and blocked and len(tied) == 1:
        return _step_aside(pts, centre, tied[0], R, d, unit, cands, pat, approx, tower,
                           detail, readings)
    if chosen is None and len(tied) == 1 and len(options) == 1 and inside[tied[0]] and \
            len(pat.robots) > 4:
        around = _around_blocked(options[0], pts, centre, R, d, unit, cands, pat, approx,
                                 tower, inside, detail, readings)
        if around is not None:
            return around
    if chosen is None:
        if blocked:
            why = (f"every move of robots {sorted(o[1] for o in blocked)} ends in a "
                   f"symmetric configuration; {why}")
        return _stay(pts, centre, pat,
                     f"corrected: {why} for the nearest robots {tied} ({detail})")
    i, path = chosen
    return Decision("move", (Move(i, path, "leader"),), centre, pat, i, detail)


def _stay(pts, centre, pat, why):
    """No move: ``stay``, or ``not-possible`` when the ground truth finds the snapshot
    symmetric (no leader: the tie that stops the variant is one of a symmetry, which no
    algorithm without chirality breaks against an adversary that activates symmetric
    robots together; ``docs/gathering-corrected.md``); on D1 with a leader on the mirror
    that step 11 cannot move, the detail names the leader instead."""
    group = no_leader(pts)
    if group is not None:
        lead = mirror_leader(pts)
        if lead is not None:    # D1 with a robot on the mirror: the truth has a leader
            return Decision("not-possible", (), centre, pat, None,
                            f"no rule of the corrected variant applies: the configuration "
                            f"has the symmetry group {group} with leader robot {lead} on "
                            f"the mirror (ground truth), and step 11 finds no step for it; "
                            f"{why}")
        return Decision("not-possible", (), centre, pat, None,
                        f"no leader: the configuration has the symmetry group {group} "
                        f"(ground truth); {why}")
    return Decision("stay", (), centre, pat, None, why)


def _step_aside(pts, centre, m, R, d, unit, cands, pat, approx, tower, detail,
                readings=None):
    """The nearest robot ``m`` alone, and its move ends in a symmetric configuration: it
    moves radially out to the distance of R's next robot (role ``asym``), where it ties
    with that robot and the tie-break leaves it out (its target, hence the symmetric
    completion, is the same from every point of its ray).  Stay when the way out is not
    clear or does not keep C."""
    rest = [d[j] for j in R if j != m]
    nxt = min(rest, key=SortKey)
    target = outward_point(centre, pts[m], nxt, tower)
    if target is None:
        return Decision("undecided", (), centre, pat, None,
                        "corrected: the kernel cannot build the way out")
    path = (g.Segment(pts[m], target),)
    if path_is_clear(path, pts, m, unit * unit, frozenset(), approx) and \
            _keeps_centre(path, pts, m, centre, cands, R, pat, approx, readings, unit) and \
            keeps_a_leader(pts, m, target):
        return Decision("move", (Move(m, path, "asym"),), centre, pat, None,
                        f"corrected: robot {m}'s move would end in a symmetric "
                        f"configuration; it moves out to the next robot's distance ({detail})")
    return _stay(pts, centre, pat, f"corrected: robot {m}'s move would end in a symmetric "
                                   f"configuration and its way out is not clear ({detail})")


def _around_blocked(option, pts, centre, R, d, unit, cands, pat, approx, tower, inside,
                    detail, readings=None):
    """The nearest robot m alone has a target but every path of its list (all of them,
    whatever its rank among R) comes within 2 of some robot: the nearest robot x of R
    that blocks none of m's paths moves instead (role ``asym``), when its own path is
    clear, keeps C and ends with a leader.  m's paths stay blocked while x moves (their
    blockers stand still), and x stays the nearest such robot, so a fresh Look on x's
    way plans x again; once x is the nearest of R it is planned as the leader, to the
    same target.  None when there is no such x (or it has no clear path)."""
    _dist, m, target, l, kind = option
    unit2 = unit * unit
    if kind == "centre":
        paths = list(paths_to_centre(pts[m], centre, pts, m, unit2))
        allowed = frozenset(j for j in R if j != m and g.dist2(pts[j], centre) == 4 * unit2)
    elif kind == "new-layer":
        paths = [[g.Segment(pts[m], target)]]
        allowed = pat.robots
    else:
        paths = list(to_slot_paths(pts[m], centre, target, l, unit, None, tower, pts, m)) + \
            _approaches(pts[m], centre, target, pat, pts, m, unit2)
        allowed = pat.robots
    blockers = set()
    for path in paths:
        by = path_blockers(path, pts, m, unit2, allowed, approx)
        if not by:
            return None                 # blocked by keeping C only: no stable choice
        blockers |= by
    free = [j for j in R if j != m and j not in blockers]
    if not free:
        return None
    near = min((d[j] for j in free), key=SortKey)
    first = [j for j in free if d[j] == near]
    if len(first) != 1:
        return None
    x = first[0]
    if not inside[x]:
        return None                     # x would move the SEC, hence C
    stay = [j for j in R if j != x]
    try:
        t, lx, kx = _target(pts[x], centre, pat, pts, unit, stay, tower, x, readings)
    except ValueError:
        return None
    if t is None or not keeps_a_leader(pts, x, t):
        return None
    path = _first_path((None, x, t, lx, kx), pts, centre, cands, R, unit, pat, False, approx,
                       tower, readings)
    if path is None:
        return None
    return Decision("move", (Move(x, path, "asym"),), centre, pat, None,
                    f"corrected: every path of the nearest robot {m} is blocked; robot {x}, "
                    f"the nearest robot blocking none of them, moves ({detail})")


def _clear_centre(pts, centre, R, d, unit, cands, pat, approx, tower=None, readings=None):
    """Nobody is at C but two or more robots are within 2 of it: C cannot be taken.  The
    farthest of them from C moves radially out to distance 2 (then it is in layer 1
    once the nearest reaches C).  A tie for the farthest: the smallest distance profile;
    equal profiles: stay."""
    unit2 = unit * unit
    close = [j for j in R if (d[j] - 4 * unit2).sign() < 0]
    if len(close) < 2:
        return None
    far = max((d[j] for j in close), key=SortKey)
    top = [j for j in close if d[j] == far]
    if len(top) > 1:
        # the smallest distance profile (no handedness; once it moves out it is the
        # farthest alone); equal profiles: no choice
        profiles = {j: profile(pts, j) for j in top}
        least = top[0]
        for j in top[1:]:
            if profile_compare(profiles[j], profiles[least]) < 0:
                least = j
        if sum(1 for j in top if profile_compare(profiles[j], profiles[least]) == 0) > 1:
            return _stay(pts, centre, pat, f"corrected: robots {top} tie to clear C")
        top = [least]
    if pts[top[0]] == centre:
        return _stay(pts, centre, pat, f"corrected: robots {top} tie to clear C")
    j = top[0]
    try:
        target = radial_point(centre, pts[j], 2 * unit, tower)
    except ValueError as err:
        return Decision("undecided", (), centre, pat, None, str(err))
    path = [g.Segment(pts[j], target)]
    if path_is_clear(path, pts, j, unit2, frozenset(), approx) and \
            _keeps_centre(path, pts, j, centre, cands, R, pat, approx, readings, unit) and \
            keeps_a_leader(pts, j, target):
        return Decision("move", (Move(j, tuple(path), "clear"),), centre, pat, None,
                        f"corrected: robot {j} clears C (robots {close} within 2 of it)")
    return _stay(pts, centre, pat,
                 f"corrected: robot {j} cannot clear C (robots {close} within 2 of it)")


def _approaches(p, centre, target, pat, pts, mover, unit2, limit2=None):
    """The via-point approaches (:func:`.corrected_paths.slot_approach_paths`) to a chain
    end's slot, kept strictly nearer in angle to it than to the other end; none to the
    point that starts a new layer (chosen by the nearest robot in angle, which a via
    point could change)."""
    if pat.last_full():
        return []
    l, chain_ = pat.last_layer, pat.layers[-1]
    ends = (slot(centre, pts[chain_[-1]], l, 1), slot(centre, pts[chain_[0]], l, -1))
    other = next((s for s in ends if s != target), None)
    return list(slot_approach_paths(p, centre, target, pts, mover, unit2, limit2, other))


def _first_path(option, pts, centre, cands, R, unit, pat, tied_start, approx, tower=None,
                readings=None):
    """The first clear path of ``option`` = (dist, robot, target, layer, kind) that keeps
    C, as a tuple of pieces; None.  Clear (:func:`.corrected_paths.path_is_clear`): no
    robot within 2 anywhere, except that the final point may touch the robots of P (a
    slot) or the robots at distance 2 of an empty C (the target C)."""
    _dist, i, target, l, kind = option
    unit2 = unit * unit
    if kind == "centre":
        paths = paths_to_centre(pts[i], centre, pts, i, unit2)
        allowed = frozenset(j for j in R if j != i and g.dist2(pts[j], centre) == 4 * unit2)
    elif kind == "new-layer":
        paths = iter([[g.Segment(pts[i], target)]])
        allowed = pat.robots
    else:
        others = [g.dist2(pts[j], centre) for j in R if j != i]
        limit2 = min(others, key=SortKey) if others else None
        paths = chain(to_slot_paths(pts[i], centre, target, l, unit, limit2, tower, pts, i,
                                    kind == "slot-fixed"),
                      _approaches(pts[i], centre, target, pat, pts, i, unit2, limit2))
        allowed = pat.robots
    for path in paths:
        if not path or (tied_start and isinstance(path[0], g.Arc)):
            continue                    # tied at the Look: the first piece must go in (I4)
        if path_is_clear(path, pts, i, unit2, allowed, approx) and \
                _keeps_centre(path, pts, i, centre, cands, R, pat, approx, readings, unit):
            return tuple(path)
    return None



def decide_for(algorithm: str):
    """The decision function of ``algorithm`` ("paper" or "corrected")."""
    if algorithm == "corrected":
        return decide_corrected
    if algorithm == "paper":
        return decide
    raise ValueError(f"unknown algorithm {algorithm!r} (choices: {', '.join(ALGORITHMS)})")


def _cache_clear():
    _decide_corrected.cache_clear()
    _decide_plain.cache_clear()


decide_corrected.cache_clear = _cache_clear   # the benchmarks time cold Looks
