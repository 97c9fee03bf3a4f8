"""Critical instants of a joint step that joint_instants and joint_symmetry did not list
before: a symmetry appearing with fewer than two robots standing still (the hypotheses
on images, ``joint_symmetry.image_polys``), a mover keeping a still robot's distance
from both the SEC centre and the centroid all along (the same hypotheses from that
swap), and the rays and ties about R's SEC centre while a mover of R supports that SEC
(``moving_centre.about_moving_sec``).  Each: found at its exact instant, missed
without the new family, and a fresh Look there catches a (test) algorithm that stays
exactly at that instant (I3); plus the superset property with 0 or 1 robots standing
still, and the relations about moving points against their definitions."""

from fractions import Fraction as F

import pytest
from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import invariants, geometry as g
from exactsym.gathering import joint_instants, joint_symmetry, stops
from exactsym.gathering.motion import motion_of
from exactsym.gathering.invariants import Checker, Violation
from exactsym.gathering.joint_instants import joint_critical_roots
from exactsym.gathering.joint_relations import (centroid_motion, circumcentre_motion,
                                                midpoint_motion, pair_tie, ray_about,
                                                still, tie_about)
from exactsym.gathering.joint_symmetry import image_polys
from exactsym.gathering.pattern import recognise
from exactsym.exact.algebraic.polynomials import peval
from exactsym.gathering.robot import Decision, Move, Readings
from exactsym.exact.algebraic.tower_numbers import is_tower
from exactsym.gathering.world import IDENTITY, Frame, World

P = g.point
Q = MQ.rational
ORIGIN = P(0, 0)


def seg(a, b):
    return g.Segment(P(*a), P(*b))


def _stub(mover: int, target, centre, stays, arc_centre=None):
    """A test algorithm (not the paper's): robot ``mover`` goes to ``target`` (a segment,
    or an arc about ``arc_centre``) unless ``stays(points)`` (then everybody stays).
    Plain-frame Looks only."""
    def decide(snapshot, readings=Readings(), unit=fmpq(1)):
        pts = list(snapshot)
        pat = recognise(pts, centre)
        if stays(pts):
            return Decision("stay", (), centre, pat, None, "the test's event")
        piece = (g.Segment(pts[mover], target) if arc_centre is None else
                 g.Arc(arc_centre, pts[mover], target, 1))
        return Decision("move", (Move(mover, (piece,), "leader"),), centre, pat, mover,
                        "to the target")
    return decide


def _step(points, mover, pieces, centre, stays, arc_centre=None, r_set=None):
    """Robot ``mover`` Looks (the stub plans its piece), the others of ``pieces`` get
    made-up moves (no Look: I3 concerns the mover only); then the step, I3 on."""
    w = World(points, Readings(), checker=Checker(enabled=frozenset({"I3"})))
    w.decide = _stub(mover, pieces[mover].final, centre, stays, arc_centre)
    w.look(mover, IDENTITY)
    assert w.robots[mover].path == [pieces[mover]]
    for i, piece in pieces.items():
        if i != mover:
            w.robots[i].path = [piece]
            w.robots[i].centre = centre
        if r_set is not None:
            w.robots[i].r_set = frozenset(r_set)
    return w


def _instant(v):
    return v.witness.split("(time ")[1].split(" of the step")[0]


def _world(points, pieces, centre, r_set=None):
    w = World(points, Readings())
    for i, piece in pieces.items():
        w.robots[i].path, w.robots[i].centre = [piece], centre
        if r_set is not None:
            w.robots[i].r_set = frozenset(r_set)
    return w


def _tags_at(pieces, w, tau):
    return [t for r in joint_critical_roots(pieces, w) if r.exact == tau for t in r.tags]


# -- 1. a symmetry among movers: one robot standing still --------------------------------
#: robot 0 stands still on the y-axis; robots 1-4 move, and at tau = 1/3 exactly the
#: five are their own mirror image in it: robots 1, 2 at (-10, 0), (10, 0), robots 3, 4
#: on the axis at (0, -15), (0, -30) (no four on one circle: no SEC instant there).  C
#: is taken off the axis, (1, 50), so no tie about C marks that instant either.
ONE_STILL = [(0, 20), (-11, -2), (12, -1), (-2, -16), (1, -32)]
ONE_STILL_PIECES = {1: seg((-11, -2), (-8, 4)), 2: seg((12, -1), (6, 2)),
                    3: seg((-2, -16), (4, -13)), 4: seg((1, -32), (-2, -26))}
