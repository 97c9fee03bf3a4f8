"""Simultaneous motion in continuous time: two discs moving at once (the exact predicate),
joint steps of the world (I1 between movers, the other invariants at the interval's end),
the schedulers moving their movers together, traces with joint steps, and the search."""

from fractions import Fraction as F

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from exactsym.exact.multiquadratic import MQ
from exactsym.gathering import geometry as g
from exactsym.gathering.invariants import ALL, Checker, Violation
from exactsym.gathering.robot import Readings
from exactsym.gathering.schedulers import run
from exactsym.gathering.world import IDENTITY as MIRROR_FREE, World

P = g.point
ONE_CIRCLE = [(20, 0), (0, 20), (-20, 0), (0, -20), (12, 16)]
#: the invariants with which two leaders of opposite handedness get to move at once
NO_I2_I9 = sorted(set(ALL) - {"I2", "I9"})


def seg(a, b):
    return g.Segment(P(*a), P(*b))


def dist2_at(p1, p2, tau):
    t = MQ.rational(tau)
    return g.dist2(p1.at(t), p2.at(t))


# -- the predicate ---------------------------------------------------------------------
def test_crossing_movers_meet_in_the_middle():
    """Two robots crossing at right angles: any order of full moves is free, together
    they meet at the crossing at time 1/2."""
    a, b = seg((0, -5), (0, 5)), seg((-5, 0), (5, 0))
    assert g.joint_motion_overlap(a, b) == F(1, 2)
    for p in (a.start, a.end):                 # one robot still at an end: free
        assert not g.piece_hits(b, p)
    # the same two paths with robot b starting later (its first half only): free
    assert g.joint_motion_overlap(seg((0, -5), (0, 5)), seg((-5, 0), (-3, 0))) is None


def test_touching_all_along_and_following_are_allowed():
    assert g.joint_motion_overlap(seg((0, 0), (10, 0)), seg((0, 2), (10, 2))) is None
    assert g.joint_motion_overlap(seg((0, 0), (10, 0)), seg((-3, 0), (7, 0))) is None
    assert g.joint_motion_overlap(seg((0, 0), (10, 0)), seg((0, 3), (10, 3))) is None
    # the follower is faster: it catches up at time 1/2 (squared distance 1/4 then)
    tau = g.joint_motion_overlap(seg((0, 0), (10, 0)), seg((-3, 0), (9, 0)))
    assert tau is not None and dist2_at(seg((0, 0), (10, 0)), seg((-3, 0), (9, 0)), tau) < 4


def test_arcs_sliding_towards_each_other():
    """Two quarter arcs of radius 4 about the origin, one counter-clockwise from (4, 0),
    the other clockwise from (0, 4): they meet on the diagonal at time 1/2."""
    up = g.Arc(P(0, 0), P(4, 0), P(0, 4), 1)
    down = g.Arc(P(0, 0), P(0, 4), P(4, 0), -1)
    assert g.joint_motion_overlap(up, down) == F(1, 2)
    # the same sense of turning, a quarter turn apart: always 4 sqrt(2) apart
    ahead = g.Arc(P(0, 0), P(0, 4), P(-4, 0), 1)
    assert g.joint_motion_overlap(up, ahead) is None
    # an arc against a segment crossing its chord
    assert g.joint_motion_overlap(up, seg((0, 4), (4, 0))) == F(1, 2)
    assert g.joint_motion_overlap(up, seg((0, -4), (4, -8))) is None


def test_irrational_contact_instants_are_isolated_exactly():
    """Contact at tau = 1 - 1/(10 sqrt 2) (both heading for the origin): the witness is
    a rational instant after it, and no rational instant before it overlaps."""
    a, b = seg((-20, 0), (0, 0)), seg((0, -20), (0, 0))
    tau = g.joint_motion_overlap(a, b)
    assert tau == F(14, 15) and dist2_at(a, b, tau) == MQ.rational(F(32, 9))
    assert dist2_at(a, b, F(13, 14)) > 4         # 13/14 < 1 - 1/(10 sqrt 2) < 14/15


