"""Symmetry instants of one mover (exactsym.gathering.instants): the ``distance`` ties
are ``symmetry`` candidates too, so I9 (no chirality) is checked there; a mover on an
arc about C at another robot's distance (the C-tie vanishes all along) gets the tie
about the centroid instead.  Each found at its exact instant, I9 firing exactly there
and holding where the reading rescues it, and a hypothesis superset property."""

from fractions import Fraction as F

import pytest
from hypothesis import given, settings, strategies as st

from exactsym.exact.multiquadratic import MQ
from exactsym.gathering import geometry as g
from exactsym.gathering.instants import critical_roots, look_points
from exactsym.gathering.invariants import Checker, Violation
from exactsym.exact.algebraic.polynomials import peval
from exactsym.gathering.robot import Readings
from exactsym.gathering.world import Frame, World

P = g.point
Q = MQ.rational

#: robots 0-2 on the circle of radius 20 (C = 0); robot 3 moves down the y axis from
#: (0, 12) to (0, 8); robot 4 stands at (6, 8), at distance 10 from C
TIE = [(0, 20), (-20, 0), (0, -20), (0, 12), (6, 8)]


def _tie_world(readings=Readings(), keys=("I3", "I9"), frame=None, robot4=(6, 8)):
    """Robot 3 on its (made-up) way to (0, 8): a move with a target, a role and the C and
    R that a Look records, so the fresh Looks of I3 and I9 run at its instants."""
    pts = TIE[:4] + [robot4]
    centre, end = P(0, 0), P(0, 8)
    if frame is not None:
        pts = [frame.to_local(P(*p)) for p in pts]
        centre, end = frame.to_local(centre), frame.to_local(end)
    w = World(pts, readings, checker=Checker(enabled=frozenset(keys)))
    rob = w.robots[3]
    rob.path, rob.role, rob.kind = [g.Segment(rob.pos, end)], "MakeAsym", "to-G_t-circle"
    rob.centre, rob.start, rob.target = centre, rob.pos, end
    rob.r_set = frozenset(range(5))
    return w


def test_a_distance_root_of_one_mover_is_a_symmetry_candidate():
    w = _tie_world()
    roots = critical_roots(w.robots[3].path[0], w, 3, P(0, 0))
    (r,) = [r for r in roots if r.exact == Q(F(1, 2))]
    assert sorted(r.tags) == [("distance", "as far from C as robot 4"),
                              ("symmetry", "as far from C as robot 4")]


def test_I9_fires_exactly_at_a_distance_instant_of_one_mover():
    """At f = 1/2 robot 3 is at (0, 10), as far from C as robot 4: there (the five robots
    of the joint step's tie, test_gathering_joint_instants) MakeAsym's mover is read in
    the observer's handedness, robot 3 in the world's frame, robot 4 in the reflected
    one.  Before and after the instant both frames agree (I3 holds all along up to it)."""
    w = _tie_world()
    with pytest.raises(Violation) as err:
        w.advance(3)
    v = err.value
    assert (v.invariant, v.label, v.robots) == ("I9", "no chirality (L210-214)", (3, 4))
    assert v.witness == (
        "robot 3 moves; with robot 3 at (0, 10) (as far from C as robot 4) a fresh Look in "
        "the world's frame plans robot 3 (MakeAsym) to (0, 20), one in frame "
        "['1', '0', True, '0', '0'] plans robot 4 (MakeAsym) to (12, 16)")
    # the stretch before the instant was checked, and held
    assert w.checker.counts["I9"] == 2 and w.checker.counts["instants"] == 2


def test_I9_holds_at_the_distance_instant_under_EL_unordered_and_without_the_tie():
    """EL=unordered reads the pairs the same way in both handednesses: I9 holds at the
    tie (checked: before, at, after it).  With robot 4 at distance 15 the piece never
    ties with it: no symmetry instant, no I9 Look inside the piece."""
    w = _tie_world(Readings(EL="unordered"), keys=("I9",))
    w.advance(3)
    assert w.checker.counts["I9"] == 3 and w.checker.counts["instants"] == 3
    w = _tie_world(keys=("I9",), robot4=(9, 12))
    points, _ = look_points(w.robots[3].path[0], w, 3, P(0, 0))
    assert not any("symmetry" in lp.families for lp in points)