C1 = P(1, 50)


def _mirror_x(pts):
    have = set(pts)
    return all((-p[0], p[1]) in have for p in pts)


def test_a_symmetry_among_movers_with_one_robot_standing_still_is_enumerated(monkeypatch):
    w = _world(ONE_STILL, ONE_STILL_PIECES, C1)
    third = Q(F(1, 3))
    at = _tags_at(ONE_STILL_PIECES, w, third)
    assert ("symmetry", "all robots: robots 1 and 2 as far from the centroid") in at
    assert {f for f, _ in at} == {"symmetry"}          # no other family marks it
    # there the five robots are mirror images in x = 0
    assert _mirror_x([ONE_STILL_PIECES[k].at(third) if k in ONE_STILL_PIECES else P(*p)
                      for k, p in enumerate(ONE_STILL)])
    # a fresh Look there sees the symmetric configuration: the stub stays, I3 fires at
    # exactly 1/3 and not before
    w = _step(ONE_STILL, 1, ONE_STILL_PIECES, C1, _mirror_x)
    with pytest.raises(Violation) as err:
        w.advance_together([(k, None, False) for k in ONE_STILL_PIECES])
    v = err.value
    assert (v.invariant, v.robots, _instant(v)) == ("I3", (1,), "1/3")
    assert "robot 1 at (-10, 0)" in v.witness and "no move" in v.witness
    # without the hypotheses on images the instant is not enumerated, and the step passes
    monkeypatch.setattr(joint_symmetry, "image_polys", lambda *a, **k: [])
    monkeypatch.setattr(stops, "_POINTS", {})     # the motion's points, cached above
    monkeypatch.setattr(stops, "_ROOTS", {})      # and its roots
    assert not _tags_at(ONE_STILL_PIECES, _world(ONE_STILL, ONE_STILL_PIECES, C1), third)
    w = _step(ONE_STILL, 1, ONE_STILL_PIECES, C1, _mirror_x)
    w.advance_together([(k, None, False) for k in ONE_STILL_PIECES])


def test_a_set_of_three_with_no_robot_standing_still():
    """R = {2, 3, 4}, all moving (robots 0, 1 stand still outside R): at tau = 1/2 robot 2
    reaches the perpendicular bisector of robots 3 and 4, y = 2 (R is an isosceles
    triangle, its own mirror image in that line); the hypotheses on images list it."""
    pts = [(0, 40), (0, -40), (-5, 0), (10, -6), (10, 4)]
    pieces = {2: seg((-5, 0), (-5, 4)), 3: seg((10, -6), (10, -2)),
              4: seg((10, 4), (10, 12))}
    w = _world(pts, pieces, ORIGIN, r_set={2, 3, 4})
    half = Q(F(1, 2))
    a, b, c = (pieces[k].at(half) for k in (2, 3, 4))
    assert (a, b, c) == (P(-5, 2), P(10, -4), P(10, 8))
    assert any(f == "symmetry" and w_.startswith("R: ")
               for f, w_ in _tags_at(pieces, w, half))


# -- 2. a mover on a still robot's circle about both centres ------------------------------
#: robots 0-3 and 6-9 stand still: (20, 0), (-20, 0), (15, 15), (-15, -15) and the
#: hull (30, 30), (-30, -30), (26, -26), (-26, 26) (centroid and SEC centre at the
#: origin; a half turn, no mirror line); robot 4 slides on the circle of radius 20 from
#: (12, 16) to (-12, 16), robot 5 opposite it (the pair always a half turn of each
#: other), so the centroid stays at the origin: robot 4 keeps robot 0's distance from
#: the SEC centre and from the centroid all along (both ties vanish identically).  At
#: (0, 20) the ten robots are mirror images in y = x, which swaps robots 4 and 0.
SWAP = [(20, 0), (-20, 0), (15, 15), (-15, -15), (12, 16), (-12, -16),
        (30, 30), (-30, -30), (26, -26), (-26, 26)]
SWAP_PIECES = {4: g.Arc(ORIGIN, P(12, 16), P(-12, 16), 1),
               5: g.Arc(ORIGIN, P(-12, -16), P(12, -16), 1)}


