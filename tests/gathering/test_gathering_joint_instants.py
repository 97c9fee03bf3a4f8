"""The critical instants of a joint step that exactsym.gathering.joint_symmetry adds
(a symmetry of the robots can appear while several robots move at once), the rays and
ties about R's SEC centre, and I9 at the SEC and symmetry instants of a joint step
(``invariants.Checker._joint_instants``): each found at its exact instant, each firing
exactly there, holding where nothing happens, and unchanged by an exact congruence."""

from fractions import Fraction as F

import pytest
from hypothesis import given, settings, strategies as st

from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import geometry as g
from exactsym.gathering.instants import motion_of
from exactsym.gathering.invariants import Checker, Violation
from exactsym.gathering.joint_instants import (joint_critical_roots, joint_look_points,
                                               still)
from exactsym.gathering.joint_symmetry import (centroid_tie, mirror_pair_poly,
                                               rotations_of, symmetry_polys)
from exactsym.exact.algebraic.polynomials import peval
from exactsym.exact.algebraic.roots import roots_in_unit
from exactsym.gathering.robot import Readings
from exactsym.gathering.world import Frame, World

P = g.point
Q = MQ.rational


def seg(a, b):
    return g.Segment(P(*a), P(*b))


def moved_world(points, paths, centre=None, r_set=None, keys=("I9",), readings=Readings()):
    """A world whose robots ``paths`` carry made-up moves (no Look: no pending target, so
    I3 does not apply), with the C and R a Look would have recorded."""
    w = World(points, readings, checker=Checker(enabled=frozenset(keys)))
    for i, piece in paths.items():
        w.robots[i].path = [piece]
        w.robots[i].centre = centre
        if r_set is not None:
            w.robots[i].r_set = frozenset(r_set)
    return w


def roots_by_tag(pieces, w, family):
    return {t[1]: r.exact for r in joint_critical_roots(pieces, w) for t in r.tags
            if t[0] == family}


# -- the symmetry family (joint_symmetry) ---------------------------------------------
#: robots 0-2 stand still, symmetric about the y-axis (their centroid (0, 10) on it)
STILL3 = [(-10, 0), (10, 0), (0, 30)]


def test_two_movers_become_mirror_images_in_a_line_of_the_others():
    """Robot 3 at (-6 + 6 tau, -10), robot 4 at (3 + 3 tau, -10): mirror images in the
    y-axis at tau = 1/3 exactly, where the five robots are symmetric.  Of the other
    families only the SEC's four-on-a-circle has that instant too (two mirror pairs
    make an isosceles trapezoid, always on one circle): no tie, ray or contact."""
    pieces = {3: seg((-6, -10), (0, -10)), 4: seg((3, -10), (6, -10))}
    w = moved_world(STILL3 + [(-6, -10), (3, -10)], pieces)
    roots = joint_critical_roots(pieces, w)
    at = [r for r in roots if r.exact == Q(F(1, 3))]
    assert len(at) == 1
    assert {t[0] for t in at[0].tags} == {"symmetry", "sec"}
    assert ("symmetry", "all robots: robots 3 and 4 mirror images in a mirror line of the "
            "robots standing still") in at[0].tags
    # at that instant the configuration is its own mirror image in x = 0
    pts = {(-x, y) for x, y in (pieces[3].at(Q(F(1, 3))), pieces[4].at(Q(F(1, 3))))}
    assert pts == {pieces[3].at(Q(F(1, 3))), pieces[4].at(Q(F(1, 3)))}
    # a fresh Look at tau = 1/3 exactly (and beside it) compares the two frames: I9
    # is checked there and holds (the symmetric configuration is in O_S in every frame:
    # "gathering not possible", nobody moves)
    pts, _ = joint_look_points(pieces, w)
    assert [p.tau for p in pts if p.exact and "symmetry" in p.families] == [Q(F(1, 3))]
    w.advance_together([(3, None, False), (4, None, False)])
    assert w.checker.counts["I9"] == sum(1 for p in pts if p.families & {"sec", "symmetry"})
    assert w.checker.counts["I9"] >= 2
    # the same movers one unit lower on the right: never mirror images, no such root
    pieces = {3: seg((-6, -10), (0, -10)), 4: seg((3, -11), (6, -11))}
    w = moved_world(STILL3 + [(-6, -10), (3, -11)], pieces)
    assert not [t for r in joint_critical_roots(pieces, w) for t in r.tags
                if "mirror images" in t[1]]


