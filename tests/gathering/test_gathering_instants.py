"""The critical instants of a motion (exactsym.gathering.instants) and the exact root
isolation under them (exactsym.gathering.polyroots): each family fires where its event
happens and stays silent where it does not; roots are exact where the multiquadratic
kernel holds them and isolated by rationals where they need a nested radical."""

from fractions import Fraction as F

from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import geometry as g
from exactsym.gathering.instants import critical_roots, look_points
from exactsym.gathering.motion import motion_of, point_param
from exactsym.gathering.point_sets import mirror_lines
from exactsym.gathering.invariants import Checker
from exactsym.exact.algebraic.polynomials import peval, pmul
from exactsym.exact.algebraic.roots import mq_sqrt, roots_in_unit, separate
from exactsym.gathering.robot import Readings
from exactsym.gathering.world import World

Q = MQ.rational
S2 = sqrt_rational(2)


def poly(*cs):
    return tuple(MQ.coerce(c) for c in cs)


def world(points):
    return World(points, Readings(), checker=Checker())


# -- polyroots -------------------------------------------------------------------------
def test_linear_and_square_discriminant_roots_are_exact():
    (r,) = roots_in_unit(poly(-1, 3))                    # 3f - 1
    assert r.exact == Q(F(1, 3)) and r.lo < fmpq(1, 3) < r.hi
    # (f - 1/4)(f - sqrt(2)/2): discriminant a square in Q(sqrt 2)
    p = pmul(poly(F(-1, 4), 1), (-S2 / 2, Q(1)))
    ex = sorted((r.exact for r in roots_in_unit(p)), key=float)
    assert ex == [Q(F(1, 4)), S2 / 2]
    assert roots_in_unit(poly(1, 0, 1)) == []            # f^2 + 1: no real root
    assert roots_in_unit(poly(-2, 1)) == []              # f = 2: outside (0, 1)
    assert roots_in_unit(()) == []                       # identically zero: no instant


def test_nested_radical_root_is_exact_in_a_tower():
    # f^2 - (sqrt(2) - 1) = 0: f = sqrt(sqrt(2) - 1), a nested radical (~0.6436), held
    # exactly in a tower of quadratic extensions (exactsym.gathering.tower_numbers)
    p = poly(1 - S2, 0, 1)
    (r,) = roots_in_unit(p)
    assert r.exact is not None and not isinstance(r.exact, MQ)
    assert r.exact * r.exact == S2 - 1 and peval(p, r.exact).is_zero()
    assert peval(p, r.lo).sign() * peval(p, r.hi).sign() < 0
    for _ in range(30):
        r.refine()
    assert abs(float(r.lo) - 0.6435942529) < 1e-8 and r.hi - r.lo < fmpq(1, 10 ** 9)


def test_cubic_root_is_isolated_not_guessed():
    # f^3 - 2/5: the cube root of 2/5 (~0.7368) is not expressible by square roots; it
    # is exact in Q(alpha) (algebraic_instants), and its interval still refines exactly
    p = poly(F(-2, 5), 0, 0, 1)
    (r,) = roots_in_unit(p)
    assert r.exact is not None and r.exact ** 3 == Q(F(2, 5)) and r.exact * r.exact != 0
    for _ in range(30):
        r.refine()
    assert abs(float(r.lo) - 0.7368062997) < 1e-8 and r.hi - r.lo < fmpq(1, 10 ** 9)


def test_quartic_roots_by_sturm():
    # (f - 1/3)(f - 1/2)(f^2 - 2/9) on (0, 1): 1/3, 1/2 and sqrt(2)/3 ~ 0.4714
    p = pmul(pmul(poly(F(-1, 3), 1), poly(F(-1, 2), 1)), poly(F(-2, 9), 0, 1))
    roots = separate(roots_in_unit(p))
    assert len(roots) == 3
    assert [r.exact for r in roots if r.exact is not None] == [Q(F(1, 3)), Q(F(1, 2))] or \
        all(peval(p, r.lo).sign() * peval(p, r.hi).sign() < 0 or r.exact is not None
            for r in roots)
    mids = sorted(float((r.lo + r.hi) / 2) for r in roots)
    assert abs(mids[1] - 2 ** 0.5 / 3) < 0.05