def _mirror_diagonal(pts):
    have = set(pts)
    return all((p[1], p[0]) in have for p in pts)


def _swap_instant():
    """The arc parameter of (0, 20) on robot 4's arc (the rational rotation's)."""
    from exactsym.gathering.motion import point_param
    return point_param(SWAP_PIECES[4], P(0, 20))


def test_a_mover_on_a_still_robots_circle_about_both_centres(monkeypatch):
    tau = _swap_instant()
    assert tau == Q(F(4, 9))
    assert SWAP_PIECES[5].at(tau) == P(0, -20)
    w = _world(SWAP, SWAP_PIECES, ORIGIN)
    at = _tags_at(SWAP_PIECES, w, tau)
    assert at and {f for f, _ in at} == {"symmetry"}
    assert any("if robot 4's image is robot 0" in w_ for _, w_ in at)
    assert _mirror_diagonal([SWAP_PIECES[k].at(tau) if k in SWAP_PIECES else P(*p)
                             for k, p in enumerate(SWAP)])
    w = _step(SWAP, 4, SWAP_PIECES, ORIGIN, _mirror_diagonal, arc_centre=ORIGIN)
    with pytest.raises(Violation) as err:
        w.advance_together([(4, None, False), (5, None, False)])
    v = err.value
    assert (v.invariant, v.robots, _instant(v)) == ("I3", (4,), "4/9")
    assert "robot 4 at (0, 20)" in v.witness
    # before: both ties vanish, nothing listed for that swap, the step passes
    monkeypatch.setattr(joint_symmetry, "image_polys", lambda *a, **k: [])
    monkeypatch.setattr(stops, "_POINTS", {})     # the motion's points, cached above
    monkeypatch.setattr(stops, "_ROOTS", {})      # and its roots
    assert not _tags_at(SWAP_PIECES, _world(SWAP, SWAP_PIECES, ORIGIN), tau)
    w = _step(SWAP, 4, SWAP_PIECES, ORIGIN, _mirror_diagonal, arc_centre=ORIGIN)
    w.advance_together([(4, None, False), (5, None, False)])


# -- 3. rays and ties about R's moving SEC centre ---------------------------------------
#: robots 0, 1 in the pattern (C = (0, 0)); R = {2, 3, 4, 5}.  Robot 5 moves out along the
#: x-axis from (25, 0) to (35, 0): with robots 2 (10, 10) and 3 (10, -10) it supports R's
#: SEC, whose centre (h, 0), h = (x^2 - 200) / (2x - 20), moves.  Robot 4 moves up x = 12
#: from (12, 16/3) to (12, 28/3): at tau = 1/2 (x = 30, h = 35/2) it is on the line
#: through that centre and robot 2, at (12, 22/3); it crossed that line once before, at
#: tau = -7/6 + sqrt(13)/3 (about 0.035: the ray's quadratic factor).
MOVING = [(0, 0), (2, 0), (10, 10), (10, -10), (12, F(16, 3)), (25, 0)]
MOVING_PIECES = {4: seg((12, F(16, 3)), (12, F(28, 3))), 5: seg((25, 0), (35, 0))}
R_SET = {2, 3, 4, 5}


def _on_ray_2_4(pts):
    c = g.smallest_enclosing_circle([pts[k] for k in sorted(R_SET)])[0]
    return g.cross(g.sub(pts[2], c), g.sub(pts[4], c)).is_zero()