def test_a_mover_crossing_the_mirror_line_and_a_rotation_centre():
    """One mover of R on the mirror line of the robots of R standing still (x = 0, at
    tau = 1/2); with four robots standing still on a square (a quarter-turn symmetry
    about its centre) a mover through that centre (tau = 2/5) and a mover at the image
    of the other in one of the square's rotations (tau = 1/14): the rotation family."""
    pieces = {3: seg((-2, -10), (2, -10)), 4: seg((20, 20), (22, 20))}
    w = moved_world(STILL3 + [(-2, -10), (20, 20)], pieces, r_set={0, 1, 2, 3})
    tags = roots_by_tag(pieces, w, "symmetry")
    assert tags["R: robot 3 on a mirror line of the robots standing still"] == Q(F(1, 2))
    square = [(10, 10), (-10, 10), (-10, -10), (10, -10)]
    assert len(rotations_of([P(*p) for p in square], P(0, 0))) == 3   # 1/4, 1/2, 3/4 turn
    assert rotations_of([P(*p) for p in square[:3]], P(0, 0)) == []
    pieces = {4: seg((-4, 0), (6, 0)), 5: seg((0, 3), (0, 7))}
    w = moved_world(square + [(-4, 0), (0, 3)], pieces)
    tags = roots_by_tag(pieces, w, "symmetry")
    rot = "all robots: robot 4 at the centre of a rotation of the robots standing still"
    assert tags[rot] == Q(F(2, 5))
    # (0, 3 + 4 tau) is the image of (-4 + 10 tau, 0) in the clockwise quarter turn where
    # 3 + 4 tau = 4 - 10 tau, tau = 1/14 (the other turns: no root in (0, 1))
    assert tags["all robots: robot 5 the image of robot 4 in a rotation of the robots "
                "standing still"] == Q(F(1, 14))


def test_a_mover_leaving_the_sec_brings_the_centroid_ties():
    """Robot 4 leaves the SEC of the others: the SEC centre moves, a symmetry mapping a
    mover to a robot standing still fixes the (moving) centroid; inside, the ties about
    the SEC centre of the robots standing still (here C's, the ``distance`` family) --
    except for robot 0 sliding on the circle of robots 1-3 about it (its ties vanish
    identically: an epsilon move's), which gets the centroid ties with them."""
    pts = [(20, 0), (0, 20), (-20, 0), (0, -20), (5, 0)]
    arc = g.Arc(P(0, 0), P(20, 0), P(16, 12), 1)

    def centroid_pairs(pieces):
        w = moved_world(pts, pieces, centre=P(0, 0))
        return sorted({t[1] for r in joint_critical_roots(pieces, w) for t in r.tags}
                      | {w_ for _, (f, w_) in symmetry_polys(
                          {k: motion_of(pieces[k]) if k in pieces else still(P(*p))
                           for k, p in enumerate(pts)}, set(pieces), range(5), "all robots",
                          {P(0, 0)})
                         if "centroid" in w_})

    inside = centroid_pairs({4: seg((5, 0), (5, 5)), 0: arc})
    assert [w_ for w_ in inside if "centroid" in w_] == [
        f"all robots: robots 0 and {q} as far from the centroid" for q in (1, 2, 3)]
    outside = centroid_pairs({4: seg((5, 0), (5, 30)), 0: arc})
    assert "all robots: robots 4 and 1 as far from the centroid" in outside


PIECES = st.sampled_from([
    seg((0, 0), (10, 3)), seg((-7, 2), (5, -9)), seg((3, 8), (3, -8)),
    g.Arc(P(0, 0), P(10, 0), P(6, 8), 1), g.Arc(P(1, 1), P(1, 14), P(-4, 13), 1),
    g.Arc(P(2, -3), P(7, -3), P(6, 0), 1)])


@settings(max_examples=25, deadline=None)
@given(PIECES, PIECES, st.integers(-9, 9), st.integers(-9, 9),
       st.fractions(F(1, 50), F(49, 50)))
