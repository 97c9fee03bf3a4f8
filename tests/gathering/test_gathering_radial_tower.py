"""The simulator's own radial move to a nested-radical target (exactsym.gathering.run_tower,
robot.radial_point): the target is a point of a tower of quadratic extensions, the run
goes on exactly in one tower per run (positions re-homed into it), and runs that need no
nested radical build no tower at all."""

from fractions import Fraction as F

from flint import fmpq
from hypothesis import given, settings, strategies as st

from exactsym.exact.mq_closure import decided_sqrt
from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import geometry as g
from exactsym.gathering.invariants import Checker
from exactsym.exact.algebraic.roots import roots_in_unit
from exactsym.gathering.robot import Readings, decide, radial_point
from exactsym.exact.algebraic.norms import tower_norm
from exactsym.exact.algebraic.run_tower import RunTower, home, sqrt_exact
from exactsym.gathering.run_home import RunHome, common_tower, home_point, towers_of
from exactsym.exact.algebraic.tower_numbers import is_tower
from exactsym.gathering.world import IDENTITY, World

Q = MQ.rational
S2 = sqrt_rational(2)
ORIGIN = (Q(0), Q(0))
ALL_FIRST = Readings(A3="all")

# a robot at C = (0, 0) (the pattern), three rational robots on the SEC of radius 25, and
# robot 4 at (1 + sqrt 2, 7): |p - C|^2 = 52 + 2 sqrt 2 is a square in no multiquadratic
# field, so its radial target at radius 2 needs sqrt(52 + 2 sqrt 2)
NESTED = ((Q(0), Q(0)), (Q(25), Q(0)), (Q(-7), Q(24)), (Q(0), Q(-25)), (1 + S2, Q(7)),
          (Q(10), Q(3)), (Q(-9), Q(5)))


def _similar(p, c=F(3, 5), s=F(4, 5), k=2, t=(F(1), F(-3))):
    """An exact similarity: Pythagorean rotation, scale k, translation t."""
    x, y = p
    return (x * (k * c) - y * (k * s) + t[0], x * (k * s) + y * (k * c) + t[1])


def test_radial_point_at_a_nested_radical_is_exact():
    p = (1 + S2, Q(7))
    q = radial_point(ORIGIN, p, 2)
    assert is_tower(q[0]) and is_tower(q[1])
    assert g.dist2(q, ORIGIN) == 4                         # exactly on the circle
    assert g.cross(q, p) == 0 and g.dot(q, p).sign() > 0   # on the ray towards p
    (tower,) = towers_of([q])
    assert isinstance(tower, RunTower) and tower.levels == 1
    assert tower.radicands[0] == 52 + 2 * S2
    ball = q[0].to_arb(80)                                 # the filters' ball
    assert ball.contains(q[0].enclosure(200)) and ball.rad() < 1e-15


def test_radial_point_stays_multiquadratic_when_it_can():
    # |p|^2 = 3 + 2 sqrt 2 = (1 + sqrt 2)^2: denested, no tower
    q = radial_point(ORIGIN, (1 + S2, Q(0)), 2)
    assert isinstance(q[0], MQ) and q == (Q(2), Q(0))
    q = radial_point(ORIGIN, (Q(3), Q(5)), 2)               # rational |p|^2 = 34
    assert isinstance(q[0], MQ) and g.dist2(q, ORIGIN) == 4


def test_decide_moves_to_the_nested_target_instead_of_undecided():
    d = decide(NESTED, ALL_FIRST)
    assert d.status == "move" and d.leader == 4
    m = d.move_of(4)
    assert m.role == "leader+epsilon"
    end = m.path[-1].final
    assert is_tower(end[0]) and g.dist2(end, d.centre) == 4
    # the epsilon arc keeps |p - C|, so the segment after it is radial
    start = m.path[-1].start
    assert g.cross(g.sub(start, d.centre), g.sub(end, d.centre)) == 0


@settings(max_examples=8, deadline=None)
@given(st.integers(-6, 6), st.integers(1, 4), st.integers(1, 3),
       st.tuples(st.integers(-9, 9), st.integers(-9, 9)))
def test_a_similar_snapshot_gives_the_similar_target(t, k_num, k_den, shift):
    # a Pythagorean rotation (parameter t/3), a rational scale, a translation
    tau = F(t, 3)
    c, s = (1 - tau * tau) / (1 + tau * tau), 2 * tau / (1 + tau * tau)
    k = F(k_num, k_den)
    sim = lambda p: _similar(p, c, s, k, (F(shift[0]), F(shift[1])))   # noqa: E731
    d = decide(NESTED, ALL_FIRST)
    moved = tuple(sim(p) for p in NESTED)
    d2 = decide(moved, ALL_FIRST, fmpq(k.numerator, k.denominator))
    assert d2.status == "move" and d2.leader == 4
    want = sim(d.move_of(4).path[-1].final)
    got = d2.move_of(4).path[-1].final
    # two decisions, two towers: compared after re-homing into the first one
    (tower,) = towers_of([want])
    assert home_point(got, tower) == want