def test_radical_coordinates_go_through_the_norm():
    """A piece with coordinates in Q(sqrt 2): the polynomial's coefficients are
    irrational and the roots come from its rational norm."""
    s2 = MQ.sqrt(2)
    arc = g.Arc(P(0, 0), (s2 * 2, s2 * 2), P(0, 4), 1)       # radius 4, 45 -> 90 degrees
    f = g.joint_gap_polynomial(arc, seg((0, 4), (3, 3)))
    assert any(not c.is_rational() for c in f)
    tau = g.joint_motion_overlap(arc, seg((0, 4), (3, 3)))
    assert tau is not None and dist2_at(arc, seg((0, 4), (3, 3)), tau) < 4
    assert g.joint_motion_overlap(arc, seg((s2 * 5, MQ()), (s2 * 5, s2 * 5))) is None


def _pythagorean(t):
    return ((1 - t * t) / (1 + t * t), 2 * t / (1 + t * t))


@st.composite
def pieces(draw):
    c = (draw(st.integers(-6, 6)), draw(st.integers(-6, 6)))
    if draw(st.booleans()):
        return seg(c, (draw(st.integers(-6, 6)), draw(st.integers(-6, 6))))
    r = draw(st.integers(1, 6))
    t0 = F(draw(st.integers(-9, 9)), draw(st.integers(1, 5)))
    k = F(draw(st.integers(-5, 5).filter(bool)), 5)           # at most a quarter turn
    u = _pythagorean(t0)
    start = (c[0] + r * u[0], c[1] + r * u[1])
    cs, sn = _pythagorean(k)
    v = (r * u[0], r * u[1])
    end = (c[0] + v[0] * cs - v[1] * sn, c[1] + v[0] * sn + v[1] * cs)
    return g.Arc(P(*c), P(*start), P(*end), 1 if k > 0 else -1)


@settings(max_examples=60, deadline=None)
@given(pieces(), pieces())
def test_overlap_verdict_agrees_with_exact_samples_and_is_symmetric(p1, p2):
    """A witness instant is an overlap; no verdict: no rational sample overlaps; the
    verdict does not depend on the order of the two robots."""
    tau = g.joint_motion_overlap(p1, p2)
    assert (tau is None) == (g.joint_motion_overlap(p2, p1) is None)
    if tau is not None:
        assert 0 <= tau <= 1 and dist2_at(p1, p2, tau) < 4
    else:
        assert all(dist2_at(p1, p2, F(j, 40)) >= 4 for j in range(41))


@settings(max_examples=30, deadline=None)
@given(pieces(), pieces(), st.integers(-9, 9), st.integers(-9, 9),
       st.sampled_from([F(0), F(1, 2), F(-3), F(2, 7)]))
def test_overlap_verdict_is_invariant_under_a_rigid_motion(p1, p2, dx, dy, t):
    """A Pythagorean rotation and a translation applied to both paths change nothing."""
    cs, sn = (MQ.rational(x) for x in _pythagorean(t))

    def move(p):
        return (p[0] * cs - p[1] * sn + dx, p[0] * sn + p[1] * cs + dy)

    def moved(pc):
        if isinstance(pc, g.Segment):
            return g.Segment(move(pc.start), move(pc.end))
        return g.Arc(move(pc.centre), move(pc.start), move(pc.end), pc.sense)
    assert (g.joint_motion_overlap(p1, p2) is None) == \
        (g.joint_motion_overlap(moved(p1), moved(p2)) is None)


# -- the world -------------------------------------------------------------------------
SQUARE = [(0, 0), (4, 0), (4, 4), (0, 4), (30, 30)]


def _square_world(checker):
    """Four robots on a square of side 4, each about to move to the next corner."""
    w = World(SQUARE, checker=checker)
    for i in range(4):
        rob = w.robots[i]
        rob.path, rob.start = [g.Segment(rob.pos, w.robots[(i + 1) % 4].pos)], rob.pos
    return w