@pytest.mark.parametrize("frame", [Frame(F(3, 5), F(4, 5), False, F(7), F(-3)),
                                   Frame(F(-5, 13), F(12, 13), True, F(1, 2), F(9))])
def test_the_I9_witness_survives_an_exact_congruence(frame):
    """A Pythagorean rotation and a translation (with or without a reflection) of the
    whole scene: the same instant, the same robots (in a reflected scene the world's
    frame and the reflected one swap roles: the two plans swap, so only I9 is on)."""
    w = _tie_world(frame=frame, keys=("I9",))
    with pytest.raises(Violation) as err:
        w.advance(3)
    v = err.value
    assert (v.invariant, v.robots) == ("I9", (3, 4))
    assert f"robot 3 at {g.fmt_point(frame.to_local(P(0, 10)))} (as far from C" in v.witness


# -- an arc on another robot's circle ---------------------------------------------------
#: robots 0-3 on the circle of radius 20 (their SEC: C = 0), robot 4 inside; robot 5
#: moves along that circle (an epsilon move along the SEC) through (12, 16) at f = 1/3,
#: where the six robots are symmetric in the y axis: robot 5 is robot 0's mirror image
ARC_STILL = [(-12, 16), (16, -12), (-16, -12), (0, -20), (0, 5)]
ARC = g.Arc(P(0, 0), P(F(612, 37), F(416, 37)), P(F(172, 185), F(3696, 185)), 1)


def test_an_arc_on_another_robots_circle_meets_the_symmetric_instant():
    assert ARC.at(Q(F(1, 3))) == P(12, 16)
    w = World(ARC_STILL + [ARC.start], Readings())
    roots = critical_roots(ARC, w, 5, P(0, 0))
    at = [r for r in roots if r.exact == Q(F(1, 3))]
    assert len(at) == 1
    tags = {t[1] for t in at[0].tags}
    assert {t[0] for t in at[0].tags} == {"symmetry"}
    circle = "all robots, on robot 0's circle about C"
    # the centroid of all is fixed by the mirror: robot 5 as far from it as robot 0
    assert f"symmetry: as far from the centroid of {circle}" in tags
    # a reflection swapping robots 5 and 0 maps the rest onto itself: robot 5 is robot
    # 0's mirror image in a mirror line of the rest (through C; through their centroid)
    assert (f"symmetry: robot 0's image (the mirror image in a mirror line through the "
            f"centre; {circle})") in tags
    # nothing else names that instant: on the circle the C-ties say nothing
    assert not any(t[0] == "distance" for r in roots for t in r.tags)
    points, sided = look_points(ARC, w, 5, P(0, 0))
    (lp,) = [lp for lp in points if lp.exact and lp.f == Q(F(1, 3))]
    assert lp.point == P(12, 16) and "symmetry" in lp.families and sided == 0


# -- the superset property ---------------------------------------------------------------
IMAGES = {"mirror": lambda p: (-p[0], p[1]), "half": lambda p: (-p[0], -p[1]),
          "quarter": lambda p: (-p[1], p[0])}


def _orbit(p, img):
    out = [p]
    while img(out[-1]) != p:
        out.append(img(out[-1]))
    return out


def _rot(u):
    """The rational rotation whose half-angle tangent is ``u``: (cos, sin)."""
    d = 1 + u * u
    return (1 - u * u) / d, 2 * u / d


