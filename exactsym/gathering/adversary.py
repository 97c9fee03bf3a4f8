"""The adversary's choices at a state of a run, for the search (:mod:`.search`).

At a state the adversary may (spec section 1; ``docs/gathering.md``, "The search"):

* let an idle robot Look -- in the plain frame, the mirrored one (the two handednesses),
  and a rotated and scaled frame of each handedness whose origin is elsewhere (a frame
  in which nothing lines up with the axes: a decision that depends on more than the
  handedness flips there);
* move one busy robot along its current piece to the piece's end or to a stop at and
  between the critical instants of that motion that the simulator already computes
  (:func:`.stops.piece_stops` over :func:`.instants.critical_roots`: contacts and
  grazes, distance ties, SEC changes, symmetry instants, the pattern's circles) -- every
  instant whose exact value the kernel holds, rational or irrational (a quadratic
  irrational, a nested radical: a trace records it as the k-th instant of the motion
  with an isolating interval), and the simplest rational point of each stretch between
  two instants;
* move several busy robots at once (ASYNC interleavings: all of them, and every pair)
  over one common interval, to their pieces' ends or to a stop at and between the
  critical instants of the joint motion (:func:`.joint_instants.joint_critical_roots`);
* non-rigid: end a move at any of those stops, once delta is covered.

Actions are the plain dicts of a trace (:mod:`.trace`), so a found schedule replays.
"""

from __future__ import annotations

from fractions import Fraction
from itertools import combinations

from ..exact.algebraic.interface import float_and_error
from . import geometry as g
from .stops import piece_stops, resolve
from .world import IDENTITY, MIRROR, Frame, World

__all__ = ["FRAMES", "children", "apply_action", "badness", "stop_fractions"]

#: the Look frames: plain and mirrored, and a rotation by the 3-4-5 angle, scale 2 and a
#: shifted origin in each handedness
FRAMES = (IDENTITY, MIRROR,
          Frame(Fraction(6, 5), Fraction(8, 5), False, Fraction(7, 3), Fraction(-5, 2)),
          Frame(Fraction(6, 5), Fraction(8, 5), True, Fraction(7, 3), Fraction(-5, 2)))
HALF = Fraction(1, 2)


def stop_fractions(world: World, i: int) -> list:
    """The stops strictly inside robot ``i``'s current piece, in order
    (:func:`.stops.piece_stops`: one simple rational in each stretch between its
    critical instants, and each instant a stop can be -- a rational as a string, an
    irrational one as its trace record); 1/2 alone when the kernel cannot hold them."""
    try:
        return piece_stops(world, [i])
    except (ValueError, ArithmeticError):
        return [str(HALF)]


def _joint_stops(world: World, group) -> list:
    try:
        return piece_stops(world, list(group))
    except (ValueError, ArithmeticError):
        return [str(HALF)]


def children(world: World, frames=FRAMES, joint: bool = True):
    """Every action the adversary may take now (see the module docstring), in a fixed
    order: joint steps, single moves, Looks."""
    busy = world.busy()
    if joint and len(busy) >= 2:
        groups = [tuple(busy)] + ([c for c in combinations(busy, 2)] if len(busy) > 2 else [])
        for group in groups:
            for stop in [None] + _joint_stops(world, group):
                yield {"a": "step", "moves": [[i, stop, False] for i in group]}
    for i, rob in enumerate(world.robots):
        if rob.busy:
            yield {"a": "advance", "robot": i, "stop": None, "end": False}
            for stop in stop_fractions(world, i):
                yield {"a": "advance", "robot": i, "stop": stop, "end": False}
                if not world.rigid:
                    yield {"a": "advance", "robot": i, "stop": stop, "end": True}
        else:
            for frame in frames:
                yield {"a": "look", "robot": i, "frame": frame.as_list()}


def apply_action(world: World, act) -> bool:
    """Apply ``act`` (a trace action); False when the model does not allow it (a
    non-rigid stop before delta).  A violation raises :class:`.invariants.Violation`."""
    try:
        if act["a"] == "look":
            world.look(act["robot"], Frame.from_list(act["frame"]))
        elif act["a"] == "step":
            movers = [i for i, _stop, _end in act["moves"]]
            world.advance_together([(i, resolve(world, movers, stop), end)
                                    for i, stop, end in act["moves"]])
        else:
            world.advance(act["robot"], resolve(world, [act["robot"]], act["stop"]),
                          act["end"])
    except ValueError:
        return False
    return True


def _approx(x) -> float:
    return float_and_error(x)[0]


def badness(world: World) -> float:
    """How near the state is to a violation: the smallest clearance between two discs
    (centre distance minus 2) or the nearest tie of two distances to the SEC centre,
    whichever is smaller; lower is nearer.  Doubles: the score only orders the search's
    exploration, it decides no verdict (every verdict is the checker's, exact)."""
    pts = [(_approx(p[0]), _approx(p[1])) for p in world.positions()]
    clear = min(((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5 - 2
                for a, b in combinations(pts, 2))
    try:
        centre, _r2 = g.smallest_enclosing_circle(list(world.positions()))
        c = (_approx(centre[0]), _approx(centre[1]))
    except (ValueError, ArithmeticError):
        return clear
    dists = sorted(((p[0] - c[0]) ** 2 + (p[1] - c[1]) ** 2) ** 0.5 for p in pts)
    tie = min((b - a for a, b in zip(dists, dists[1:]) if b - a > 0), default=clear)
    return min(clear, tie)