def test_separate_merges_a_common_root_and_keeps_distinct_ones_apart():
    a = roots_in_unit(poly(1 - S2, 0, 1), "a")                  # sqrt(sqrt2 - 1)
    b = roots_in_unit(pmul(poly(1 - S2, 0, 1), poly(F(-1, 5), 1)), "b")   # same, and 1/5
    roots = separate(a + b)
    assert len(roots) == 2
    merged = [r for r in roots if len(r.tags) == 2]
    assert len(merged) == 1 and sorted(merged[0].tags) == ["a", "b"]
    assert all(x.hi < y.lo for x, y in zip(roots, roots[1:]))


def test_separate_merges_many_repeats_of_one_irrational_root():
    # a sweep run met 27 roots, most of them one root found by several families, each
    # by another polynomial: a fixed budget of 400 refinements ran out (here at 30 copies)
    p = poly(1 - S2, 0, 1)                                      # sqrt(sqrt2 - 1)
    copies = [r for k in range(40) for r in roots_in_unit(pmul(p, poly(F(k + 2), 1)), k)]
    roots = separate(copies)
    assert len(roots) == 1 and sorted(roots[0].tags) == list(range(40))


def test_mq_sqrt_denests_or_declines():
    assert mq_sqrt(3 + 2 * S2) == 1 + S2
    assert mq_sqrt(Q(F(9, 4))) == Q(F(3, 2))
    assert mq_sqrt(1 + S2) is None                               # sqrt(1 + sqrt 2)
    assert mq_sqrt(Q(-1)) is None


# -- the motion as a rational curve ---------------------------------------------------
@settings(max_examples=25, deadline=None)
@given(st.fractions(0, 1), st.integers(-9, 9), st.integers(1, 9))
def test_motion_matches_piece_at(f, t_num, t_den):
    arc_end = g.rotate(g.point(5, 0), Q(F(3, 5)), Q(F(4, 5)))    # a rational quarter-ish turn
    pieces = [g.Segment(g.point(t_num, 1), g.point(3, F(t_num, t_den))),
              g.Arc(g.point(1, 2), g.add(g.point(1, 2), g.point(5, 0)),
                    g.add(g.point(1, 2), arc_end), 1)]
    for piece in pieces:
        m = motion_of(piece)
        d = peval(m.d, Q(f))
        assert piece.at(Q(f)) == (peval(m.nx, Q(f)) / d, peval(m.ny, Q(f)) / d)
        if 0 < f < 1 and piece.start != piece.end:
            assert point_param(piece, piece.at(Q(f))) == Q(f)
        elif piece.start == piece.end:
            assert point_param(piece, piece.at(Q(f))) is None      # no motion, no instant


# -- the families -----------------------------------------------------------------------
def _families(roots):
    return {t[0] for r in roots for t in r.tags}


def test_sec_support_change_fires_where_the_mover_crosses_the_others_sec():
    # the others' SEC: the circle of radius 10 about the origin (robots 1..4); the mover
    # runs from inside (5, 0) to outside (15, 0): it crosses the circle at x = 10
    pts = [(5, 0), (10, 0), (0, 10), (-10, 0), (0, -10)]
    w = world(pts)
    seg = g.Segment(g.point(5, 0), g.point(15, 0))
    roots = critical_roots(seg, w, 0, None)
    sec = [r for r in roots if any(t[0] == "sec" and "crosses the SEC" in t[1] for t in r.tags)]
    assert len(sec) == 1 and sec[0].exact == Q(F(1, 2))
    # holds: a move inside the SEC that stays inside has no SEC instant
    inside = g.Segment(g.point(5, 0), g.point(2, 3))
    assert "sec" not in _families(critical_roots(inside, w, 0, None))