def test_rays_about_Rs_moving_sec_centre(monkeypatch):
    w = _world(MOVING, MOVING_PIECES, ORIGIN, r_set=R_SET)
    half = Q(F(1, 2))
    at = _tags_at(MOVING_PIECES, w, half)
    assert ("ray", "robots 2 and 4 on one line through the centre of R's SEC (supports "
            "2, 3, 5)") in at
    pts = [MOVING_PIECES[k].at(half) if k in MOVING_PIECES else P(*p)
           for k, p in enumerate(MOVING)]
    assert g.smallest_enclosing_circle([pts[k] for k in sorted(R_SET)])[0] == \
        P(F(35, 2), 0)
    assert _on_ray_2_4(pts)
    first = Q(F(-7, 6)) + sqrt_rational(13) / 3
    assert ("ray", "robots 2 and 4 on one line through the centre of R's SEC (supports "
            "2, 3, 5)") in _tags_at(MOVING_PIECES, w, first)
    assert _on_ray_2_4([MOVING_PIECES[k].at(first) if k in MOVING_PIECES else P(*p)
                        for k, p in enumerate(MOVING)])
    # a fresh Look at the first of the two instants, exactly, catches the stub there
    w = _step(MOVING, 4, MOVING_PIECES, ORIGIN, _on_ray_2_4, r_set=R_SET)
    with pytest.raises(Violation) as err:
        w.advance_together([(4, None, False), (5, None, False)])
    v = err.value
    assert (v.invariant, v.robots, _instant(v)) == ("I3", (4,), "-7/6 + sqrt(13)/3")
    # before: the rays about the still robots' SEC centre (10, 0) only
    monkeypatch.setattr(joint_instants, "about_moving_sec", lambda *a, **k: ([], []))
    monkeypatch.setattr(stops, "_POINTS", {})     # the motion's points, cached above
    monkeypatch.setattr(stops, "_ROOTS", {})      # and its roots
    assert not [t for t in _tags_at(MOVING_PIECES, _world(MOVING, MOVING_PIECES, ORIGIN,
                                                          r_set=R_SET), half)
                if t[0] == "ray"]


def test_every_exact_root_about_the_moving_centre_is_an_event():
    """Each exact root tagged about the moving centre (here: in the stretch of its
    support) is exactly the relation's event about the true SEC centre of R there."""
    w = _world(MOVING, MOVING_PIECES, ORIGIN, r_set=R_SET)
    checked = 0
    for r in joint_critical_roots(MOVING_PIECES, w):
        for fam, what in r.tags:
            if "supports" not in what:
                continue
            a, b = (int(x) for x in what.split("robots ")[1].split(" on")[0]
                    .split(" as")[0].split(" and "))

            def rel(t, a=a, b=b, fam=fam):
                pts = {k: MOVING_PIECES[k].at(t) if k in MOVING_PIECES else P(*MOVING[k])
                       for k in R_SET}
                c = g.smallest_enclosing_circle(list(pts.values()))[0]
                if fam == "ray":
                    return g.cross(g.sub(pts[a], c), g.sub(pts[b], c)).sign()
                return (g.dist2(pts[a], c) - g.dist2(pts[b], c)).sign()
            if r.exact is not None and not is_tower(r.exact):
                assert rel(r.exact) == 0
                checked += 1
    assert checked >= 1


# -- the relations about moving points: their definitions --------------------------------
PIECES = st.sampled_from([
    seg((0, 0), (10, 3)), seg((-7, 2), (5, -9)), seg((3, 8), (3, -8)),
    g.Arc(P(0, 0), P(10, 0), P(6, 8), 1), g.Arc(P(1, 1), P(1, 14), P(-4, 13), 1),
    g.Arc(P(2, -3), P(7, -3), P(6, 0), 1)])


@settings(max_examples=25, deadline=None)
@given(PIECES, PIECES, st.integers(-9, 9), st.integers(-9, 9),
       st.fractions(F(1, 50), F(49, 50)))
def test_relations_about_moving_points_have_the_signs_of_their_definitions(p1, p2, qx, qy,
                                                                           tau):
    t = Q(tau)
    a, b, q = motion_of(p1), motion_of(p2), still(P(qx, qy))
    pa, pb, pq = p1.at(t), p2.at(t), P(qx, qy)
    if g.cross(g.sub(pb, pa), g.sub(pq, pa)).is_zero():
        return
    cc, _ = g.circumcircle(pa, pb, pq)
    circ = circumcentre_motion(a, b, q)
    assert (peval(circ.nx, t) / peval(circ.d, t), peval(circ.ny, t) / peval(circ.d, t)) == cc
    mid = midpoint_motion(a, b)
    assert (peval(mid.nx, t) / peval(mid.d, t), peval(mid.ny, t) / peval(mid.d, t)) == \
        g.scale(g.add(pa, pb), Q(F(1, 2)))
    z = centroid_motion({0: a, 1: b, 2: q}, [0, 1, 2])
    zt = (peval(z.nx, t) / peval(z.d, t), peval(z.ny, t) / peval(z.d, t))
    assert zt == g.scale(g.add(g.add(pa, pb), pq), Q(F(1, 3)))
    for c, cv in ((circ, cc), (z, zt)):
        sd = peval(c.d, t).sign()              # the moving point's denominator's sign
        for u, pu in ((q, pq), (b, pb)):
            assert peval(tie_about(a, u, c), t).sign() == \
                sd * (g.dist2(pa, cv) - g.dist2(pu, cv)).sign()
            assert peval(ray_about(a, u, c), t).sign() == \
                sd * g.cross(g.sub(pa, cv), g.sub(pu, cv)).sign()
    assert peval(pair_tie(a, b, q, a), t).sign() == \
        (g.dist2(pa, pb) - g.dist2(pq, pa)).sign()