def test_a_cyclic_shift_is_free_together_and_collides_one_at_a_time():
    """Moving together (closest approach 2 sqrt 2) is free; every interleaving of full
    moves puts the first robot onto an occupied corner."""
    w = _square_world(Checker(enabled=frozenset({"I1"})))
    w.advance_together([(i, None, False) for i in range(4)])
    assert w.positions()[:4] == tuple(P(*p) for p in SQUARE[1:4] + SQUARE[:1])
    assert w.checker.counts["I1"] >= 4 and w.events == 1 and not w.busy()
    w = _square_world(Checker(enabled=frozenset({"I1"})))
    with pytest.raises(Violation) as err:
        w.advance(0)
    assert err.value.invariant == "I1" and err.value.robots == (0, 1)


def test_the_joint_check_is_the_checkers_and_counted_like_the_others():
    """``Checker.after_step`` holds the joint I1 check: called on its own it counts one
    check per mover and fires on the crossing pair; with I1 off it neither counts nor
    fires; in a world step each mover is counted twice (the joint check over the
    interval, the per-robot check at its end)."""
    w = _square_world(Checker(enabled=frozenset({"I1"})))
    w.advance_together([(i, None, False) for i in range(4)])
    assert w.checker.counts["I1"] == 8
    crossing = {0: seg((0, -5), (0, 5)), 1: seg((-5, 0), (5, 0))}
    w = World([(0, -5), (-5, 0), (20, 20), (-20, 20), (20, -20)])
    on, off = Checker(enabled=frozenset({"I1"})), Checker(enabled=frozenset({"I3"}))
    off.after_step(w, crossing)
    assert off.counts["I1"] == 0
    with pytest.raises(Violation) as err:
        on.after_step(w, crossing)
    assert on.counts["I1"] == 2 and err.value.robots == (0, 1)
    on.after_step(w, {0: seg((0, -5), (0, -9)), 1: seg((-5, 0), (-9, 0))})
    assert on.counts["I1"] == 4


def test_joint_step_fires_between_movers_with_an_exact_instant():
    w = World([(0, -5), (-5, 0), (20, 20), (-20, 20), (20, -20)],
              checker=Checker(enabled=frozenset({"I1"})))
    for i, goal in ((0, (0, 5)), (1, (5, 0))):
        rob = w.robots[i]
        rob.path, rob.start = [g.Segment(rob.pos, P(*goal))], rob.pos
    with pytest.raises(Violation) as err:
        w.advance_together([(0, None, False), (1, None, False)])
    v = err.value
    assert v.invariant == "I1" and v.label == "gather-no-obstacle" and v.robots == (0, 1)
    assert "at time 1/2" in v.witness and "squared distance 0" in v.witness


def test_joint_step_checks_each_mover_against_robots_standing_still():
    w = World([(0, -5), (-5, 0), (1, 0), (-20, 20), (20, -20)],
              checker=Checker(enabled=frozenset({"I1"})))
    for i, goal in ((0, (0, -9)), (1, (-5, 9))):
        rob = w.robots[i]
        rob.path, rob.start = [g.Segment(rob.pos, P(*goal))], rob.pos
    w.advance_together([(0, None, False), (1, None, False)])       # both away: free
    w = World([(0, -5), (-5, 0), (1, 0), (-20, 20), (20, -20)],
              checker=Checker(enabled=frozenset({"I1"})))
    for i, goal in ((0, (0, -9)), (1, (5, 0))):
        rob = w.robots[i]
        rob.path, rob.start = [g.Segment(rob.pos, P(*goal))], rob.pos
    with pytest.raises(Violation) as err:
        w.advance_together([(0, None, False), (1, None, False)])
    assert err.value.robots == (1, 2)


def test_a_look_after_a_partial_joint_step_sees_both_movers_part_way():
    w = _square_world(Checker(enabled=frozenset({"I1"})))
    pieces = [w.robots[i].path[0] for i in range(4)]
    w.advance_together([(0, F(1, 2), False), (2, F(1, 4), False)])
    half = MQ.rational(F(1, 2))
    assert w.robots[0].pos == pieces[0].at(half) == P(2, 0)
    assert w.robots[2].pos == pieces[2].at(MQ.rational(F(1, 4))) == P(3, 4)
    assert w.robots[1].pos == P(4, 0) and w.robots[0].path[0].start == P(2, 0)
    assert sorted(w.busy()) == [0, 1, 2, 3]