def test_sec_support_change_with_the_mover_a_support():
    # outside the others' SEC the mover is a support; the SEC on the diameter mover-robot 1
    # takes robot 2 on its boundary where the angle at robot 2 is right
    pts = [(30, 1), (-10, 0), (0, 10), (0, -10), (1, 1)]
    w = world(pts)
    seg = g.Segment(g.point(30, 1), g.point(30, 40))
    roots = critical_roots(seg, w, 0, None)
    tags = [t[1] for r in roots for t in r.tags if t[0] == "sec"]
    assert any("diameter mover-1" in t for t in tags), tags
    # at each exact SEC instant of that kind, robot q is exactly on the circle
    for r in roots:
        for fam, what in r.tags:
            if fam == "sec" and what.startswith("SEC of all: robot ") and r.exact is not None:
                q = int(what.split()[4])
                a = int(what.split("mover-")[1])
                p = seg.at(r.exact)
                assert g.dot(g.sub(w.robots[q].pos, p), g.sub(w.robots[q].pos,
                                                             w.robots[a].pos)).is_zero()


def test_symmetry_appears_where_the_mover_reaches_a_mirror_image():
    # robots 1..4 symmetric about the y axis except robot 4; the mover passes through the
    # mirror image of robot 4 (-7, 3) -> (7, 3): there all five robots are symmetric
    pts = [(7, -30), (10, 20), (-10, 20), (0, -20), (-7, 3)]
    w = world(pts)
    seg = g.Segment(g.point(7, -30), g.point(7, 30))
    roots = critical_roots(seg, w, 0, g.point(0, 0))
    hits = [r for r in roots if any("mirror image of robot 4" in t[1] for t in r.tags)]
    assert len(hits) == 1 and seg.at(hits[0].exact) == g.point(7, 3)
    at = [seg.at(hits[0].exact)] + [w.robots[k].pos for k in range(1, 5)]
    assert mirror_lines(at, g.point(0, F(23, 5)))      # a mirror line through the centroid
    # holds: moved off the mirror image, no such instant
    seg2 = g.Segment(g.point(8, -30), g.point(8, 30))
    assert not [r for r in critical_roots(seg2, w, 0, g.point(0, 0))
                if any("mirror image" in t[1] for t in r.tags)]


def test_mirror_lines_exact():
    sq = [g.point(1, 1), g.point(-1, 1), g.point(-1, -1), g.point(1, -1)]
    assert len(mirror_lines(sq, g.point(0, 0))) == 4
    assert mirror_lines([g.point(1, 0), g.point(0, 2), g.point(-3, -1)], g.point(0, 0)) == []


def test_distance_tie_with_a_nested_radical_is_checked_at_the_instant():
    # the mover on a segment from (sqrt2, 1) to (sqrt2, 9), C = 0; robot 1 at squared
    # distance 7 + 4 sqrt2: the tie is at y^2 = 5 + 4 sqrt2, whose root is not in any
    # multiquadratic field (25 - 32 < 0: no denesting), a nested radical: the instant is
    # a number of a tower, and the Look there sees the two distances exactly equal
    pts = [(0, 0), (0, 30), (21, 0), (-40, 1), (0, -40)]
    w = world(pts)
    start = (S2, Q(1))
    seg = g.Segment(start, (S2, Q(9)))
    w.robots[0].pos = start
    w.robots[1].pos = (Q(1), 2 + S2)
    roots = critical_roots(seg, w, 0, g.point(0, 0))
    ties = [r for r in roots if any(t[0] == "distance" and "robot 1" in t[1] for t in r.tags)]
    assert len(ties) == 1
    r = ties[0]
    assert r.exact is not None and not isinstance(r.exact, MQ)
    points, sided = look_points(seg, w, 0, g.point(0, 0))
    assert sided == 0
    d1 = g.dist2(w.robots[1].pos, g.point(0, 0))
    at = [p for p in points if p.exact and "distance" in p.families]
    assert len(at) == 1 and g.dist2(at[0].point, g.point(0, 0)) == d1
    assert at[0].point[1] * at[0].point[1] == 5 + 4 * S2
    # the Look points between instants are in the field and on both sides of the tie
    signs = {(g.dist2(p.point, g.point(0, 0)) - d1).sign() for p in points}
    assert signs == {-1, 0, 1}


