"""Schedulers (the adversary's policies) and the run loop.

Every scheduler produces a sequence of adversary actions (:mod:`.world`): ``look`` with a
frame, ``advance`` with an optional stop (a fraction, or an exact critical instant:
:mod:`.stops`) and end flag.  The run records them;
:func:`replay` feeds a recorded sequence back, so a run is reproduced event for event.

* ``centralised`` -- one robot at a time, atomically: it Looks and completes its move;
* ``fsync`` -- every robot Looks at the same instant, then the movers move together
  (one ``step`` per piece: all of them over a common time interval), then the next round;
* ``ssync`` -- a random non-empty subset Looks at the same instant, then they move
  together;
* ``async`` -- each event picks a random robot: an idle one Looks; a busy one moves
  (possibly to a random rational point of its piece), and every other busy robot moves
  with it over the same interval with probability 1/2 (each at its own speed and stop),
  so Looks are taken mid-motion, moves are made on stale snapshots and pending moves
  overlap in time.

With at most one busy robot the random draws are those of the earlier interleaving
schedulers, so seeded runs in which no two robots move at once are unchanged.

Frames are random rational similarities (Pythagorean rotation, scale, translation and a
random reflection), one per Look, seeded.
"""

from __future__ import annotations

import random
import sys
from dataclasses import dataclass, field
from fractions import Fraction

from ..exact.context import in_own_context
from ..exact.multiquadratic import MQ
from . import geometry as g
from .invariants import Checker, Violation
from .pattern import recognise
from .robot import Readings
from .stops import resolve, stop_record
from .world import IDENTITY, MIRROR, Frame, World

SCHEDULERS = ("centralised", "fsync", "ssync", "async")


class TraceMismatch(Exception):
    """A recorded action that cannot be applied (the trace is not of this configuration)."""


@dataclass
class Result:
    # gathered | stalled | violated | not-possible | undecided | undecided-at-budget |
    # max-events  (docs/gathering.md, "Outcomes")
    outcome: str
    detail: str
    events: int
    looks: int
    checks: dict
    violation: dict | None
    pattern: dict
    actions: list = field(default_factory=list)
    log: tuple = ()               # world.Step per Look and advance: the paths, exact
    violation_time: object = None  # Violation.time, exact (the dict has its text)

    @property
    def label(self) -> str | None:
        return self.violation["label"] if self.violation else None


def random_frame(rng: random.Random, reflections: bool = True) -> Frame:
    t = Fraction(rng.randint(-9, 9), rng.randint(1, 9))
    s = Fraction(rng.randint(1, 6), rng.randint(1, 4))
    a, b = (1 - t * t) / (1 + t * t) * s, 2 * t / (1 + t * t) * s
    return Frame(a, b, reflections and rng.random() < 0.5, Fraction(rng.randint(-20, 20), 3),
                 Fraction(rng.randint(-20, 20), 7))