def test_a_run_goes_on_exactly_in_one_tower():
    world = World(NESTED, ALL_FIRST, checker=Checker())
    world.look(4, IDENTITY)
    while world.robots[4].busy:
        world.advance(4)
    pos = world.robots[4].pos
    assert world.home.levels == 1 and towers_of([pos]) == (world.home.tower,)
    assert g.dist2(pos, ORIGIN) == 4
    # the others Look at a snapshot with tower coordinates: decided, never "undecided"
    d = world.look(6, IDENTITY)
    assert d.status == "move" and d.leader == 6 and 4 in d.pattern.robots
    assert all(t is world.home.tower for t in towers_of(world.robots[6].path))
    counts = world.checker.counts
    assert counts["I1"] > 0 and counts["I3"] > 0 and counts["I8"] > 0


def test_two_runs_keep_their_own_towers():
    # the same run twice: equal raw values in two towers are never compared (decide's
    # cache key holds the towers first)
    ends = []
    for _ in range(2):
        world = World(NESTED, ALL_FIRST)
        world.look(4, IDENTITY)
        while world.robots[4].busy:
            world.advance(4)
        d = world.look(6, IDENTITY)
        assert d.status == "move"
        ends.append((world.home.tower, world.robots[6].path[-1].final))
    (t1, e1), (t2, e2) = ends
    assert t1 is not t2 and home_point(e2, t1) == e1


def test_rational_run_builds_no_tower():
    pts = [(30, 0), (0, 31), (-33, 2), (5, -34), (21, 22), (-20, -23)]
    world = World([(Q(x), Q(y)) for x, y in pts], ALL_FIRST,
                  checker=Checker(enabled=frozenset({"I1", "I3", "I6"})))
    for i in range(len(pts)):
        world.look(i, IDENTITY)
        while world.robots[i].busy:
            world.advance(i)
    assert any(s.kind == "advance" for s in world.log)          # somebody moved
    assert world.checker.counts["I3"] > 0
    assert isinstance(world.home, RunHome) and world.home.tower is None
    assert all(isinstance(c, MQ) for r in world.robots for c in r.pos)


def test_rehoming_an_instant_into_a_run_tower():
    # an instant at y = sqrt(sqrt 2 - 1) lives on its own one-level tower
    (r,) = roots_in_unit((1 - S2, Q(0), Q(1)))
    y = r.exact
    assert is_tower(y) and not isinstance(y.tower, RunTower)
    run = RunTower()
    z = sqrt_exact(3 + S2, run)                     # the run's own first level
    yh = home(y, run)
    assert yh.tower is run and yh * yh == S2 - 1 and yh.sign() > 0
    assert run.levels == 2 and home(y, run) == yh   # homed once: the same number again
    assert home(y + 3, run) == yh + 3
    # a snapshot mixing the two towers is re-homed into the run's
    pts, tower = common_tower(((y, Q(1)), (z, Q(0))))
    assert tower is run and towers_of(pts) == (run,)
    assert common_tower(((Q(1), Q(2)),)) == (((Q(1), Q(2)),), None)


def test_decided_sqrt_of_a_tower_number():
    run = RunTower()
    z = sqrt_exact(3 + S2, run)                     # sqrt(3 + sqrt 2)
    w = z + 1
    root, decided = decided_sqrt(w * w)
    assert decided and root == w
    assert decided_sqrt(z) == (None, True)          # a fourth-root level is not there yet
    assert decided_sqrt(-z) == (None, True)


def test_joint_motion_of_a_tower_piece_is_exact():
    p = (1 + S2, Q(7))
    seg = g.Segment(p, radial_point(ORIGIN, p, 4))
    crossing = g.Segment((Q(-3), Q(4)), (Q(4), Q(3)))
    tau = g.joint_motion_overlap(seg, crossing)
    assert tau is not None
    t = Q(tau)
    assert (g.dist2(seg.at(t), crossing.at(t)) - 4).sign() < 0
    # and a piece that stays far below it: none, the exact polynomial agrees everywhere
    low = g.Segment((Q(-9), Q(-3)), (Q(6), Q(-3)))
    assert g.joint_motion_overlap(seg, low) is None
    gap = g.joint_gap_polynomial(seg, low)
    assert all(c is not None for c in gap) and len(tower_norm(gap)) == 2 * len(gap) - 1
    assert all(isinstance(c, MQ) for c in tower_norm(gap))