def test_mq_sqrt_over_several_radicals():
    s3, s6, s7 = sqrt_rational(3), sqrt_rational(6), sqrt_rational(7)
    y = 3 + S2 - 2 * s3 + s6 / 5
    assert mq_sqrt(y * y) == abs(y)
    assert mq_sqrt(y * y * 7) == abs(y) * s7          # a new radical outside y's field
    assert mq_sqrt(5 + 4 * S2) is None


def test_ray_crossing_on_an_arc_is_exact_in_a_larger_field():
    # an arc about C = 0 of radius sqrt(2)-scaled coordinates crossing the line through
    # C and robot 1 at (3, 7): the crossing point needs sqrt(58) and the arc's radicals
    start = (5 * S2, Q(1))
    arc = g.Arc(g.point(0, 0), start, g.rotate(start, Q(0), Q(1)), 1)
    w = world([(7, 1), (3, 7), (-30, 0), (0, -30), (30, 30)])
    w.robots[0].pos = start
    roots = critical_roots(arc, w, 0, g.point(0, 0))
    ray = [r for r in roots if any("robot 1" in t[1] and t[0] == "ray" for t in r.tags)]
    assert len(ray) == 1 and ray[0].exact is not None
    p = arc.at(ray[0].exact)
    assert g.cross(p, g.point(3, 7)).is_zero() and g.dot(p, g.point(3, 7)).sign() > 0


# -- the checker: I3 and I9 at the instants -------------------------------------------
def _sec_points():
    def P(t, r=20):
        cs, sn = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
        return (r * cs, r * sn)
    return [P(F(0)), P(F(1, 11)), P(F(1, 6)), P(F(4, 15)), (-20, 0)]


def test_I3_fires_in_the_stretch_before_an_sec_instant():
    """Robot 2 moves to C, then robot 0 leaves the SEC on its one-piece move to layer 1:
    only the Looks at and between critical instants see another mover elected (there is
    no piece end inside that move)."""
    from exactsym.gathering.schedulers import run
    from exactsym.gathering.world import Frame
    acts = [("look", 2, Frame(F(20, 113), F(448, 339), False, F(2, 3), F(17, 7))),
            ("advance", 2, None), ("look", 2, Frame(F(-55, 122), F(-150, 61), True,
                                                    F(-16, 3), F(1, 7))),
            ("look", 0, Frame(F(5, 39), F(4, 13), True, F(19, 3), F(20, 7))),
            ("advance", 0, None)]
    actions = [{"a": a, "robot": r, "frame": f.as_list()} if a == "look" else
               {"a": a, "robot": r, "stop": None, "end": False} for a, r, f in acts]
    res = run(_sec_points(), checker=Checker(enabled=frozenset({"I3"})), actions=actions)
    v = res.violation
    assert v["invariant"] == "I3" and v["label"] == "FormGPattern (L1642-1643)"
    assert v["robots"] == [0, 2] and v["instant"] == 5
    assert "SEC of all: right angle at the mover (diameter 1-4)" in v["witness"]
    assert res.checks["instants"] >= 1


def test_I3_holds_at_the_instants_of_a_move_that_keeps_everything():
    """ONE_CIRCLE: robot 3 goes to C along the y axis; the SEC keeps (20,0) and (-20,0)
    and the fresh Looks at and between its instants plan the same move."""
    from exactsym.gathering.world import IDENTITY
    w = World([(20, 0), (0, 20), (-20, 0), (0, -20), (12, 16)], Readings(),
              checker=Checker(enabled=frozenset({"I3"})))
    w.look(3, IDENTITY)
    w.advance(3, F(1, 2))
    w.advance(3)
    assert w.checker.counts["I3"] == 2 and w.robots[3].pos == g.point(0, 0)


