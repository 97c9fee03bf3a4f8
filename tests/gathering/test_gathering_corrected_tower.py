"""The corrected variant's radial moves to a nested-radical target (corrected.py with
robot.radial_point and the run's tower): where |p - C| is a nested radical the corrected
algorithm moves exactly there (before: ``undecided``), in the snapshot's tower, its
decisions cached per tower, and the run goes on in the world's one tower."""

from fractions import Fraction as F

import pytest

from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import geometry as g
from exactsym.gathering.corrected import decide_corrected
from exactsym.gathering.invariants import Checker
from exactsym.gathering.robot import Readings
from exactsym.exact.algebraic.run_tower import RunTower
from exactsym.exact.algebraic.tower_numbers import is_tower
from exactsym.gathering.run_home import home_point, towers_of
from exactsym.gathering.world import IDENTITY, Frame, World

Q = MQ.rational
S2 = sqrt_rational(2)
ORIGIN = (Q(0), Q(0))

# a robot at C = (0, 0) (the SEC centre of all: (25, 0), (-7, 24), (0, -25) hold it), no
# two robots touching; robot 4 at (1 + sqrt 2, 7), the nearest, goes to layer 1 on its
# ray, whose slope is irrational: |p - C|^2 = 52 + 2 sqrt 2 is a square in no
# multiquadratic field, so the target at radius 2 needs sqrt(52 + 2 sqrt 2)
NESTED = ((Q(0), Q(0)), (Q(25), Q(0)), (Q(-7), Q(24)), (Q(0), Q(-25)), (1 + S2, Q(7)),
          (Q(10), Q(3)), (Q(-9), Q(5)))


def test_the_corrected_layer_one_move_is_exact_at_a_nested_radical():
    d = decide_corrected(NESTED)
    assert d.status == "move" and d.centre == ORIGIN
    (m,) = d.moves
    assert m.robot == 4 and len(m.path) == 1 and isinstance(m.path[0], g.Segment)
    p, end = NESTED[4], m.path[0].final
    assert is_tower(end[0]) and is_tower(end[1])
    assert g.dist2(end, ORIGIN) == 4                        # exactly on layer 1
    assert g.cross(end, p) == 0 and g.dot(end, p).sign() > 0
    (tower,) = towers_of([end])
    assert isinstance(tower, RunTower) and tower.radicands[0] == 52 + 2 * S2


def test_clearing_C_radially_at_a_nested_radical():
    """Nobody at C = (0, 0), robots 3 and 4 within 2 of it: the farther, robot 4 at
    (1/2 + sqrt 2 / 2, 1/2) (|p|^2 = 1 + sqrt 2 / 2, a square in no multiquadratic
    field), moves radially out to distance 2."""
    p4 = (Q(F(1, 2)) + S2 / 2, Q(F(1, 2)))
    pts = ((Q(25), Q(0)), (Q(-7), Q(24)), (Q(0), Q(-25)), (Q(F(-1, 2)), Q(-1)), p4,
           (Q(10), Q(3)))
    d = decide_corrected(pts)
    assert d.status == "move"
    (m,) = d.moves
    assert m.robot == 4 and m.role == "clear"
    end = m.path[-1].final
    assert is_tower(end[0]) and g.dist2(end, ORIGIN) == 4
    assert g.cross(end, p4) == 0 and g.dot(end, p4).sign() > 0


def test_decisions_are_cached_per_tower():
    """The same snapshot with the mover's point in two towers: two decisions, each in its
    own tower, and no number of one tower compared with one of the other."""
    a = decide_corrected(NESTED).moves[0].path[0].final
    b = decide_corrected(NESTED[:4] + ((1 + S2, Q(7)),) + NESTED[5:]).moves[0].path[0].final
    assert towers_of([a]) == towers_of([b])               # cached: the same decision
    for end in (a, b):
        pts = list(NESTED)
        pts[4] = end
        d = decide_corrected(tuple(pts))
        assert d.status != "undecided"
    other = RunTower()
    moved = home_point(a, other)                          # the same point, another tower
    pts = list(NESTED)
    pts[4] = moved
    d = decide_corrected(tuple(pts))
    assert d.status != "undecided"
    assert all(t is other for t in towers_of([q for mv in d.moves for pc in mv.path
                                              for q in (pc.start, pc.final)]))