class _Run:
    def __init__(self, world: World, max_events: int, progress: bool):
        self.world = world
        self.max_events = max_events
        self.actions: list = []
        self.progress = progress
        self.last_decision = None
        # exact state key -> (event, number of actions) when it was first seen
        self.seen: dict = {}
        self.cycle: str | None = None     # the first fair cycle found: its description

    def note_state(self):
        """Remember the world's state (nobody busy) and, the first time it is exactly
        one seen before (``World.state_key``) with every robot having acted (Looked or
        moved) in between, keep that fair cycle as ``self.cycle``: the adversary could
        play it forever (the same frames, stops and order: the robots are oblivious and
        their Compute is a function of the snapshot in the frame), so the run need
        never gather.  The run goes on (its events stay those of a run without the
        record); the budget check (:func:`_stall`) reads the proof."""
        w = self.world
        if self.cycle is not None or w.busy():
            return
        key = w.state_key()
        if key is None:
            return
        if key not in self.seen:
            self.seen[key] = (w.events, len(self.actions))
            return
        event, start = self.seen[key]
        acted = set()
        for act in self.actions[start:]:
            acted |= {act["robot"]} if "robot" in act else {m[0] for m in act["moves"]}
        if len(acted) == w.n:
            self.cycle = (f"a cycle: the state after event {w.events} is exactly the state "
                          f"after event {event} (every centre, nobody busy) and every robot "
                          "acted in between; the adversary can repeat it forever")

    def look(self, i, frame):
        self.actions.append({"a": "look", "robot": i, "frame": frame.as_list()})
        self.last_decision = self.world.look(i, frame)
        self._tick()
        return self.last_decision

    def advance(self, i, stop=None, end=False):
        """``stop``: None, a rational fraction, or an exact instant's trace record
        (:mod:`.stops`, resolved against the current state)."""
        value = resolve(self.world, [i], stop)
        self.actions.append({"a": "advance", "robot": i, "stop": stop_record(stop),
                             "end": end})
        self.world.advance(i, value, end)
        self._tick()

    def step(self, moves):
        """Robots move at once (``[(robot, stop, end)]``); one robot: an ``advance``.
        An exact instant's record names an instant of the joint motion of them all."""
        if len(moves) == 1:
            return self.advance(*moves[0])
        movers = [i for i, _stop, _end in moves]
        values = [(i, resolve(self.world, movers, stop), end) for i, stop, end in moves]
        self.actions.append({"a": "step", "moves": [
            [i, stop_record(stop), end] for i, stop, end in moves]})
        self.world.advance_together(values)
        self._tick()

    def _tick(self):
        w = self.world
        if self.progress and w.events % 100 == 0:
            print(f"gather: {w.events} events, {w.looks} Looks", file=sys.stderr, flush=True)
        if w.events >= self.max_events:
            raise _MaxEvents()


class _MaxEvents(Exception):
    pass


def _status(world: World):
    """``(status, detail)`` of a fresh Look in the world frame when nobody is busy."""
    return world.fresh_decision(IDENTITY)


@in_own_context         # the run's K(alpha) roots and levels are its own (exact/context.py)
def run(points, scheduler: str = "async", seed: int = 0, readings: Readings = Readings(),
        rigid: bool = True, delta: Fraction | None = None, max_events: int = 2000,
        checker: Checker | None = None, progress: bool = False, reflections: bool = True,
        actions: list | None = None, algorithm: str = "paper") -> Result:
    """Run the gathering algorithm (``algorithm``: "paper", the paper's GatheringPattern
    and FormGPattern, or "corrected", :mod:`.corrected`); ``actions`` replays a recorded
    adversary instead."""
    checker = checker if checker is not None else Checker()
    world = World(points, readings, rigid, delta, checker, algorithm)
    r = _Run(world, max_events, progress)
    rng = random.Random(seed)
    outcome, detail, violation = "max-events", f"stopped after {max_events} events", None
    violation_time = None
    try:
        if actions is not None:
            outcome, detail = _replay(r, actions)
        else:
            outcome, detail = _POLICIES[scheduler](r, rng, reflections)
    except Violation as v:
        outcome, detail, violation = "violated", str(v), v.as_dict()
        violation_time = v.time
    except _MaxEvents:
        pass
    pts = world.positions()
    centre = _status(world).centre if not world.busy() else None
    pattern = {}
    if centre is not None:
        pat = recognise(pts, centre, readings.lone)
        pattern = {"centre": [centre[0].text(), centre[1].text()],
                   "centre_robot": pat.centre_robot,
                   "layers": [list(layer) for layer in pat.layers],
                   "size": len(pat.robots)}
    checks = dict(checker.counts)
    checks["skipped"] = checker.undecided_fresh   # I3/I9 Looks the kernel could not hold
    return Result(outcome, detail, world.events, world.looks, checks, violation,
                  pattern, r.actions, tuple(world.log), violation_time)