def test_I9_holds_at_the_sec_and_symmetry_instants_of_the_corrected_variant():
    """The corrected variant decides by distances and dot products only: the reflected
    frame's fresh Looks at the SEC and symmetry instants agree (I9 counts them)."""
    from exactsym.gathering.schedulers import run
    res = run([(F(3, 2), 0), (F(-9, 5), 0), (8, 6), (-6, 8), (0, -10)], "centralised", 0,
              algorithm="corrected")
    assert res.outcome == "gathered"
    assert res.checks["I9"] > res.looks // 2 + 1 and res.checks["instants"] > 0


def test_look_points_are_ordered_strictly_inside_and_cover_every_stretch():
    pts = [(30, 1), (-10, 0), (0, 10), (0, -10), (1, 1)]
    w = world(pts)
    seg = g.Segment(g.point(30, 1), g.point(30, 40))
    points, sided = look_points(seg, w, 0, None)
    fs = [p.f for p in points]
    assert all(0 < float(f) < 1 for f in fs)
    assert all((b - a).sign() > 0 for a, b in zip(fs, fs[1:]))
    roots = critical_roots(seg, w, 0, None)
    # every root lies strictly between two consecutive non-exact Look points
    sides = [p.f for p in points if not p.exact]
    assert len(sides) == len(roots) + 1
    for k, r in enumerate(roots):
        assert (sides[k] - Q(r.lo)).sign() <= 0 and (sides[k + 1] - Q(r.hi)).sign() >= 0


def test_I6_fires_inside_a_piece_whose_ends_keep_C():
    """The mover is an SEC support with robots 1 and 2 (acute triangle, C = 0 at both
    ends of its chord of the circle of radius 25); inside the chord the SEC shrinks and C
    moves: only the Look inside the piece sees it."""
    from exactsym.gathering.world import World
    pts = [(24, -7), (-15, 20), (-15, -20), (1, 2), (-3, 1)]
    w = World(pts, Readings(), checker=Checker(enabled=frozenset({"I6"})))
    rob = w.robots[0]
    assert g.smallest_enclosing_circle(w.positions())[0] == g.point(0, 0)
    end = g.point(24, 7)
    rob.path, rob.role, rob.centre, rob.start = [g.Segment(rob.pos, end)], "leader", \
        g.point(0, 0), rob.pos
    import pytest
    from exactsym.gathering.invariants import Violation
    with pytest.raises(Violation) as err:
        w.advance(0)
    assert err.value.invariant == "I6" and err.value.label == "conclusion (L1708-1710)"
    assert "half way" in err.value.witness or "just" in err.value.witness
    # holds: the same chord with the SEC held by robots 1 and 2 and a third far support
    pts2 = pts + [(25, 0)]
    w = World(pts2, Readings(), checker=Checker(enabled=frozenset({"I6"})))
    rob = w.robots[0]
    rob.path, rob.role, rob.centre, rob.start = [g.Segment(rob.pos, end)], "leader", \
        g.point(0, 0), rob.pos
    w.advance(0)
    assert w.checker.counts["I6"] >= 2


def test_pattern_family_layers_and_contacts():
    w = world([(7, 0), (5, 2), (-30, 0), (0, 30), (0, -30)])
    seg = g.Segment(g.point(7, 0), g.point(1, 0))
    roots = critical_roots(seg, w, 0, g.point(0, 0))
    pattern = {t[1]: r.exact for r in roots for t in r.tags if t[0] == "pattern"}
    assert pattern["on the circle of layer 1"] == Q(F(5, 6))      # x = 2
    assert pattern["touching robot 1"] == Q(F(1, 3))              # x = 5, tangent
    # five robots: layer 2 (x = 4) and 3 (x = 6) can hold no robot of a pattern (the
    # inner layers would need 1 + 6 robots)
    assert set(pattern) == {"on the circle of layer 1", "touching robot 1"}
    short = g.Segment(g.point(F(9, 2), 0), g.point(F(11, 2), 0))
    w.robots[0].pos = short.start
    tags = [t[1] for r in critical_roots(short, w, 0, g.point(0, 0)) for t in r.tags
            if t[0] == "pattern"]
    assert tags == ["touching robot 1"]                            # no layer's circle