@pytest.mark.parametrize("frame", [Frame(F(3, 5), F(4, 5), False, F(7), F(-3)),
                                   Frame(F(-5, 13), F(12, 13), True, F(1, 2), F(9)),
                                   Frame(F(2), F(0), False, F(0), F(0))])
def test_a_similar_frame_plans_the_same_target(frame):
    """A Look in a rational similarity's frame plans the same world target (both re-homed
    into the world's tower)."""
    w = World(NESTED, Readings(), algorithm="corrected")
    d0, plain = w.snapshot_decision(IDENTITY)
    d1, framed = w.snapshot_decision(frame)
    assert d1.status == "move" and set(framed) == {4}
    assert framed[4][-1].final == plain[4][-1].final
    assert towers_of([framed[4][-1].final]) == (w.home.tower,)


def test_a_corrected_run_goes_on_in_one_tower():
    """Robot 4 Looks and moves to its nested-radical point of layer 1, every invariant
    checked (the fresh Looks of I3 along the way too); the next Looks decide there."""
    w = World(NESTED, Readings(), algorithm="corrected", checker=Checker())
    w.look(4, IDENTITY)
    w.advance(4)
    assert is_tower(w.robots[4].pos[0]) and g.dist2(w.robots[4].pos, ORIGIN) == 4
    assert towers_of(w.positions()) == (w.home.tower,)
    assert w.checker.counts["I3"] >= 1
    for k in (6, 5):                                     # the next movers
        d = w.look(k, IDENTITY)
        assert d.status == "move" and d.moves[0].robot == k
        while w.robots[k].busy:
            w.advance(k)
    # the pattern grew: robot 0 at C, robots 4, 6, 5 a chain of layer 1 (slots exact)
    assert set(decide_corrected(w.positions()).pattern.robots) == {0, 4, 5, 6}
    assert towers_of(w.positions()) == (w.home.tower,)


def test_the_own_circle_path_at_a_nested_radius():
    """corrected_paths.to_slot_paths: the path along the mover's own circle, then radially in,
    also when |p - C|^2 = 52 + 2 sqrt 2 is a square in no multiquadratic field (before,
    that option needed a rational squared radius and was left out): every point of the
    arc is at that distance from C, the arc ends on the target's ray, then the segment
    to the target."""
    from exactsym.gathering.corrected_paths import to_slot_paths as _to_slot_paths
    p, target = NESTED[4], (Q(2), Q(0))                  # a slot of layer 1 on the x axis
    run = RunTower()
    paths = list(_to_slot_paths(p, ORIGIN, target, 1, 1, None, run))
    arcs = [path for path in paths if isinstance(path[0], g.Arc)]
    assert len(arcs) == 1
    *arc, last = arcs[0]
    r2 = 52 + 2 * S2
    for piece in arc:
        assert piece.centre == ORIGIN
        assert g.dist2(piece.start, ORIGIN) == r2 and g.dist2(piece.end, ORIGIN) == r2
    b = arc[-1].end
    assert b[1] == 0 and b[0].sign() > 0 and towers_of([b]) == (run,)
    assert isinstance(last, g.Segment) and last.start == b and last.end == target
    # a point of the arc finds the same path again (the radius is the same number)
    q = arc[0].at(Q(F(1, 3)))
    again = [path for path in _to_slot_paths(q, ORIGIN, target, 1, 1, None, run)
             if isinstance(path[0], g.Arc)]
    assert again and again[0][-1].start == b