def test_bad_joint_steps_are_refused():
    w = _square_world(Checker(enabled=frozenset({"I1"})))
    with pytest.raises(ValueError):
        w.advance_together([(0, None, False), (0, None, False)])
    with pytest.raises(ValueError):
        w.advance_together([(0, None, False), (4, None, False)])     # robot 4 is idle
    with pytest.raises(ValueError):
        w.advance_together([(0, F(1, 2), True), (1, None, False)])   # rigid: no end
    w = World(SQUARE, rigid=False, delta=F(3), checker=Checker(enabled=frozenset({"I1"})))
    for i, goal in ((0, (-8, 0)), (1, (4, -8))):
        rob = w.robots[i]
        rob.path, rob.start = [g.Segment(rob.pos, P(*goal))], rob.pos
    with pytest.raises(ValueError):                                   # 1/4 of 8 < delta
        w.advance_together([(0, F(1, 4), True), (1, None, False)])


# -- schedulers, traces, search -----------------------------------------------------------
def test_synchronous_leaders_of_both_handednesses_collide_and_replay(tmp_path):
    from exactsym.gathering.trace import read_trace, replay, same_result, write_trace
    settings_ = {"scheduler": "ssync", "seed": 6, "invariants": NO_I2_I9}
    res = run(ONE_CIRCLE, "ssync", 6, Readings(), checker=Checker(enabled=frozenset(NO_I2_I9)))
    assert res.outcome == "violated" and res.violation["invariant"] == "I1"
    assert res.violation["robots"] == [2, 3] and "time 14/15" in res.violation["witness"]
    assert [a["a"] for a in res.actions][-1] == "step"
    path = tmp_path / "t.json"
    write_trace(path, ONE_CIRCLE, res, {**settings_, "readings": Readings().as_dict()})
    data = read_trace(path)
    assert same_result(data["result"], replay(data)) == []
    data["actions"][-1]["moves"][0][1] = "1/2"                # robot 2 stops half-way
    assert same_result(data["result"], replay(data)) != []
    # under EL=unordered both handednesses elect one robot: nobody collides
    res = run(ONE_CIRCLE, "ssync", 6, Readings(EL="unordered"),
              checker=Checker(enabled=frozenset(NO_I2_I9)))
    assert res.label != "gather-no-obstacle"


@pytest.mark.parametrize("scheduler", ["fsync", "ssync", "async"])
def test_one_mover_at_a_time_never_makes_a_joint_step(scheduler):
    """The corrected variant has one mover at a time: no ``step`` action appears, the
    run is the interleaving schedulers' run."""
    res = run([(0, 0), (7, 1), (-6, 5), (2, -9), (11, 8)], scheduler, 2,
              algorithm="corrected", max_events=400)
    assert res.outcome == "gathered"
    assert all(a["a"] != "step" for a in res.actions)


def test_async_lets_busy_robots_move_together():
    res = run(ONE_CIRCLE, "async", 5, Readings(), checker=Checker(enabled=frozenset(NO_I2_I9)))
    assert res.violation["invariant"] == "I1" and res.violation["robots"] == [2, 3]
    step = [a for a in res.actions if a["a"] == "step"][-1]
    assert sorted(m[0] for m in step["moves"]) == [2, 3]


def test_search_finds_the_simultaneous_overlap_first():
    """Two Looks in the two handednesses, then one joint step: three actions (one at a
    time, the shortest collision needs four)."""
    from exactsym.gathering.search import exhaustive
    settings_ = {"readings": Readings().as_dict(), "invariants": NO_I2_I9,
                 "rigid": True, "delta": None, "max_events": 50}
    found = exhaustive(ONE_CIRCLE, settings_, max_depth=4)
    assert [a["a"] for a in found] == ["look", "look", "step"]
    assert sorted(m[0] for m in found[-1]["moves"]) == [2, 3]
    assert exhaustive(ONE_CIRCLE, settings_, max_depth=2) is None