def test_instants_are_invariant_under_an_exact_similarity():
    """A Pythagorean rotation, a scale and a translation (a reflection too) move no
    instant: the same exact parameters, the same families."""
    from exactsym.gathering.world import Frame
    pts = [(30, 1), (-10, 0), (0, 10), (0, -10), (1, 1)]
    seg = g.Segment(g.point(30, 1), g.point(30, 40))
    base = critical_roots(seg, world(pts), 0, g.point(0, 0))

    def key(roots):
        return sorted((str(r.exact), tuple(sorted(t[0] for t in r.tags)))
                      for r in roots if r.exact is not None)

    for fr in (Frame(F(6, 5), F(8, 5), False, F(1, 3), F(-2)),
               Frame(F(3, 5), F(-4, 5), True, F(7), F(5, 2))):
        # the local coordinates are the world's under the similarity; distances scale,
        # so the layer and contact radii are not similarity-invariant: compare the
        # families that are (ray, distance, sec, symmetry)
        moved = [tuple(fr.to_local((MQ.coerce(x), MQ.coerce(y)))) for x, y in pts]
        w2 = world([(i, 100 * i) for i in range(5)])      # placeholders, moved below
        for rob, p in zip(w2.robots, moved):
            rob.pos = p
        seg2 = g.Segment(fr.to_local(seg.start), fr.to_local(seg.end))
        got = critical_roots(seg2, w2, 0, fr.to_local(g.point(0, 0)))

        def inv(roots):
            return [k for k in key(roots) if "pattern" not in k[1]]
        assert len(inv(base)) >= 3 and inv(got) == inv(base)


# -- joint motions (exactsym.gathering.joint_instants) ------------------------------------
def test_joint_relations_have_their_exact_instants():
    from exactsym.gathering.joint_instants import (contact_poly, incircle_poly, ray_poly,
                                                   right_poly, still, tie_poly)
    P = g.point
    m0 = motion_of(g.Segment(P(10, 0), P(0, 0)))           # |p0| = 10 - 10 tau
    m1 = motion_of(g.Segment(P(0, 2), P(0, 10)))           # |p1| = 2 + 8 tau
    c = P(0, 0)
    assert [r.exact for r in roots_in_unit(tie_poly(m0, m1, c))] == [Q(F(4, 9))]
    # (10, -5 + 10 tau) and the still (-10, 2): on one line through C at tau = 3/10
    m2 = motion_of(g.Segment(P(10, -5), P(10, 5)))
    assert [r.exact for r in roots_in_unit(ray_poly(m2, still(P(-10, 2)), c))] == [Q(F(3, 10))]
    # two robots 2 apart: (10 - 10 tau, 0) and (0, 2 + 8 tau) never (>= 2 sqrt(...)),
    # (10 - 10 tau, 0) and the still (3, 0) at tau = 1/2 and 9/10
    assert roots_in_unit(contact_poly(m0, m1, Q(4))) == []
    ex = sorted((r.exact for r in roots_in_unit(contact_poly(m0, still(P(3, 0)), Q(4)))),
                key=float)
    assert ex == [Q(F(1, 2)), Q(F(9, 10))]
    # the moving q = (10 - 10 tau, 0) on the circle on the diameter (-4, 0)-(4, 0) at
    # tau = 3/5 (|q| = 4), and on the circle through (4, 0), (0, 4), (-4, 0) then too
    assert [r.exact for r in roots_in_unit(right_poly(m0, still(P(-4, 0)),
                                                      still(P(4, 0))))] == [Q(F(3, 5))]
    four = [m0, still(P(4, 0)), still(P(0, 4)), still(P(-4, 0))]
    # (4, 0) is one of the three: the determinant vanishes where q meets it, tau = 3/5
    assert [r.exact for r in roots_in_unit(incircle_poly(four))] == [Q(F(3, 5))]
    four = [m0, still(P(0, -4)), still(P(0, 4)), still(P(-4, 0))]
    assert [r.exact for r in roots_in_unit(incircle_poly(four))] == [Q(F(3, 5))]


