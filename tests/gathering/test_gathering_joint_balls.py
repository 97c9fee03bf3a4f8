"""The ball filter of a joint step's in-circle relations (``instant_balls.incircle_clear``,
used by ``joint_instants._sec``): it leaves out only determinants with no root in the
interval, so the critical instants are those of the exact computation, one for one."""

from fractions import Fraction as F

from hypothesis import assume, given, settings, strategies as st

from exactsym.exact.algebraic.roots import roots_in_unit
from exactsym.exact.multiquadratic import MQ
from exactsym.gathering import geometry as g
from exactsym.gathering import joint_instants
from exactsym.gathering.instant_balls import MotionBall, incircle_clear
from exactsym.gathering.joint_relations import incircle_poly
from exactsym.gathering.motion import motion_of
from exactsym.gathering.world import World

coord = st.fractions(min_value=-30, max_value=30, max_denominator=7)
pt = st.tuples(coord, coord)


def _piece(a, b, arc: bool, centre):
    a, b = g.point(*a), g.point(*b)
    if not arc:
        return g.Segment(a, b)
    c = g.point(*centre)
    q = g.add(c, g.rotate(g.sub(a, c), MQ.rational(F(3, 5)), MQ.rational(F(4, 5))))
    return g.Arc(c, a, q, 1)


@settings(max_examples=60, deadline=None)
@given(st.lists(pt, min_size=4, max_size=4), st.lists(pt, min_size=2, max_size=2),
       st.booleans(), pt)
def test_a_cleared_in_circle_relation_has_no_root_inside(points, ends, arc, centre):
    # an arc about its own start point is no motion (radius 0: the simulator never makes
    # one, and its half-angle tangent divides by zero)
    assume(not arc or tuple(centre) != tuple(points[0]))
    motions = [motion_of(_piece(points[0], ends[0], arc, centre)),
               motion_of(_piece(points[1], ends[1], False, centre))]
    motions += [motion_of(g.Segment(g.point(*p), g.point(*p))) for p in points[2:]]
    poly = incircle_poly(motions)
    if incircle_clear([MotionBall(m) for m in motions]):
        assert not roots_in_unit(poly)


def _roots(world, pieces):
    return [(r.lo, r.hi, None if r.exact is None else r.exact.text(), sorted(r.tags))
            for r in joint_instants.joint_critical_roots(pieces, world)]


@settings(max_examples=12, deadline=None)
@given(st.lists(pt, min_size=6, max_size=6, unique=True), st.lists(pt, min_size=2,
                                                                   max_size=2))
def test_the_joint_instants_are_those_of_the_exact_computation(points, ends):
    world = World(points)
    pieces = {0: g.Segment(world.robots[0].pos, g.point(*ends[0])),
              1: g.Segment(world.robots[1].pos, g.point(*ends[1]))}
    filtered = _roots(world, pieces)
    original = joint_instants.incircle_clear
    joint_instants.incircle_clear = lambda balls: False          # every relation exact
    try:
        exact = _roots(world, pieces)
    finally:
        joint_instants.incircle_clear = original
    assert [(r[2], r[3]) for r in filtered] == [(r[2], r[3]) for r in exact]