def test_centroid_tie_and_mirror_pair_signs_are_the_definitions(p1, p2, qx, qy, tau):
    """At a rational time the polynomials have the signs of their definitions: the tie
    about the moving centroid (positive factors cleared) and the mirror relation's
    components (zero exactly where the points are mirror images)."""
    motions = {0: motion_of(p1), 1: motion_of(p2), 2: still(P(qx, qy)),
               3: still(P(4, -11))}
    t = Q(tau)
    a, b, q = p1.at(t), p2.at(t), P(qx, qy)
    z = tuple(sum((p[i] for p in (a, b, q, P(4, -11))), MQ()) / 4 for i in (0, 1))
    want = (g.dist2(a, z) - g.dist2(q, z)).sign()
    assert peval(centroid_tie(motions, [0, 1, 2, 3], {0, 1}, 0, 2), t).sign() == want
    u = (Q(3), Q(4))
    rel = mirror_pair_poly(motions[0], motions[1], P(1, 2), u)
    image = g.sub(g.add(P(1, 2), g.scale(u, g.dot(g.sub(a, P(1, 2)), u) * 2 / 25)),
                  g.sub(a, P(1, 2)))
    if image == b:
        assert not rel or peval(rel, t).is_zero()
    for r in roots_in_unit(rel):
        if r.exact is not None:
            x, y = p1.at(r.exact), p2.at(r.exact)
            mid = g.scale(g.add(x, y), Q(F(1, 2)))
            assert g.cross(g.sub(mid, P(1, 2)), u).is_zero()
            assert g.dot(g.sub(y, x), u).is_zero()


# -- the rays and ties about R's SEC centre ---------------------------------------------
def test_ties_and_rays_about_the_centre_of_Rs_sec():
    """R = robots 2, 3, 4, 5 (robots 0, 1 in the pattern, at C = (0, 0) and (2, 0)): the
    SEC of R's robots standing still is centred at (10, 0); robot 4 moving (10, 3) ->
    (10, 7) and robot 5 moving (15, 0) -> (5, -5) are as far from it at an exact
    irrational instant, and robot 5 is on the line through it and robot 2 at
    tau = 1/2; with R every robot, no ties about that centre."""
    pts = [(0, 0), (2, 0), (10, 10), (10, -10), (10, 3), (15, 0)]
    pieces = {4: seg((10, 3), (10, 7)), 5: seg((15, 0), (5, -5))}
    w = moved_world(pts, pieces, centre=P(0, 0), r_set={2, 3, 4, 5})
    ties = roots_by_tag(pieces, w, "distance")
    assert ties["robots 4 and 5 as far from the centre of R's SEC"] is not None
    r = [x for x in joint_critical_roots(pieces, w) if ("distance", "robots 4 and 5 as far "
         "from the centre of R's SEC") in x.tags][0]
    # |(0, 3 + 4 tau)|^2 = |(5 - 10 tau, -5 tau)|^2: 9 + 24 tau + 16 tau^2 =
    # 25 - 100 tau + 125 tau^2, 109 tau^2 - 124 tau + 16 = 0,
    # tau = (62 - 10 sqrt(21)) / 109
    assert r.exact == Q(F(62, 109)) - Q(F(10, 109)) * sqrt_rational(21)
    assert ("symmetry", "robots 4 and 5 as far from the centre of R's SEC") in r.tags
    rays = roots_by_tag(pieces, w, "ray")
    assert rays["robots 2 and 5 on one line through the centre of R's SEC"] == Q(F(1, 2))
    w = moved_world(pts, pieces, centre=P(0, 0), r_set=range(6))
    assert not [k for k in roots_by_tag(pieces, w, "distance") if "R's SEC" in k]


# -- I9 inside a joint step -------------------------------------------------------------
#: robots 0-2 fix the SEC (centre (0, 0), radius 20); robots 3 and 4 inside, moving
#: radially: |p3| = 8 + 4 tau, |p4| = 12 - 4 tau, as far from C at tau = 1/2, at (0, 10)
#: and (6, 8): there G_{t-1} = {3, 4} and MakeAsym's mover is read in the observer's
#: handedness (robot 3 in one frame, robot 4 in the reflected one)
TIE = [(0, 20), (-20, 0), (0, -20), (0, 8), (F(36, 5), F(48, 5))]


def _tie_world(end4=(F(24, 5), F(32, 5)), frame=None, readings=Readings()):
    pts, paths = TIE, {3: seg((0, 8), (0, 12)), 4: seg(TIE[4], end4)}
    centre = P(0, 0)
    if frame is not None:
        pts = [frame.to_local(P(*p)) for p in pts]
        paths = {i: g.Segment(frame.to_local(p.start), frame.to_local(p.end))
                 for i, p in paths.items()}
        centre = frame.to_local(centre)
    return moved_world(pts, paths, centre=centre, readings=readings)


STEP = [(3, None, False), (4, None, False)]


def _instant(v):
    return v.witness.split("(time ")[1].split(" of the step")[0]