def test_joint_look_points_cover_each_stretch_and_each_exact_instant():
    from exactsym.gathering.joint_instants import joint_critical_roots, joint_look_points
    P = g.point
    w = World([(0, -10), (-20, 6), (30, 30), (-30, 30), (0, -40)], Readings())
    w.robots[0].centre = P(0, 0)
    pieces = {0: g.Segment(P(0, -10), P(0, -5)), 1: g.Segment(P(-20, 6), P(20, 6))}
    roots = joint_critical_roots(pieces, w)
    tags = [t for r in roots for t in r.tags]
    assert ("distance", "robots 0 and 1 as far from C") in tags
    assert ("ray", "robots 0 and 1 on one line through C") in tags
    pts, sided = joint_look_points(pieces, w)
    taus = [p.tau for p in pts]
    assert all(a < b for a, b in zip(taus, taus[1:]))           # in order, distinct
    assert all(Q(0) < t < Q(1) for t in taus)
    assert sum(not p.exact for p in pts) == len(roots) + 1      # one per stretch
    assert sum(p.exact for p in pts) + sided == len(roots)
    # a robot standing still everywhere and no movers near: no instant, half way
    far = {1: g.Segment(P(-20, 6), P(-19, 6))}
    w.robots[1].centre = P(0, 0)
    pts, _ = joint_look_points(far, w)
    assert [p.tau for p in pts] == [Q(F(1, 2))]


@settings(max_examples=200, deadline=None)
@given(st.tuples(st.integers(-40, 40), st.integers(-40, 40), st.integers(-40, 40)),
       st.integers(1, 9), st.booleans())
def test_a_quadratic_with_no_root_inside_is_skipped_before_its_square_root(cs, den, rad):
    """polyroots._none_inside (signs of the ends, the vertex and the discriminant) says
    "none" exactly when Sturm's isolation finds no root of the quadratic in (0, 1): the
    early exit changes no list."""
    from exactsym.exact.algebraic.roots import _isolate, _none_inside
    c, b, a = (Q(F(k, den)) for k in cs)
    if rad:
        b = b + S2
    if a.is_zero():
        return
    p = (c, b, a)
    if c.is_zero() or (a + b + c).is_zero():
        assert not _none_inside(p)
        return
    assert _none_inside(p) == (not _isolate(p, fmpq(0), fmpq(1), None))


@settings(max_examples=150, deadline=None)
@given(st.sampled_from([F(-1), F(0), F(1, 3), F(1, 2), F(1), F(3, 2)]),
       st.sampled_from([F(-1, 2), F(0), F(1, 4), F(1, 2), F(1), F(2)]),
       st.integers(-3, 3).filter(bool), st.booleans())
def test_the_quadratic_count_on_ties_at_the_ends_and_double_roots(r1, r2, lead, shift):
    """Roots placed on the ends, equal to each other, or moved by sqrt 2 / 10: the sign
    count agrees with Sturm's isolation (double roots included)."""
    from exactsym.exact.algebraic.roots import _isolate, _none_inside
    a = Q(F(lead))
    s = Q(F(r1 + r2)) + (S2 / 10 if shift else Q(F(0)))
    p = (a * Q(F(r1 * r2)), -(a * s), a)
    c, b, _ = p
    if c.is_zero() or (a + b + c).is_zero():
        assert not _none_inside(p)
        return
    assert _none_inside(p) == (not _isolate(p, fmpq(0), fmpq(1), None))