def _terminal(world: World):
    """When nobody is busy: "gathered", "not-possible", "undecided", a proved "stalled"
    (:func:`no_mover_in_any_frame`) or None (go on)."""
    d = _status(world)
    if d.status == "terminated":
        return "gathered", f"all {world.n} robots are in the pattern"
    if d.status == "not-possible":
        return "not-possible", d.detail
    if d.status == "undecided":
        return "undecided", d.detail
    if d.status == "stay":
        return no_mover_in_any_frame(world, d)
    return None


def no_mover_in_any_frame(world: World, d=None):
    """``("stalled", detail)`` when nobody is busy and no robot plans a move in any
    frame, else None.  A Compute sees the snapshot up to a similarity, so its plan
    depends on the frame only through the frame's handedness (what I9 checks at every
    Look against the adversary's frames): a Look in the world's frame and one in the
    reflected frame stand for every frame.  Both must plan no move with R not empty."""
    d = d if d is not None else _status(world)
    if d.status != "stay":
        return None
    m = world.fresh_decision(MIRROR)
    if m.status != "stay":
        return None
    return "stalled", (f"no robot plans a move in any frame (the world's and the reflected "
                       f"one; R not empty): {d.detail}")


def _stall(r: _Run, idle_rounds: int, leader_free: int):
    """After a round, past the budget (two idle rounds in the adversary's frames, or
    3n + 10 moves without the pattern growing): a proved stall (no mover in any frame,
    or a fair cycle seen during the run), else "undecided-at-budget": not a proof
    either way.  Before the budget: None (go on)."""
    world = r.world
    r.note_state()
    if idle_rounds >= 2:
        if not world.busy():
            proved = no_mover_in_any_frame(world)
            if proved:
                return proved
        if r.cycle is not None:
            return "stalled", r.cycle
        return "undecided-at-budget", ("a round in which every robot Looked in the "
                                       "adversary's frames and none moved, but a Look in the "
                                       "world's or the reflected frame plans a move")
    if leader_free > 3 * world.n + 10:
        if r.cycle is not None:
            return "stalled", r.cycle
        return "undecided-at-budget", (
            f"{leader_free} moves in a row without the pattern growing and no state "
            "repeated (MakeAsym / Make_SymToAsym moves: progress, I10, is not shown; "
            "neither is a stall)")
    return None


def _centralised(r: _Run, rng, reflections):
    w = r.world
    idle_rounds, since_growth = 0, 0
    while True:
        end = _terminal(w)
        if end:
            return end
        moved = False
        order = list(range(w.n))
        rng.shuffle(order)
        for i in order:
            r.look(i, random_frame(rng, reflections))
            if w.robots[i].busy:
                role = w.robots[i].role
                _finish_move(r, i, rng)
                moved = True
                since_growth = 0 if role.startswith("leader") else since_growth + 1
                break
        idle_rounds = 0 if moved else idle_rounds + 1
        stall = _stall(r, idle_rounds, since_growth)
        if stall:
            return stall


def _finish_move(r: _Run, i, rng):
    """Robot ``i`` completes its move; non-rigid: the adversary may stop at a rational point
    of a piece, and end the move there once delta is covered."""
    w = r.world
    while w.robots[i].busy:
        if not w.rigid and rng.random() < 0.3:
            stop = Fraction(rng.randint(1, 3), 4)
            r.advance(i, stop, end=_may_end(w, i, stop))
        else:
            r.advance(i)


def _may_end(w: World, i, stop) -> bool:
    rob = w.robots[i]
    pos = rob.path[0].split(MQ.rational(stop))[0].final if stop else rob.path[0].final
    return (g.dist2(rob.start, pos) - MQ.rational(w.delta) ** 2).sign() >= 0