# -- I3, I4, I6 over a joint step (exactsym.gathering.joint_instants) --------------------
#: robot 4 Looks and gets Make_SymToAsym's epsilon arc about C = (0, 0); robots 0 and 1
#: then move with it (made-up moves: no Look of their own)
JOINT = [(20, 0), (-20, 0), (12, 16), (-16, 12), (5, 0)]


def _joint_world(checker, chords: bool):
    """``chords``: robots 0 and 1 cut across the SEC, (20, 0) -> (0, 20) and (-20, 0) ->
    (0, -20) (part-way only robots 2 and 3, 90 degrees apart, are on the circle of
    radius 20: the SEC and C change, and come back at the end); otherwise they slide
    along that circle (C stays)."""
    w = World(JOINT, checker=checker)
    w.look(4, MIRROR_FREE)
    if chords:
        w.robots[0].path = [seg((20, 0), (0, 20))]
        w.robots[1].path = [seg((-20, 0), (0, -20))]
    else:
        w.robots[0].path = [g.Arc(P(0, 0), P(20, 0), P(16, -12), -1)]
        w.robots[1].path = [g.Arc(P(0, 0), P(-20, 0), P(-16, -12), 1)]
    return w


def _end_only(w, key):
    """The old check of a joint step: each mover at the step's end only."""
    c = Checker(enabled=frozenset({key}))
    w.checker = c
    for i in (0, 1, 4):
        pos = w.robots[i].pos
        c.after_advance(w, i, g.Segment(pos, pos))
    return c


STEP = [(0, None, False), (1, None, False), (4, F(1, 2), False)]


@pytest.mark.parametrize("key", ["I3", "I6"])
def test_I3_and_I6_fire_inside_a_joint_step_and_not_at_its_end(key):
    w = _joint_world(None, chords=True)
    w.advance_together(STEP)
    assert _end_only(w, key).counts[key] >= 1             # at the end: no violation
    w = _joint_world(Checker(enabled=frozenset({key})), chords=True)
    with pytest.raises(Violation) as err:
        w.advance_together(STEP)
    v = err.value
    assert v.invariant == key and 4 in v.robots
    tau = F(v.witness.split("(time ")[1].split(" of the step")[0])
    assert 0 < tau < 1
    if key == "I6":
        assert "C moved from (0, 0)" in v.witness
        assert v.label == "conclusion (L1708-1710)"
    else:
        assert v.label == "obs-v-move" and "plans robot 0 (MakeAsym)" in v.witness


def test_I3_and_I6_hold_over_a_joint_step_along_the_sec():
    for key in ("I3", "I6"):
        w = _joint_world(Checker(enabled=frozenset({key})), chords=False)
        w.advance_together(STEP)
        c = w.checker.counts
        assert c["instants"] >= 3 and c[key] >= c["instants"]


def _leader_world(checker, cross_at):
    """Leader 0 goes from (0, -10) to (0, -5) towards C = (0, 0); robot 1 crosses the
    plane along y = ``cross_at`` (a made-up move), nearest to C half way."""
    w = World([(0, -10), (-20, cross_at), (30, 30), (-30, 30), (0, -40)], checker=checker)
    lead = w.robots[0]
    lead.path, lead.start, lead.role = [seg((0, -10), (0, -5))], lead.pos, "leader"
    lead.centre, lead.target, lead.r_set = P(0, 0), P(0, 0), frozenset(range(5))
    w.robots[1].path = [seg((-20, cross_at), (20, cross_at))]
    return w