def test_I9_fires_at_a_tie_inside_a_joint_step():
    w = _tie_world()
    with pytest.raises(Violation) as err:
        w.advance_together(STEP)
    v = err.value
    assert (v.invariant, v.label, v.robots) == ("I9", "no chirality (L210-214)", (3, 4))
    assert _instant(v) == "1/2"
    assert "robot 3 at (0, 10), robot 4 at (6, 8)" in v.witness
    assert "robots 3 and 4 as far from C" in v.witness
    assert "plans robot 3 (MakeAsym)" in v.witness and "plans robot 4 (MakeAsym)" in v.witness
    # I9 held at every earlier SEC instant and beside it: 1/2 is not the first check
    assert w.checker.counts["I9"] >= 2
    # the step's end alone (what was checked before): the frames agree there
    w = _tie_world()
    w.checker = None
    w.advance_together(STEP)
    c = Checker(enabled=frozenset({"I9"}))
    c._mirror_look(w, [3, 4], 1, "")


def test_I9_holds_over_a_joint_step_without_the_tie():
    """Robot 4 moving out to radius 13 instead (|p4| = 12 + tau > 8 + 4 tau on [0, 1]):
    never as far from C as robot 3, I9 is checked at the SEC instants and holds; the
    paper layer's other reading (EL=unordered) rescues the tie too."""
    for w in (_tie_world((F(39, 5), F(52, 5))), _tie_world(readings=Readings(EL="unordered"))):
        w.advance_together(STEP)
        c = w.checker.counts
        assert c["I9"] >= 3 and c["I9"] <= c["instants"]


def test_I9_fires_at_an_sec_instant_inside_a_joint_step_and_holds_unordered():
    """Robots 0 and 4 move radially out through the circle of radius 20 and reach it
    together at tau = 1/2 (a change of the SEC's support: four and five robots on one
    circle): there the five robots are those of handedness-frames-disagree.toml, whose
    leader is read in the observer's handedness; before, both frames plan robot 0's
    MakeAsym move, after, robot 1's Make_SymToAsym move (its sense is its own)."""
    pts = [(16, 0), (0, 20), (-20, 0), (0, -20), (9, 12)]
    paths = {0: seg((16, 0), (24, 0)), 4: seg((9, 12), (15, 20))}
    w = moved_world(pts, paths)
    with pytest.raises(Violation) as err:
        w.advance_together([(0, None, False), (4, None, False)])
    v = err.value
    assert (v.invariant, v.robots, _instant(v)) == ("I9", (2, 3), "1/2")
    assert "robots 0, 1, 2, 3 on one circle" in v.witness
    assert "plans robot 3 (leader) to (0, 0)" in v.witness
    w = moved_world(pts, paths, readings=Readings(EL="unordered"))
    w.advance_together([(0, None, False), (4, None, False)])
    assert w.checker.counts["I9"] >= 3


CONGRUENCES = [Frame(F(3, 5), F(4, 5), False, F(7), F(-3)),
               Frame(F(-5, 13), F(12, 13), True, F(1, 2), F(9)),
               Frame(F(1), F(0), True, F(0), F(0))]


@pytest.mark.parametrize("frame", CONGRUENCES)
def test_joint_instants_and_the_I9_outcome_survive_an_exact_congruence(frame):
    """A Pythagorean rotation, a translation and a reflection of the whole step (robots
    are unit discs: a congruence keeps every contact) move no instant and change no
    outcome: the same exact times, the same families, the same violation."""
    def key(w):
        pieces = {i: w.robots[i].path[0] for i in (3, 4)}
        return sorted((str(r.exact), tuple(sorted({t[0] for t in r.tags})))
                      for r in joint_critical_roots(pieces, w) if r.exact is not None)

    assert key(_tie_world(frame=frame)) == key(_tie_world())
    got = []
    for w in (_tie_world(), _tie_world(frame=frame)):
        with pytest.raises(Violation) as err:
            w.advance_together(STEP)
        got.append((err.value.invariant, err.value.robots, _instant(err.value)))
    assert got[0] == got[1]
    w = _tie_world((F(39, 5), F(52, 5)), frame=frame)
    w.advance_together(STEP)                                    # holds, mapped


def test_joint_symmetry_look_points_stay_in_order():
    """The new candidates merge with the others: Looks strictly inside, in order, one per
    stretch and one per exact instant."""
    w = _tie_world()
    pieces = {i: w.robots[i].path[0] for i in (3, 4)}
    roots = joint_critical_roots(pieces, w)
    pts, sided = joint_look_points(pieces, w)
    taus = [p.tau for p in pts]
    assert all(a < b for a, b in zip(taus, taus[1:]))
    assert all(Q(0) < t < Q(1) for t in taus)
    assert sum(not p.exact for p in pts) == len(roots) + 1
    assert sum(p.exact for p in pts) + sided == len(roots)
    assert symmetry_polys({k: still(P(k, k * k)) for k in range(5)}, set(), range(5),
                          "all") == []                            # nobody moves