# -- the superset property with 0 or 1 robots standing still ------------------------------
def _symmetric_all_moving(data, kind):
    """Robots symmetric at a rational time ``ts`` under ``kind`` (``mirror``: x -> -x;
    ``half``: p -> -p; ``quarter``: a quarter turn), then a random congruence; at most
    one robot stands still (on the axis / at the centre), every other one moves along a
    random segment through its point at ``ts``."""
    img = {"mirror": lambda p: (-p[0], p[1]), "half": lambda p: (-p[0], -p[1]),
           "quarter": lambda p: (-p[1], p[0])}[kind]
    coord = st.integers(-30, 30).filter(lambda v: v != 0)
    orbits = data.draw(st.integers(2, 3 if kind != "quarter" else 2))
    at_ts = []
    for _ in range(orbits):
        p = (data.draw(coord), data.draw(coord))
        orbit = [p]
        while img(orbit[-1]) != p:
            orbit.append(img(orbit[-1]))
        at_ts += orbit
    still_pts = []
    if data.draw(st.booleans()):
        still_pts = [(0, data.draw(coord)) if kind == "mirror" else (0, 0)]
    elif kind == "mirror" and data.draw(st.booleans()):
        at_ts.append((0, data.draw(coord)))          # a mover on the axis
    ts = data.draw(st.fractions(F(1, 10), F(9, 10), max_denominator=12))
    vel = st.tuples(st.integers(-9, 9), st.integers(-9, 9))
    pieces = []
    for p in at_ts:
        v = data.draw(vel)
        pieces.append(((p[0] - ts * v[0], p[1] - ts * v[1]),
                       (p[0] + (1 - ts) * v[0], p[1] + (1 - ts) * v[1])))
    a, b = data.draw(st.sampled_from([(F(3, 5), F(4, 5)), (F(5, 13), F(-12, 13)),
                                      (F(1), F(0))]))
    fr = Frame(a, b, data.draw(st.booleans()), F(data.draw(st.integers(-5, 5)), 3), F(2))
    start = [fr.to_local(P(*p)) for p in still_pts] + \
        [fr.to_local(P(*s)) for s, _ in pieces]
    movers = {len(still_pts) + k: g.Segment(fr.to_local(P(*s)), fr.to_local(P(*e)))
              for k, (s, e) in enumerate(pieces)}

    def symmetric_at(t):         # before the congruence: closed under the image map
        now = set(still_pts) | {(s[0] + t * (e[0] - s[0]), s[1] + t * (e[1] - s[1]))
                                for s, e in pieces}
        return all(img(p) in now for p in now)
    return start, movers, ts, symmetric_at


