"""A critical instant whose polynomial has only multiquadratic coefficients while the
mover's piece lies in the run's tower (run_tower.instant_in): the nested root is built in
its own one-level tower, and evaluating the piece there mixed two towers (TypeError)
before it was re-homed into the piece's tower.  Robot 5 at (t, 0), t = sqrt(52 + 2
sqrt 2) (a run's tower), moves radially out to (2 t, 0): |p|^2 = t^2 (1 + f)^2 has
multiquadratic coefficients, and it ties with robot 4's |q|^2 = 100 at f = 10 / t - 1."""

import pytest

from exactsym.exact.multiquadratic import MQ, sqrt_rational
from exactsym.gathering import geometry as g
from exactsym.gathering.instants import critical_roots, look_points
from exactsym.gathering.invariants import Checker
from exactsym.gathering.joint_instants import joint_look_points
from exactsym.gathering.robot import Readings
from exactsym.exact.algebraic.run_tower import RunTower, sqrt_exact
from exactsym.exact.algebraic.tower_numbers import is_tower
from exactsym.gathering.run_home import instant_in, towers_of
from exactsym.gathering.world import World

Q = MQ.rational
S2 = sqrt_rational(2)
ORIGIN = (Q(0), Q(0))


def _scene(checker=None):
    t = sqrt_exact(52 + 2 * S2)                    # a number of a new RunTower
    pts = [ORIGIN, (Q(30), Q(0)), (Q(-18), Q(24)), (Q(0), Q(-30)), (Q(0), Q(-10)),
           (t, Q(0))]
    w = World([(0, 0)] * len(pts), Readings(), checker=checker)
    for rob, p in zip(w.robots, pts):
        rob.pos = p
    (w.home.tower,) = towers_of([(t,)])              # the run's tower
    return w, t, g.Segment((t, Q(0)), (2 * t, Q(0)))


def test_the_tie_root_is_in_its_own_tower_and_the_piece_in_the_runs():
    w, t, piece = _scene()
    (root,) = [r for r in critical_roots(piece, w, 5, ORIGIN)
               if ("distance", "as far from C as robot 4") in r.tags]
    assert all(isinstance(c, MQ) for c in root.poly)      # multiquadratic coefficients
    assert is_tower(root.exact) and towers_of([(root.exact,)]) != towers_of([(t,)])
    with pytest.raises(TypeError):
        piece.at(root.exact)                                # what look_points did before
    f = instant_in(root.exact, [piece])
    assert towers_of([(f,)]) == (w.home.tower,) and f == 10 / t - 1
    assert piece.at(f) == (Q(10), Q(0))


def test_look_points_evaluate_the_instant_in_the_pieces_tower():
    w, t, piece = _scene()
    points, sided = look_points(piece, w, 5, ORIGIN)
    (lp,) = [lp for lp in points if lp.exact]
    assert sided == 0 and lp.point == (Q(10), Q(0)) and lp.f == 10 / t - 1
    assert towers_of([(lp.f,)]) == (w.home.tower,)
    assert w.home.tower.levels == 1                        # it denests there: no new level


def test_the_checker_runs_its_fresh_looks_there():
    """A made-up move along the piece with I6 on: C is checked at the instant too."""
    w, t, piece = _scene(Checker(enabled=frozenset({"I6"})))
    rob = w.robots[5]
    rob.path, rob.role, rob.centre, rob.start = [piece], "leader", ORIGIN, rob.pos
    w.advance(5)
    assert w.checker.counts["nested"] == 1 and w.checker.counts["I6"] >= 3
    assert rob.pos == (2 * t, Q(0))


def test_a_joint_step_evaluates_the_instant_in_the_pieces_tower():
    """Robot 5 as above and robot 1 moving along the x-axis far out: the tie of robots 5
    and 4 about C is the same root."""
    w, t, piece = _scene()
    pieces = {5: piece, 1: g.Segment((Q(30), Q(0)), (Q(31), Q(0)))}
    for i, pc in pieces.items():
        w.robots[i].path, w.robots[i].centre = [pc], ORIGIN
    points, sided = joint_look_points(pieces, w)
    taus = [jp.tau for jp in points if jp.exact]
    assert 10 / t - 1 in taus and sided == 0
    assert all(towers_of([(x,)]) in ((), (w.home.tower,)) for x in taus)
    assert piece.at(10 / t - 1) == (Q(10), Q(0))


def test_an_instant_is_left_alone_when_the_piece_is_multiquadratic():
    root = sqrt_exact(52 + 2 * S2)                        # any tower number
    seg = g.Segment(ORIGIN, (Q(1), Q(0)))
    assert instant_in(root, [seg]) is root
    assert instant_in(Q(1) / 3, [seg]) == Q(1) / 3
    other = RunTower()
    assert instant_in(Q(1) / 3, [g.Segment((root, Q(0)), ORIGIN)]) == Q(1) / 3
    assert towers_of([(instant_in(other.number(other.sqrt(Q(3) + S2)),
                                  [g.Segment((root, Q(0)), ORIGIN)]),)]) == \
        towers_of([(root,)])