def _synchronous(r: _Run, rng, reflections, subset: bool):
    """FSYNC (everyone) or SSYNC (a random subset) Looks at one configuration, then the
    movers move in turn.  Reaching here, a fresh Look plans a move (``_terminal``)."""
    w = r.world
    since_growth = 0
    while True:
        end = _terminal(w)
        if end:
            return end
        active = [i for i in range(w.n) if not subset or rng.random() < 0.5] or \
            [rng.randrange(w.n)]
        for i in active:
            r.look(i, random_frame(rng, reflections))
        movers = [i for i in active if w.robots[i].busy]
        roles = [w.robots[i].role for i in movers]
        _move_together(r, movers, rng)
        if movers:
            grew = any(x.startswith("leader") for x in roles)
            since_growth = 0 if grew else since_growth + 1
        # nobody moved in the adversary's frames although a Look in the world's or the
        # reflected one plans a move (``_terminal``): no proof of a stall, go on
        stall = _stall(r, 0, since_growth)
        if stall:
            return stall


def _move_together(r: _Run, movers, rng):
    """The movers move at once, piece by piece, until every move is over (non-rigid: each
    may stop at a rational point of a piece, and end there once delta is covered; with
    one mover the draws are :func:`_finish_move`'s)."""
    w = r.world
    while True:
        active = [i for i in movers if w.robots[i].busy]
        if not active:
            return
        moves = []
        for i in active:
            if not w.rigid and rng.random() < 0.3:
                stop = Fraction(rng.randint(1, 3), 4)
                moves.append((i, stop, _may_end(w, i, stop)))
            else:
                moves.append((i, None, False))
        r.step(moves)


def _fsync(r, rng, reflections):
    return _synchronous(r, rng, reflections, subset=False)


def _ssync(r, rng, reflections):
    return _synchronous(r, rng, reflections, subset=True)


def _async(r: _Run, rng, reflections):
    w = r.world
    since_growth = 0
    while True:
        if not w.busy():
            # a stall is proved by ``_terminal`` (no mover in any frame) or a fair
            # cycle (``_stall``); a Look that plans nothing in the adversary's frame is
            # no proof
            end = _terminal(w)
            if end:
                return end
        i = rng.randrange(w.n)
        rob = w.robots[i]
        if rob.busy:
            movers = [i] + [k for k in w.busy() if k != i and rng.random() < 0.5]
            roles = {k: w.robots[k].role for k in movers}
            r.step([_async_move(w, k, rng) for k in movers])
            for k in movers:
                if not w.robots[k].busy:
                    grew = roles[k].startswith("leader")
                    since_growth = 0 if grew else since_growth + 1
        else:
            r.look(i, random_frame(rng, reflections))
        stall = _stall(r, 0, since_growth)
        if stall:
            return stall


def _async_move(w: World, i, rng):
    """``(robot, stop, end)``: to the piece's end, or to a random rational point of it
    (non-rigid: maybe ending the move there)."""
    if rng.random() < 0.3:
        stop = Fraction(rng.randint(1, 3), 4)
        return i, stop, not w.rigid and rng.random() < 0.3 and _may_end(w, i, stop)
    return i, None, False


def _replay(r: _Run, actions):
    w = r.world
    for k, act in enumerate(actions):
        try:
            if act["a"] == "look":
                r.look(int(act["robot"]), Frame.from_list(act["frame"]))
            elif act["a"] == "advance":
                r.advance(int(act["robot"]), act.get("stop"), bool(act.get("end", False)))
            elif act["a"] == "step":
                r.step([(int(i), stop, bool(end)) for i, stop, end in act["moves"]])
            else:
                raise TraceMismatch(f"action {k}: unknown kind {act['a']!r}")
        except (ValueError, IndexError, KeyError, TypeError) as err:
            raise TraceMismatch(f"action {k} cannot be applied: {err}") from None
    if not w.busy():
        end = _terminal(w)
        if end:
            return end
    return "stopped", f"the trace ends after {len(actions)} actions"


_POLICIES = {"centralised": _centralised, "fsync": _fsync, "ssync": _ssync, "async": _async}