def test_a_rational_run_reaches_a_nested_radical_target_and_goes_on():
    # cases/gathering/radial-target-nested-radical.toml: before, "undecided"
    from exactsym.gathering.schedulers import run
    pts = [(20, 0), (-20, 0), (12, 16), (-12, 16), (3, 1)]
    inv = frozenset({"I1", "I2", "I4", "I5", "I7", "I8", "I10"})
    res = run([(F(x), F(y)) for x, y in pts], "async", 0, ALL_FIRST, max_events=200,
              checker=Checker(enabled=inv))
    assert res.outcome == "stalled" and res.violation is None
    assert res.pattern["layers"] == [[3]] and res.pattern["centre_robot"] == 4
    ends = [s for s in res.log if s.kind == "advance" and s.robot == 3]
    last = ends[-1].pieces[-1].final
    (tower,) = towers_of([last])
    assert isinstance(tower, RunTower) and tower.levels == 1
    # robot 3 ends exactly on layer 1 about the pattern's centre (robot 4's position)
    centre = [s for s in res.log if s.kind == "advance" and s.robot == 4][-1].pieces[-1].final
    assert g.dist2(last, centre) == 4
    assert res.checks["I1"] > 0 and res.checks["I8"] > 0


def test_critical_instants_over_a_run_tower_are_built_in_it():
    # a quadratic with coefficients in the run's tower: its root is a new level of the
    # same tower (tower_numbers.tower_sqrt defers to the run tower's complete test)
    run = RunTower()
    z = sqrt_exact(3 + S2, run)                     # sqrt(3 + sqrt 2), about 2.11
    (r,) = roots_in_unit((-z / 16, Q(0), Q(1)))     # f^2 = z / 16: f = sqrt(z) / 4
    f = r.exact
    assert is_tower(f) and f.tower is run and run.levels == 2
    assert f * f * 16 == z and f.sign() > 0
    # a square there is found without a new level
    (r,) = roots_in_unit((-(z + 1) ** 2 / 16, Q(0), Q(1)))
    assert r.exact == (z + 1) / 4 and run.levels == 2


def test_a_copied_world_keeps_its_own_tower():
    # the adversary search (search.py) deep-copies worlds: the copy's positions and its
    # tower move together, and its Looks are decided in its own tower
    import copy
    world = World(NESTED, ALL_FIRST)
    world.look(4, IDENTITY)
    while world.robots[4].busy:
        world.advance(4)
    twin = copy.deepcopy(world)
    assert twin.home.tower is not world.home.tower
    assert towers_of([twin.robots[4].pos]) == (twin.home.tower,)
    d = twin.look(6, IDENTITY)
    assert d.status == "move" and towers_of(twin.robots[6].path) == (twin.home.tower,)
    assert home_point(twin.robots[4].pos, world.home.tower) == world.robots[4].pos


def test_a_path_the_runs_tower_cannot_hold_makes_the_decision_undecided(monkeypatch):
    """Re-homing a planned path can need a square root that mq_closure cannot decide
    (a rational of more than 160 bits to factor): the fresh decision is "undecided"
    (counted as a skipped Look by the checker), not a crash (a sweep run crashed so)."""
    from exactsym.gathering.world import IDENTITY, World

    w = World([(20, 0), (-20, 0), (12, 16), (-12, 16), (3, 1)])
    d, paths = w.snapshot_decision(IDENTITY)
    assert d.status == "move" and paths

    def refuse(_pieces):
        raise ValueError("a square root would need a rational of more than 160 bits")
    monkeypatch.setattr(w.home, "path", refuse)
    d, paths = w.snapshot_decision(IDENTITY)
    assert d.status == "undecided" and paths == {} and "160 bits" in d.detail


def test_hypothetical_levels_are_taken_back_and_no_cached_decision_keeps_them():
    """The invariants' fresh Looks grow the run's tower only inside RunHome.scratch: the
    levels they add are taken back, and a decision cached there (robot.decide) is never
    served afterwards, when the same level index holds another radicand."""
    home = RunHome()
    home.tower = run = RunTower()
    z = sqrt_exact(52 + 2 * S2, run)                 # level 1, about 7.35
    snapshot = NESTED[:4] + ((z, Q(1)),) + NESTED[5:]
    before = run.mark()
    with home.scratch():
        d = decide(snapshot, ALL_FIRST)
        assert d.leader == 4 and run.levels == 2     # sqrt(53 + 2 sqrt 2): a new level
        assert g.dist2(d.move_of(4).path[-1].final, ORIGIN) == 4
    assert run.levels == 1 and run.mark() == before
    w = sqrt_exact(5 + 3 * S2, run)                   # level 2 is now another radicand
    assert run.levels == 2 and w * w == 5 + 3 * S2
    d = decide(snapshot, ALL_FIRST)                   # recomputed, not the cached one
    target = d.move_of(4).path[-1].final
    assert run.levels == 3 and g.dist2(target, ORIGIN) == 4


def test_a_violation_inside_scratch_keeps_its_levels():
    home = RunHome()
    home.tower = run = RunTower()
    sqrt_exact(3 + S2, run)
    try:
        with home.scratch():
            sqrt_exact(5 + S2, run)
            raise RuntimeError("a Violation leaves the block")
    except RuntimeError:
        pass
    assert run.levels == 2 and sqrt_exact(5 + S2, run) ** 2 == 5 + S2