def test_I4_fires_inside_a_joint_step_and_holds():
    """Robot 1 passes (0, 6), nearer to C than the leader (at 15/2 then): I4 inside the
    step; at the end robot 1 is at (20, 6), farther than the leader (at 5).  Along
    y = 12 robot 1 is never as near."""
    w = _leader_world(None, 6)
    w.advance_together([(0, None, False), (1, None, False)])
    c = Checker(enabled=frozenset({"I4"}))
    c._nearest(w, 0, w.events, strict=True)                # the end alone: no violation
    w = _leader_world(Checker(enabled=frozenset({"I4"})), 6)
    with pytest.raises(Violation) as err:
        w.advance_together([(0, None, False), (1, None, False)])
    v = err.value
    assert v.invariant == "I4" and v.robots == (0, 1) and v.label == "gather-min-distance"
    # the first instant where robot 1 is as near: (10 - 5 tau)^2 = (40 tau - 20)^2 + 36,
    # tau = 10/21 - 2 sqrt(37)/105, held exactly (a tie, not a sample)
    assert ("(time 10/21 - 2/105*sqrt(37) of the step: robots 0 and 1 as far from C)"
            in v.witness)
    w = _leader_world(Checker(enabled=frozenset({"I4"})), 12)        # never nearer
    w.advance_together([(0, None, False), (1, None, False)])
    assert w.checker.counts["I4"] >= 2


# -- I3 compares a fresh Look with the plan of the mover's own Look ----------------------
def test_I3_under_A3_all_asks_for_the_mover_and_its_target():
    from exactsym.gathering.invariants import _names_the_mover
    from exactsym.gathering.run_home import RunHome
    home = RunHome()                                # compares the targets
    a, b, c = P(3, -4), P(1, 1), P(5, 5)
    looked = {0: ("MakeAsym", a), 3: ("leader", b)}                # A3 = all: two movers
    assert _names_the_mover({0: ("MakeAsym", a), 3: ("leader", b)}, looked, 0, home)
    assert _names_the_mover({0: ("MakeAsym", a)}, looked, 0, home)            # robot 3 arrived
    assert _names_the_mover({0: ("MakeAsym", a), 2: ("leader", c)}, looked, 0, home)
    assert not _names_the_mover({3: ("leader", b)}, looked, 0, home)          # 0 not named
    assert not _names_the_mover({0: ("MakeAsym", a), 3: ("leader", c)}, looked, 0, home)
    assert not _names_the_mover({5: ("leader", c)}, {5: ("leader", a)}, 5, home)


def test_a_joint_step_of_the_two_movers_one_look_named_is_no_I3_violation():
    """Sweep run n = 5 (``bench_gather.random_config(5, seed=501)``), FSYNC seed 1, A3 =
    all, I2 off: robot 0 (MakeAsym's mover) and robot 3 (the leader) move at once, each
    on the move every Look named.  A fresh Look inside the step names the same two moves:
    I3 compared it with robot 0's move alone and fired; it holds, and the run stalls
    later (three robots Elect_Leader_Asym does not order)."""
    pts = [(F(21, 2), 10), (-10, F(43, 2)), (F(-17, 3), -14), (F(31, 2), F(-15, 2)),
           (16, F(-59, 2))]
    checker = Checker(enabled=frozenset(k for k in ALL if k != "I2"))
    res = run(pts, "fsync", 1, Readings(A3="all", EL="unordered"), max_events=200,
              checker=checker)
    step = next(k for k, a in enumerate(res.actions) if a["a"] == "step")
    assert res.actions[step]["moves"] == [[0, None, False], [3, None, False]]
    assert checker.counts["I3"] >= 3 and checker.counts["instants"] >= 3
    assert res.outcome == "stalled" and res.violation is None


def test_a_violation_inside_a_step_carries_its_exact_instant():
    """The I3 case of a joint step: ``Violation.time`` is the instant of the step where
    the fresh Look was taken (the witness says the same), in the JSON as text; a
    violation at a Look (I2) has none."""
    w = _joint_world(Checker(enabled=frozenset({"I3"})), chords=True)
    with pytest.raises(Violation) as err:
        w.advance_together(STEP)
    v = err.value
    tau = v.witness.split("(time ")[1].split(" of the step")[0]
    assert v.time is not None and v.time.text() == tau and 0 < F(tau) < 1
    assert v.as_dict()["time"] == tau
    w = World(JOINT, checker=Checker(enabled=frozenset({"I2"})))
    w.look(4, MIRROR_FREE)
    w.robots[0].path = [seg((20, 0), (0, 20))]
    with pytest.raises(Violation) as err:
        w.look(1, MIRROR_FREE)
    assert err.value.time is None and "time" not in err.value.as_dict()