# -- the superset property ---------------------------------------------------------------
def _symmetric_step(data, kind):
    """Robots symmetric at a rational time ``ts`` under ``kind`` (``mirror``: x -> -x;
    ``half``: p -> -p), then a random congruence: the robots standing still are pairs
    of images (and, for the mirror, robots on the axis); the movers, each on a random
    segment through its point at ``ts``, are a pair of images, on the axis / at the
    centre, or the image of a robot standing still (that robot's partner)."""
    img = (lambda p: (-p[0], p[1])) if kind == "mirror" else (lambda p: (-p[0], -p[1]))
    coord = st.integers(-30, 30).filter(lambda v: v != 0)
    pts, still_pairs = [], data.draw(st.integers(1, 3))
    for _ in range(still_pairs):
        p = (data.draw(coord), data.draw(coord))
        pts += [p, img(p)]
    if kind == "mirror" and data.draw(st.booleans()):
        pts.append((0, data.draw(coord)))
    ts = data.draw(st.fractions(F(1, 10), F(9, 10), max_denominator=12))
    at_ts = []
    shape = data.draw(st.sampled_from(["pair", "fixed", "swap"]))
    if shape == "swap" and kind == "mirror" and len(pts) % 2:
        pts.pop()                                  # the axis robot: its own image
    if shape == "pair":
        p = (data.draw(coord), data.draw(coord))
        at_ts = [p, img(p)]
    elif shape == "fixed":
        at_ts = [(0, data.draw(coord)) if kind == "mirror" else (0, 0)]
        q = (data.draw(coord), data.draw(coord))
        at_ts += [q, img(q)]                      # a second pair of movers
    else:
        q = pts.pop()            # a mover at q: the image of the still robot img(q)
        p = (data.draw(coord), data.draw(coord))
        at_ts = [q, p, img(p)]
    vel = st.tuples(st.integers(-9, 9), st.integers(-9, 9))
    pieces = []
    for p in at_ts:
        v = data.draw(vel)
        pieces.append(((p[0] - ts * v[0], p[1] - ts * v[1]),
                       (p[0] + (1 - ts) * v[0], p[1] + (1 - ts) * v[1])))
    a, b = data.draw(st.sampled_from([(F(3, 5), F(4, 5)), (F(5, 13), F(-12, 13)),
                                      (F(1), F(0))]))
    fr = Frame(a, b, data.draw(st.booleans()), F(data.draw(st.integers(-5, 5)), 3), F(2))
    start = [P(*p) for p in pts] + [P(*s) for s, _ in pieces]
    movers = {len(pts) + k: g.Segment(fr.to_local(P(*s)), fr.to_local(P(*e)))
              for k, (s, e) in enumerate(pieces)}
    start = [fr.to_local(p) for p in start]

    def symmetric_at(t):         # before the congruence: closed under the image map
        now = set(pts) | {(s[0] + t * (e[0] - s[0]), s[1] + t * (e[1] - s[1]))
                          for s, e in pieces}
        return all(img(p) in now for p in now)
    return start, movers, ts, symmetric_at


@settings(max_examples=40, deadline=None)
@given(st.data(), st.sampled_from(["mirror", "half"]))
def test_every_symmetric_instant_of_a_joint_step_is_a_symmetry_root(data, kind):
    """Whatever the movers do elsewhere, a time at which the robots are symmetric is
    among the roots tagged ``symmetry`` (exactly, or a root of its polynomial in its
    isolating interval): the family is a superset."""
    start, movers, ts, symmetric_at = _symmetric_step(data, kind)
    assert symmetric_at(ts)
    if symmetric_at(ts + F(1, 97)):
        return             # symmetric a moment later too: no instant where it appears
    if len(start) - len(movers) < 2:
        return             # fewer than two robots standing still: not enumerated
    if len({(str(p[0]), str(p[1])) for p in start}) < len(start):
        return                                    # two robots at one point: not a state
    at = [movers[k].at(Q(ts)) if k in movers else p for k, p in enumerate(start)]
    if len({(str(p[0]), str(p[1])) for p in at}) < len(at):
        return
    w = World([(0, 0)] * len(start), Readings())
    for rob, p in zip(w.robots, start):
        rob.pos = p
    t = Q(ts)
    hit = False
    for r in joint_critical_roots(movers, w):
        if not any(tag[0] == "symmetry" for tag in r.tags):
            continue
        if r.exact is not None:
            hit = hit or r.exact == t
        else:
            hit = hit or (Q(r.lo) < t < Q(r.hi) and peval(r.poly, t).is_zero())
    assert hit
