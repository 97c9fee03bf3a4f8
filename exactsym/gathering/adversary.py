"""The adversary's choices at a state of a run, for the search (:mod:`.search`).

At a state the adversary may (spec section 1; ``docs/gathering.md``, "The search"):

* let an idle robot Look -- in the plain frame, the mirrored one (the two handednesses),
  and a rotated and scaled frame of each handedness whose origin is elsewhere (a frame
  in which nothing lines up with the axes: a decision that depends on more than the
  handedness flips there);
* move one busy robot along its current piece to the piece's end or to a stop point at
  and between the critical instants of that motion that the simulator already computes
  (:func:`.instants.look_points`: contacts and grazes, distance ties, SEC changes,
  symmetry instants, the pattern's circles) -- every instant it holds as a rational, and
  one rational point just before and just after each instant (an irrational instant
  cannot be a stop: a stop is a rational fraction of the piece, as a trace records it);
* move several busy robots at once (ASYNC interleavings: all of them, and every pair)
  over one common interval, to their pieces' ends or to a stop at and between the
  critical instants of the joint motion (:func:`.joint_instants.joint_look_points`);
* non-rigid: end a move at any of those stops, once delta is covered.

Actions are the plain dicts of a trace (:mod:`.trace`), so a found schedule replays.
"""

from __future__ import annotations

from fractions import Fraction
from itertools import combinations

from ..exact.algebraic.interface import float_and_error
from . import geometry as g
from .instants import look_points
from .joint_instants import joint_look_points
from .world import IDENTITY, MIRROR, Frame, World

__all__ = ["FRAMES", "children", "apply_action", "badness", "stop_fractions"]

#: the Look frames: plain and mirrored, and a rotation by the 3-4-5 angle, scale 2 and a
#: shifted origin in each handedness
FRAMES = (IDENTITY, MIRROR,
          Frame(Fraction(6, 5), Fraction(8, 5), False, Fraction(7, 3), Fraction(-5, 2)),
          Frame(Fraction(6, 5), Fraction(8, 5), True, Fraction(7, 3), Fraction(-5, 2)))
HALF = Fraction(1, 2)


def _rational(x) -> Fraction | None:
    """``x`` (an instant in (0, 1)) as a Fraction, or None when it is not rational."""
    try:
        if not x.is_rational():
            return None
        q = x.to_fmpq()
    except (ValueError, AttributeError):
        return None
    f = Fraction(int(q.p), int(q.q))
    return f if 0 < f < 1 else None


def stop_fractions(world: World, i: int) -> list:
    """The rational stop points strictly inside robot ``i``'s current piece, in order:
    at and between the piece's critical instants (1/2 when it has none)."""
    rob = world.robots[i]
    try:
        points, _sided = look_points(rob.path[0], world, i, rob.centre,
                                     world.readings.A1 == "sec-r")
    except (ValueError, ArithmeticError):
        return [HALF]                 # the kernel cannot hold the instants: a plain stop
    out = sorted({f for f in (_rational(lp.f) for lp in points) if f is not None})
    return out or [HALF]


def _joint_stops(world: World, group) -> list:
    pieces = {i: world.robots[i].path[0] for i in group}
    try:
        points, _sided = joint_look_points(pieces, world, world.readings.A1 == "sec-r")
    except (ValueError, ArithmeticError):
        return [HALF]
    out = sorted({f for f in (_rational(jp.tau) for jp in points) if f is not None})
    return out or [HALF]


def children(world: World, frames=FRAMES, joint: bool = True):
    """Every action the adversary may take now (see the module docstring), in a fixed
    order: joint steps, single moves, Looks."""
    busy = world.busy()
    if joint and len(busy) >= 2:
        groups = [tuple(busy)] + ([c for c in combinations(busy, 2)] if len(busy) > 2 else [])
        for group in groups:
            for stop in [None] + _joint_stops(world, group):
                s = None if stop is None else str(stop)
                yield {"a": "step", "moves": [[i, s, False] for i in group]}
    for i, rob in enumerate(world.robots):
        if rob.busy:
            yield {"a": "advance", "robot": i, "stop": None, "end": False}
            for stop in stop_fractions(world, i):
                yield {"a": "advance", "robot": i, "stop": str(stop), "end": False}
                if not world.rigid:
                    yield {"a": "advance", "robot": i, "stop": str(stop), "end": True}
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
            world.advance_together([(i, None if stop is None else Fraction(stop), end)
                                    for i, stop, end in act["moves"]])
        else:
            stop = None if act["stop"] is None else Fraction(act["stop"])
            world.advance(act["robot"], stop, act["end"])
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