def _symmetric_piece(data, kind):
    """Robots symmetric at a rational time ``ts`` under ``kind`` (a mirror x -> -x, a half
    or a quarter turn), then a random congruence.  The robots standing still are whole
    orbits (and robots on the axis, for the mirror) and, when the mover takes the place
    of a robot of an orbit (``swap``), the rest of that orbit; else the mover is on the
    axis or at the centre (``fixed``).  The mover is on a random segment through its
    point at ``ts``, or on an arc about the centre of symmetry through it (on the circle
    of the swapped robots: the C-tie vanishes all along)."""
    img = IMAGES[kind]
    coord = st.integers(-30, 30).filter(lambda v: v != 0)
    pts = []
    for _ in range(data.draw(st.integers(1, 3))):
        pts += _orbit((data.draw(coord), data.draw(coord)), img)
    if kind == "mirror" and data.draw(st.booleans()):
        pts.append((0, data.draw(coord)))
    ts = data.draw(st.fractions(F(1, 10), F(9, 10), max_denominator=12))
    if data.draw(st.booleans()):                                        # swap
        orbit = _orbit((data.draw(coord), data.draw(coord)), img)
        p, pts = orbit[0], pts + orbit[1:]
    else:
        p = (0, data.draw(coord)) if kind == "mirror" else (0, 0)
    if data.draw(st.booleans()) and p != (0, 0):                        # an arc about 0
        T = data.draw(st.sampled_from([F(1, 2), F(1, 3), F(-1, 4), F(-2, 5)]))
        c0, s0 = _rot(-ts * T)
        start = (p[0] * c0 - p[1] * s0, p[0] * s0 + p[1] * c0)
        c1, s1 = _rot(T)
        end = (start[0] * c1 - start[1] * s1, start[0] * s1 + start[1] * c1)
        piece = g.Arc(P(0, 0), P(*start), P(*end), 1 if T > 0 else -1)
    else:
        v = data.draw(st.tuples(st.integers(-9, 9), st.integers(-9, 9)))
        piece = g.Segment(P(p[0] - ts * v[0], p[1] - ts * v[1]),
                          P(p[0] + (1 - ts) * v[0], p[1] + (1 - ts) * v[1]))
    assert piece.at(Q(ts)) == P(*p)
    a, b = data.draw(st.sampled_from([(F(3, 5), F(4, 5)), (F(5, 13), F(-12, 13)),
                                      (F(1), F(0))]))
    fr = Frame(a, b, data.draw(st.booleans()), F(data.draw(st.integers(-5, 5)), 3), F(2))
    mapped = (g.Segment(fr.to_local(piece.start), fr.to_local(piece.end))
              if isinstance(piece, g.Segment) else
              g.Arc(fr.to_local(piece.centre), fr.to_local(piece.start),
                    fr.to_local(piece.end), -piece.sense if fr.reflect else piece.sense))

    def symmetric_at(t):          # before the congruence: closed under the image map
        q = piece.at(Q(t))
        now = {P(*x) for x in pts} | {q}
        return all(P(*img((x[0], x[1]))) in now for x in now)
    return [fr.to_local(P(*x)) for x in pts], mapped, ts, symmetric_at


@settings(max_examples=60, deadline=None)
@given(st.data(), st.sampled_from(["mirror", "half", "quarter"]))
def test_every_symmetric_instant_of_one_mover_is_a_symmetry_root(data, kind):
    """Whatever the mover does elsewhere, a time at which the robots are symmetric is
    among the roots tagged ``symmetry`` (exactly, or a root of its polynomial in its
    isolating interval): the family is a superset.  C is the SEC centre of all the
    robots at the piece's start (what the mover's Look recorded)."""
    still, piece, ts, symmetric_at = _symmetric_piece(data, kind)
    assert symmetric_at(ts)
    if symmetric_at(ts + F(1, 97)):
        return             # symmetric a moment later too: no instant where it appears
    pts = still + [piece.start]
    at = still + [piece.at(Q(ts))]
    if len(set(pts)) < len(pts) or len(set(at)) < len(at) or len(still) < 2:
        return                                    # two robots at one point: not a state
    w = World([(0, 0)] * len(pts), Readings())
    for rob, p in zip(w.robots, pts):
        rob.pos = p
    centre = g.smallest_enclosing_circle(pts)[0]
    mover, t = len(still), Q(ts)
    hit = False
    for r in critical_roots(piece, w, mover, centre):
        if not any(tag[0] == "symmetry" for tag in r.tags):
            continue
        if r.exact is not None:
            hit = hit or r.exact == t
        else:
            hit = hit or (Q(r.lo) < t < Q(r.hi) and peval(r.poly, t).is_zero())
    assert hit