@settings(max_examples=150, deadline=None)
@given(st.tuples(st.integers(-6, 6), st.integers(-6, 6).filter(bool)),
       st.lists(st.integers(-6, 6), min_size=1, max_size=4), st.booleans(), st.booleans())
def test_gcd_with_a_linear_factor_is_division_free_and_exact(line, cofactor, divisible, rad):
    """polyroots.pgcd with a linear argument (the homogeneous evaluation at its root)
    finds the common factor exactly when Euclid's remainder vanishes."""
    from exactsym.exact.algebraic.polynomials import pdivmod, pgcd, pmul, trim
    lin = (Q(F(line[0])) + (S2 if rad else Q(F(0))), Q(F(line[1])))
    other = trim(tuple(Q(F(k)) for k in cofactor))
    if divisible:
        other = pmul(lin, other) if other else ()
    else:
        other = trim(tuple(c + Q(F(1)) if k == 0 else c for k, c in enumerate(other or (Q(F(0)),))))
    if len(other) <= 1:
        return
    divides = not pdivmod(other, lin)[1]
    for a, b in ((lin, other), (other, lin)):
        g = pgcd(a, b)
        assert (len(g) > 1) == divides
        if divides:                             # lin up to a non-zero factor
            assert len(g) == 2 and g[0] * lin[1] == g[1] * lin[0]


@settings(max_examples=100, deadline=None)
@given(st.lists(st.integers(-5, 5), min_size=1, max_size=3),
       st.lists(st.integers(-5, 5), min_size=2, max_size=3),
       st.lists(st.integers(-5, 5), min_size=2, max_size=3), st.booleans())
def test_the_pseudo_remainder_gcd_finds_a_planted_common_factor(common, u, v, rad):
    """pgcd(c u, c v) is c up to a factor when u and v are coprime (checked by their
    resultant-free test: their gcd is a constant), and has c's degree."""
    from exactsym.exact.algebraic.polynomials import pgcd, pmul, trim
    def poly(ks, shift=False):
        return trim(tuple(Q(F(k)) + (S2 if shift and i == 0 else Q(F(0)))
                          for i, k in enumerate(ks)))
    c, a, b = poly(common, rad), poly(u), poly(v)
    if not c or len(a) < 2 or len(b) < 2 or len(pgcd(a, b)) > 1:
        return
    g = pgcd(pmul(c, a), pmul(c, b))
    assert len(g) == len(c)
    # g = lambda c: every cross product of coefficients vanishes
    assert all((g[i] * c[j] - g[j] * c[i]).is_zero()
               for i in range(len(c)) for j in range(len(c)))


@settings(max_examples=100, deadline=None)
@given(st.lists(st.integers(-4, 4), min_size=2, max_size=3),
       st.lists(st.integers(-4, 4), min_size=2, max_size=3), st.booleans(), st.booleans())
def test_the_squarefree_filter_never_passes_a_square_factor(u, v, square, rad):
    """polyroots._surely_squarefree proves square-freeness only: never True for u^2 v,
    and squarefree() keeps the same distinct roots whether the filter answers or not."""
    from exactsym.exact.algebraic.polynomials import pgcd, pderiv, pmul, trim
    from exactsym.exact.algebraic.sturm import surely_squarefree as _surely_squarefree
    def poly(ks, shift=False):
        return trim(tuple(Q(F(k)) + (S2 if shift and i == 0 else Q(F(0)))
                          for i, k in enumerate(ks)))
    a, b = poly(u, rad), poly(v)
    if len(a) < 2 or len(b) < 1:
        return
    p = pmul(pmul(a, a), b) if square else pmul(a, b)
    if len(p) < 3:
        return
    if _surely_squarefree(p):
        assert len(pgcd(p, pderiv(p))) <= 1
    if square:
        assert not _surely_squarefree(p)
    elif len(pgcd(p, pderiv(p))) <= 1:          # small integers: 128 bits decide it
        assert _surely_squarefree(p)