def has_symmetry(pts) -> bool:
    """Ground truth for the test (rational points, exact): an isometry other than the
    identity maps ``pts`` onto itself.  It fixes the centroid z and maps a point p0 not
    at z to a point q as far from z: the rotation taking p0 - z to q - z, or the
    reflection in the line through z that swaps them (q = p0: the line through p0)."""
    pts = [(F(x), F(y)) for x, y in pts]
    n = len(pts)
    z = (sum(p[0] for p in pts) / n, sum(p[1] for p in pts) / n)
    rel = {(p[0] - z[0], p[1] - z[1]) for p in pts}
    p0 = next((v for v in sorted(rel) if v != (0, 0)), None)
    if p0 is None:
        return True
    r2 = p0[0] ** 2 + p0[1] ** 2
    for q in rel:
        if q[0] ** 2 + q[1] ** 2 != r2:
            continue
        c, s = (p0[0] * q[0] + p0[1] * q[1]) / r2, (p0[0] * q[1] - p0[1] * q[0]) / r2
        # rotation by (c, s); reflection x -> R(x) with R = [[c', s'], [s', -c']]
        # mapping p0 to q: c' = (p0.x q.x - p0.y q.y) / r2, s' = (p0.y q.x + p0.x q.y) / r2
        cr = (p0[0] * q[0] - p0[1] * q[1]) / r2
        sr = (p0[1] * q[0] + p0[0] * q[1]) / r2
        maps = [] if q == p0 else [lambda v, c=c, s=s: (c * v[0] - s * v[1],
                                                        s * v[0] + c * v[1])]
        maps.append(lambda v, c=cr, s=sr: (c * v[0] + s * v[1], s * v[0] - c * v[1]))
        if any(all(m(v) in rel for v in rel) for m in maps):
            return True
    return False


def test_has_symmetry_is_the_ground_truth_on_small_examples():
    assert has_symmetry([(1, 0), (-1, 0), (0, 3)])                  # a mirror line
    assert has_symmetry([(1, 1), (1, 2), (-1, -1), (-1, -2)])       # a half turn
    assert has_symmetry([(3, 0), (0, 3), (-3, 0), (0, -3), (1, 0)]) is True   # mirror y = 0
    assert not has_symmetry([(0, 0), (4, 0), (0, 1)])
    assert not has_symmetry([(0, 0), (5, 1), (2, 7), (9, 4)])


@settings(max_examples=40, deadline=None)
@given(st.data(), st.sampled_from(["mirror", "half", "quarter"]))
def test_a_step_with_fewer_than_two_robots_standing_still_that_becomes_symmetric(data,
                                                                                  kind):
    """A time at which the robots are symmetric (and not a moment later) is among the
    roots tagged ``symmetry``, with 0 or 1 robots standing still."""
    start, movers, ts, symmetric_at = _symmetric_all_moving(data, kind)
    assert symmetric_at(ts)
    later = [movers[k].at(Q(ts + F(1, 97))) if k in movers else p
             for k, p in enumerate(start)]
    if has_symmetry([(F(str(p[0])), F(str(p[1]))) for p in later]):
        return             # symmetric a moment later too (by any isometry): no instant
    assert len(start) - len(movers) < 2
    at = [movers[k].at(Q(ts)) if k in movers else p for k, p in enumerate(start)]
    if len({(str(p[0]), str(p[1])) for p in start}) < len(start) or \
            len({(str(p[0]), str(p[1])) for p in at}) < len(at):
        return                                    # two robots at one point: not a state
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


def test_image_polys_of_two_robots_are_empty_and_three_are_not():
    """Two robots are always symmetric (nothing can appear); three moving robots get
    the centroid ties of the first one (its image under a symmetry) at least."""
    ms = {0: motion_of(seg((0, 0), (1, 1))), 1: motion_of(seg((5, 0), (5, 3)))}
    assert image_polys(ms, [0, 1], {0, 1}, []) == []
    ms[2] = motion_of(seg((-4, 7), (2, 9)))
    whats = [w_ for _, w_ in image_polys(ms, [0, 1, 2], {0, 1, 2}, [])]
    assert "robots 0 and 1 as far from the centroid" in whats
    assert "robots 0 and 2 as far from the centroid" in whats


# -- the superset property about R's SEC centre ------------------------------------------
@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(st.integers(-12, 12), st.integers(-12, 12)), min_size=4,
                max_size=4, unique=True),
       st.lists(st.tuples(st.integers(-6, 6), st.integers(-6, 6)), min_size=2, max_size=2))
