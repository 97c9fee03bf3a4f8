"""The world of the gathering simulator: unit discs, Looks in adversary frames, moves.

Model (spec section 1; ``docs/gathering.md``): robots are unit discs whose centres are
exact multiquadratic points, or -- after a radial move whose length is a nested radical
-- points of the run's one tower of quadratic extensions (``World.home``,
:mod:`.run_home`).  A robot is idle, or holds a pending path computed at its
last Look (ASYNC: the path may be stale when it moves).  The adversary's actions are
plain data (Pactole's demon):

* ``look(i, frame)`` -- robot i takes a snapshot of every centre in ``frame`` (a rational
  similarity, reflections included), runs :func:`.robot.decide` on it and keeps its own
  path, mapped back to the world's frame;
* ``advance(i, stop, end)`` -- robot i moves along the current piece of its path to the
  piece's end, or to ``stop`` of it: a rational fraction, or an exact critical instant
  of the motion, irrational ones included (:mod:`.stops`); ``end``: the
  adversary ends the move there (non-rigid, allowed once the straight distance from the
  move's start is at least delta, which is never more than the distance travelled);
* ``step([(i, stop, end), ...])`` -- several robots move at once over one common time
  interval [0, 1], each along its own current piece at its own speed (robot i is at
  ``piece_i.at(tau * stop_i)`` at time tau), the others stand still.

Between two actions time is continuous; a Look happens at an action boundary and sees
every robot where it is at that instant, the moving ones part-way along their paths.  An
ASYNC run is the sequence of intervals between consecutive Looks and stops: each is one
``step`` of the robots that move during it (a busy robot left out waits or is slow).
Collisions are decided exactly over the whole interval (:mod:`.geometry`): a mover
against every robot standing still, and every two movers against each other
(``geometry.joint_motion_overlap``: a polynomial in tau, its roots isolated exactly;
checked by ``invariants.Checker.after_step``, which also checks I3, I4 and I6 at the
critical instants of the joint motion, :mod:`.joint_instants`, and I9 at its SEC and
symmetry instants).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from math import isqrt

from flint import fmpq

from ..exact.algebraic.interface import is_multiquadratic, motion_number
from ..exact.multiquadratic import MQ
from . import geometry as g
from .corrected import decide_for
from .robot import Decision, Readings
from .run_home import RunHome
from .state_key import number_key


@dataclass(frozen=True)
class Frame:
    """``local = M (x - t)``; ``M = [[a, -b], [b, a]]`` or, reflected,
    ``[[a, b], [b, -a]]``; ``a, b`` rational, not both zero."""
    a: Fraction = Fraction(1)
    b: Fraction = Fraction(0)
    reflect: bool = False
    tx: Fraction = Fraction(0)
    ty: Fraction = Fraction(0)

    @property
    def unit(self) -> Fraction:
        """The robot radius seen in this frame (the similarity's scale)."""
        n = self.a * self.a + self.b * self.b
        num, den = isqrt(n.numerator), isqrt(n.denominator)
        if num * num != n.numerator or den * den != n.denominator or n == 0:
            raise ValueError(f"frame scale sqrt({n}) is not rational")
        return Fraction(num, den)

    def to_local(self, p):
        x, y = p[0] - self.tx, p[1] - self.ty
        if self.reflect:
            return (x * self.a + y * self.b, x * self.b - y * self.a)
        return (x * self.a - y * self.b, x * self.b + y * self.a)

    def to_world(self, p):
        n = self.a * self.a + self.b * self.b
        x, y = p
        if self.reflect:
            u, v = (x * self.a + y * self.b) / n, (x * self.b - y * self.a) / n
        else:
            u, v = (x * self.a + y * self.b) / n, (-x * self.b + y * self.a) / n
        return (u + self.tx, v + self.ty)

    def piece_to_world(self, piece):
        if isinstance(piece, g.Segment):
            return g.Segment(self.to_world(piece.start), self.to_world(piece.end))
        return g.Arc(self.to_world(piece.centre), self.to_world(piece.start),
                     self.to_world(piece.end), -piece.sense if self.reflect else piece.sense)

    def as_list(self) -> list:
        return [str(self.a), str(self.b), self.reflect, str(self.tx), str(self.ty)]

    @staticmethod
    def from_list(items) -> "Frame":
        a, b, r, tx, ty = items
        return Frame(Fraction(a), Fraction(b), bool(r), Fraction(tx), Fraction(ty))


IDENTITY = Frame()
MIRROR = Frame(reflect=True)


def stop_instant(stop):
    """The exact parameter of a stop strictly inside (0, 1), or None (the piece's end):
    a Fraction becomes a rational MQ; an exact number (``.sign()``) stays itself."""
    if stop is None:
        return None
    f = stop if hasattr(stop, "sign") else MQ.rational(stop)
    return f if f.sign() > 0 and (f - 1).sign() < 0 else None


@dataclass(frozen=True)
class Step:
    """One entry of a run's path log: at event ``event`` robot ``robot`` Looked
    (``kind = "look"``; ``pieces``: the path it planned, world frame, empty when it
    stays; ``centre``: the C it saw) or advanced (``kind = "advance"``; ``pieces``: the
    one piece it moved along).  Exact; converted to floats only to draw
    (:mod:`.drawing`)."""
    event: int
    robot: int
    kind: str
    pieces: tuple
    centre: tuple | None = None


@dataclass
class RobotState:
    pos: tuple
    path: list = field(default_factory=list)    # remaining pieces, world frame
    role: str | None = None
    kind: str = ""                              # robot.Move.kind of the pending move
    look_index: int | None = None               # event index of the Look
    start: tuple | None = None                  # where the current move began
    target: tuple | None = None                 # final point of the planned path
    centre: tuple | None = None                 # C at the Look (world frame)
    r_set: frozenset = frozenset()              # R at the Look (world indices)
    cut: bool = False                           # the adversary ended the move early

    @property
    def busy(self) -> bool:
        return bool(self.path)


class World:
    """Positions and pending moves; the invariant checker is told about every action."""

    def __init__(self, points, readings: Readings = Readings(), rigid: bool = True,
                 delta: Fraction | None = None, checker=None, algorithm: str = "paper"):
        self.algorithm = algorithm
        self.decide = decide_for(algorithm)     # robot.decide or corrected.decide_corrected
        self.robots = [RobotState((motion_number(x), motion_number(y))) for x, y in points]
        self.readings = readings
        self.rigid = rigid
        self.delta = delta
        self.checker = checker
        self.events = 0
        self.looks = 0
        self.log: list = []       # Step per Look and per advance (what a picture draws)
        # the run's tower of nested radicals (none until a radial target needs one): every
        # planned path is re-homed into it, so all positions compare in one tower
        self.home = RunHome(self.positions())
        self._local = None        # {frame: {point: local point}}

    def frame_table(self):
        """The table of points mapped into Look frames (keyed by value: a fork may share it)."""
        return self._local

    @property
    def n(self) -> int:
        return len(self.robots)

    def positions(self) -> tuple:
        return tuple(r.pos for r in self.robots)

    def fresh_decision(self, frame: Frame):
        """The decision (in ``frame``) every robot would reach on a fresh Look now in
        ``frame``; its paths stay in the Look's own numbers (not re-homed into the run's
        tower, which can cost a square-root test per level: a check that reads only the
        decision's centre or status needs none of it)."""
        return self.decide(self._snapshot(frame), self.readings,
                           fmpq(frame.unit.numerator, frame.unit.denominator))

    def _snapshot(self, frame: Frame) -> tuple:
        """Every position in ``frame``; a point already mapped in that frame gives the same
        local point object again (keyed by value: a point of multiquadratic coordinates,
        whose hash is remembered; a nested-radical point is mapped anew, its numbers not
        being compared across towers even as keys).  The robots that stand still during
        a check's fresh Looks then keep their local points, and with them the numbers'
        hashes, integer forms and remembered distances (``geometry.dist2``)."""
        if self._local is None or len(self._local) > 4:
            self._local = {}
        seen = self._local.get(frame)
        if seen is None or len(seen) > 8 * self.n + 64:
            seen = self._local[frame] = {}
        out = []
        for p in self.positions():
            if not (is_multiquadratic(p[0]) and is_multiquadratic(p[1])):
                out.append(frame.to_local(p))
                continue
            local = seen.get(p)
            if local is None:
                local = seen[p] = frame.to_local(p)
            out.append(local)
        return tuple(out)

    def snapshot_decision(self, frame: Frame):
        """The decision every robot would reach on a fresh Look now in ``frame``, with
        its moves mapped to the world frame: ``(decision, {robot: world path})``."""
        d = self.fresh_decision(frame)
        try:
            paths = {m.robot: self.home.path(frame.piece_to_world(pc) for pc in m.path)
                     for m in d.moves}
        except ValueError as err:
            # a planned path the run's tower cannot hold (a radicand whose test needs a
            # root sqrt(m) w whose m of more than 160 bits the bounded split cannot tell): undecided
            return Decision("undecided", (), d.centre, d.pattern, None,
                            f"the run's tower: {err}"), {}
        return d, paths

    def fresh_plan(self, frame: Frame):
        """``(decision, {robot: (role, target)})`` of a fresh Look now in ``frame``, each
        mover's final target mapped to the world frame but left in the Look's own numbers:
        the invariants compare targets only (:meth:`.RunHome.same_point`), and re-homing whole
        paths into the run's tower cost a square-root test per level and piece (the
        corrected variant's n = 30 run spent 200 s of 240 there)."""
        d = self.fresh_decision(frame)
        return d, {m.robot: (m.role, frame.to_world(m.path[-1].final))
                   for m in d.moves if m.path}

    def look(self, i: int, frame: Frame):
        """Robot ``i`` Looks in ``frame``; returns the decision (in ``frame``)."""
        rob = self.robots[i]
        if rob.busy:
            raise ValueError(f"robot {i} Looks while it has a pending move")
        self.events += 1
        self.looks += 1
        d, paths = self.snapshot_decision(frame)
        if i in paths and paths[i]:
            rob.path = list(paths[i])
            rob.role, rob.kind = d.move_of(i).role, d.move_of(i).kind
            rob.look_index = self.events
            rob.start = rob.pos
            rob.target = paths[i][-1].final
            rob.centre = frame.to_world(d.centre)
            rob.r_set = frozenset(k for k in range(self.n) if k not in d.pattern.robots)
        self.log.append(Step(self.events, i, "look", tuple(paths.get(i) or ()),
                             frame.to_world(d.centre)))
        if self.checker is not None:
            with self.home.scratch():   # fresh Looks: hypothetical
                self.checker.after_look(self, i, frame, d, paths)
        return d

    def advance(self, i: int, stop=None, end: bool = False):
        """Robot ``i`` moves along its current piece (to ``stop`` of it, or to its end);
        ``end`` stops the whole move there (non-rigid only).  ``stop``: None (the piece's
        end), a rational fraction, or an exact instant of the piece (an irrational
        critical instant, :mod:`.stops`: a multiquadratic number or a number of the
        run's tower), in (0, 1) -- outside it, the piece's end."""
        rob = self.robots[i]
        if not rob.busy:
            raise ValueError(f"robot {i} has no pending move")
        if end and self.rigid:
            raise ValueError("a rigid move cannot be stopped early")
        self.events += 1
        piece = rob.path[0]
        f = stop_instant(stop)
        if f is not None:
            # a stop at a nested-radical instant of an MQ piece is a number of its own
            # one-level tower (:func:`.run_home.instant_in` finds no run tower in the
            # piece): both halves go into the run's tower, or the robot would stand in a
            # field no other robot's numbers mix with
            done, rest = self.home.path(piece.split(f))
            rob.path[0] = rest
        else:
            done = piece
            rob.path.pop(0)
        rob.pos = done.final
        if end:
            if (g.dist2(rob.start, rob.pos) - MQ.rational(self.delta) ** 2).sign() < 0:
                raise ValueError(f"robot {i} cannot be stopped before delta")
            rob.path, rob.cut = [], bool(rob.path)     # cut: short of the target
        self.log.append(Step(self.events, i, "advance", (done,)))
        if self.checker is not None:
            with self.home.scratch():   # fresh Looks: hypothetical
                self.checker.after_advance(self, i, done)
        if not rob.path:
            if self.checker is not None:
                with self.home.scratch():   # fresh Looks: hypothetical
                    self.checker.after_arrival(self, i)
            rob.role, rob.kind, rob.look_index, rob.target = None, "", None, None
            rob.cut = False

    def advance_together(self, moves):
        """Several robots move at once: ``moves`` is ``[(robot, stop, end), ...]`` with
        the meaning of :meth:`advance` for each; they move over one common time interval
        (robot i at ``piece_i.at(tau)`` of its part ``piece_i`` at time tau).  One
        robot: exactly :meth:`advance`."""
        moves = [(int(i), stop, bool(end)) for i, stop, end in moves]
        if len({i for i, _, _ in moves}) != len(moves) or not moves:
            raise ValueError("a step names each moving robot once, and at least one")
        if len(moves) == 1:
            return self.advance(*moves[0])
        for i, _, end in moves:
            if not self.robots[i].busy:
                raise ValueError(f"robot {i} has no pending move")
            if end and self.rigid:
                raise ValueError("a rigid move cannot be stopped early")
        self.events += 1
        done, cut = {}, {}
        whole = {i: self.robots[i].path[0] for i, _, _ in moves}
        before = {i: (self.robots[i].pos, list(self.robots[i].path)) for i in whole}
        for i, stop, end in moves:
            rob = self.robots[i]
            piece = rob.path[0]
            f = stop_instant(stop)
            if f is not None:
                done[i], rest = self.home.path(piece.split(f))   # as in advance
                new = list(rob.path)
                new[0] = rest
            else:
                done[i], new = piece, rob.path[1:]
            if end and (g.dist2(rob.start, done[i].final) -
                        MQ.rational(self.delta) ** 2).sign() < 0:
                raise ValueError(f"robot {i} cannot be stopped before delta")
            done[i] = (done[i], [] if end else new)
            cut[i] = end and bool(new)
        for i, (piece, rest) in done.items():
            rob = self.robots[i]
            rob.pos, rob.path = piece.final, rest
            rob.cut = cut[i]
            self.log.append(Step(self.events, i, "advance", (piece,)))
        if self.checker is not None:
            with self.home.scratch():   # fresh Looks: hypothetical
                self.checker.after_step(self, {i: d for i, (d, _) in done.items()},
                                        _common_stop(whole, before, moves))
        if self.checker is not None:
            # the other invariants at the interval's end, a real instant: a zero-length
            # piece there (each mover's own piece would be checked against the others'
            # end positions, a configuration that never existed)
            for i in done:
                pos = self.robots[i].pos
                with self.home.scratch():   # fresh Looks: hypothetical
                    self.checker.after_advance(self, i, g.Segment(pos, pos))
        for i in done:
            rob = self.robots[i]
            if not rob.path:
                if self.checker is not None:
                    with self.home.scratch():   # fresh Looks: hypothetical
                        self.checker.after_arrival(self, i)
                rob.role, rob.kind, rob.look_index, rob.target = None, "", None, None
                rob.cut = False

    def busy(self) -> list:
        return [i for i, r in enumerate(self.robots) if r.busy]

    def state_key(self):
        """An exact key of the state the robots' future depends on: every centre and
        every pending path (the robots are oblivious: nothing else), or None when a
        number is not multiquadratic (tower numbers of two Looks are not compared, even
        as keys).  Two equal keys are the same state, exactly: from a repeated state
        the adversary can repeat its choices forever (the Compute is a pure function of
        the snapshot in the frame the adversary picks)."""
        key = []
        for r in self.robots:
            nums = list(r.pos)
            for pc in r.path:
                nums += [*pc.start, *pc.end] + ([*pc.centre] if isinstance(pc, g.Arc) else [])
            if not all(is_multiquadratic(x) for x in nums):
                return None
            key.append((r.pos, tuple(r.path)))
        return tuple(key)


def _common_stop(whole: dict, before: dict, moves) -> tuple | None:
    """``(pieces, f, before)`` (``before``: each mover's position and path before the
    step) when every mover of a step stops at the same instant ``f`` of its
    whole piece (None: the pieces' ends), so that the step is the joint motion of the
    whole pieces up to ``f`` (:meth:`.invariants.Checker.after_step` checks its instants
    there); None otherwise."""
    stops = [stop_instant(stop) for _i, stop, _end in moves]
    if all(s is None for s in stops):
        return whole, None, before
    if any(s is None for s in stops):
        return None
    return (whole, stops[0], before) if len({number_key(s) for s in stops}) == 1 else None