def test_no_ray_or_tie_about_Rs_sec_centre_changes_inside_a_stretch(r_pts, vel):
    """R = robots 2-5 (robots 0, 1 in the pattern, far away); robots 4 and 5 of R move
    (they may drag R's SEC).  Between two consecutive critical instants the sign of
    every ray and every tie of two robots of R about the true SEC centre of R is the
    same at both ends of the stretch: no relation about the (moving) centre changes
    unseen."""
    pts = [(0, 60), (2, 60)] + r_pts
    pieces = {4: seg(r_pts[2], (r_pts[2][0] + 3 * vel[0][0], r_pts[2][1] + 3 * vel[0][1])),
              5: seg(r_pts[3], (r_pts[3][0] + 3 * vel[1][0], r_pts[3][1] + 3 * vel[1][1]))}
    w = _world(pts, pieces, P(0, 60), r_set={2, 3, 4, 5})

    def signs(t):
        at = {k: pieces[k].at(t) if k in pieces else P(*pts[k]) for k in (2, 3, 4, 5)}
        if len(set(at.values())) < 4:
            return None                               # two robots at one point
        c = g.smallest_enclosing_circle(list(at.values()))[0]
        out = []
        for a in (2, 3, 4, 5):
            for b in range(a + 1, 6):
                out.append(g.cross(g.sub(at[a], c), g.sub(at[b], c)).sign())
                out.append((g.dist2(at[a], c) - g.dist2(at[b], c)).sign())
        return out

    cuts = [F(0)] + [F(int(x.p), int(x.q)) for r in joint_critical_roots(pieces, w)
                     for x in (r.lo, r.hi)] + [F(1)]
    # the open stretches (0, lo_0), (hi_0, lo_1), ..., (hi_last, 1), each by two of its
    # points (its rational ends, or half way to 0 or 1)
    ends = [(a if a > 0 else b / 4, b if b < 1 else (3 + a) / 4)
            for a, b in zip(cuts[::2], cuts[1::2])]
    for a, b in ends:
        sa, sb = signs(Q(a)), signs(Q(b))
        if sa is not None and sb is not None:
            assert sa == sb, (a, b)


# -- metamorphic: an exact congruence moves no instant -----------------------------------
CONGRUENCES = [Frame(F(3, 5), F(4, 5), False, F(7), F(-3)),
               Frame(F(-5, 13), F(12, 13), True, F(1, 2), F(9)),
               Frame(F(1), F(0), True, F(0), F(0))]
SCENES = {"one still": (ONE_STILL, ONE_STILL_PIECES, C1, None),
          "swap": (SWAP, SWAP_PIECES, ORIGIN, None),
          "moving centre": (MOVING, MOVING_PIECES, ORIGIN, R_SET)}


@pytest.mark.parametrize("frame", CONGRUENCES)
@pytest.mark.parametrize("scene", sorted(SCENES))
def test_the_new_instants_survive_an_exact_congruence(scene, frame):
    """A Pythagorean rotation, a translation and a reflection of the whole step give the
    same exact instants with the same families."""
    pts, pieces, centre, r_set = SCENES[scene]

    def key(pts, pieces, centre):
        w = _world(pts, pieces, centre, r_set)
        return sorted((r.exact.text(), tuple(sorted({t[0] for t in r.tags})))
                      for r in joint_critical_roots(pieces, w)
                      if r.exact is not None and not is_tower(r.exact))

    moved = key([frame.to_world(P(*p)) for p in pts],
                {i: frame.piece_to_world(p) for i, p in pieces.items()},
                frame.to_world(centre))
    assert moved == key(pts, pieces, centre)
    assert moved                                      # the scene has exact instants


def test_image_polys_go_on_past_three_assumed_pairs():
    """One robot standing still (0, 0) and six moving: (1, 1) and (1, -1), (-2, 2) and
    (-2, -2) mirror images in the x axis all along, the centroid on it all along, and
    (0, 3) -> (1, 3) with (1, -3) -> (0, -3) mirror images only at tau = 1/2: the
    reflection appears there.  Its branch assumes (0, 0), (1, 2), (2, 1), (3, 4), (4, 3)
    before robot 5's relations name the instant (three pairs were the old bound)."""
    pts = [((0, 0), (0, 0)), ((1, 1), (2, 1)), ((1, -1), (2, -1)), ((-2, 2), (-2, 3)),
           ((-2, -2), (-2, -3)), ((0, 3), (1, 3)), ((1, -3), (0, -3))]
    ms = {k: motion_of(seg(a, b)) for k, (a, b) in enumerate(pts) if k}
    ms[0] = motion_of(seg((0, 0), (0, 0)))
    half = Q(F(1, 2))
    found = [w_ for p, w_ in image_polys(ms, list(range(7)), set(range(1, 7)), [])
             if peval(p, half).is_zero()]
    assert "robots 5 and 6 as far from the centroid" in found
