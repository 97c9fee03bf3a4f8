"""The adversary search: a shortest schedule that violates an invariant (issue 30).

The adversary's choices at a state are :func:`.adversary.children` (Looks in both
handednesses and in a generic frame of each; stops at and between the critical instants
of the current motions; joint steps of several movers).  The search runs in two phases
over a shared budget of states, a depth bound and a time bound:

1. breadth-first, each layer ordered by the badness score (:func:`.adversary.badness`:
   the smallest clearance or the nearest distance tie), so within the states explored the
   first violation found has the fewest actions;
2. when the first phase has used its half of the budget (or exhausted its depth) without
   a violation: best-first on the badness score (ties: fewer actions first, then a
   seeded random order), which goes deep along near-collisions.

States are de-duplicated by an exact canonical key (:func:`.state_key.state_key`);
a Look after which the robot stays changes nothing and is not expanded.  A violating
schedule is shrunk (:func:`.shrink.shrink`: delta debugging over the actions) and
replayed, so the result carries a trace that ``replay`` reproduces.  Deterministic for a
seed, unless the time bound cuts the search (the report says so).
"""

from __future__ import annotations

import copy
import heapq
import random
import time
from dataclasses import dataclass, field
from fractions import Fraction

from ..exact.algebraic.interface import is_multiquadratic
from . import geometry as g
from .adversary import FRAMES, apply_action, badness, children
from .invariants import Checker, Violation
from .robot import Readings
from .schedulers import Result, run
from .shrink import replay_actions, shrink
from .state_key import state_key
from .world import IDENTITY, MIRROR, World


@dataclass(frozen=True)
class Bounds:
    """``budget``: states generated at most; ``depth``: actions per schedule at most;
    ``seed``: the order among equally bad states; ``seconds``: wall-clock bound (None:
    none); ``shrink``: delta-debug a found schedule."""
    budget: int = 10_000
    depth: int = 16
    seed: int = 0
    seconds: float | None = None
    shrink: bool = True


@dataclass
class SearchReport:
    """What a search did: ``actions`` the (shrunk) violating schedule or None;
    ``found_length`` its length before shrinking; ``states`` generated; ``expanded``;
    ``depth`` the longest schedule expanded; ``stopped`` why it ended ("violation",
    "exhausted" -- every state within the depth bound seen: no violation there --,
    "budget", "time"); ``phase`` where the violation was found ("breadth-first",
    "best-first"); ``result`` the replayed run (with its trace) or None."""
    actions: list | None = None
    found_length: int | None = None
    states: int = 0
    expanded: int = 0
    depth: int = 0
    stopped: str = "exhausted"
    phase: str | None = None
    seconds: float = 0.0
    result: Result | None = None
    shrink_replays: int = 0
    notes: list = field(default_factory=list)

    def as_dict(self) -> dict:
        return {"found": self.actions is not None, "actions": self.actions,
                "found_length": self.found_length,
                "length": None if self.actions is None else len(self.actions),
                "states": self.states, "expanded": self.expanded, "depth": self.depth,
                "stopped": self.stopped, "phase": self.phase,
                "seconds": round(self.seconds, 3), "shrink_replays": self.shrink_replays}


def root_world(points, settings: dict) -> World:
    delta = settings.get("delta")
    return World(points, Readings(**settings["readings"]), settings.get("rigid", True),
                 None if delta is None else Fraction(delta),
                 Checker(enabled=frozenset(settings["invariants"])),
                 settings.get("algorithm", "paper"))


def _points_of(world: World):
    for rob in world.robots:
        for p in (rob.pos, rob.start, rob.target, rob.centre):
            if p is not None:
                yield p
        for piece in rob.path:
            yield from (piece.start, piece.end) + \
                ((piece.centre,) if isinstance(piece, g.Arc) else ())
    if world.checker is not None:          # the targets of the last Looks' plans (I3)
        for plan in world.checker.look_plans.values():
            yield from (target for _role, target in plan.values())


def fork(world: World) -> World:
    """A copy of ``world`` that grows on its own (a deep copy: its tower too), sharing
    what never changes: the multiquadratic numbers of its positions and paths (immutable
    values: positions, paths, planned targets), the entries of its path log (frozen, and only drawn) and its table of
    points mapped into Look frames (a cache keyed by value, multiquadratic points only);
    a plain deep copy spent half the search's time walking them."""
    memo = {id(step): step for step in world.log}
    local = world.frame_table()
    if local is not None:
        memo[id(local)] = local
    for p in _points_of(world):
        for x in p:
            if is_multiquadratic(x):
                memo[id(x)] = x
    return copy.deepcopy(world, memo)


class _Explorer:
    """The shared state of one search: the seen keys, the counters and the bounds."""

    def __init__(self, bounds: Bounds, frames, report: SearchReport):
        self.bounds, self.frames, self.report = bounds, frames, report
        self.seen: set = set()
        self.start = time.monotonic()
        self.rng = random.Random(bounds.seed)

    def out_of_time(self) -> bool:
        s = self.bounds.seconds
        return s is not None and time.monotonic() - self.start > s

    def expand(self, world: World, actions: list, limit: int):
        """The new states after ``world`` as ``(child, actions)``; a violation raises
        ``_Found``.  Stops generating at ``limit`` states."""
        self.report.expanded += 1
        self.report.depth = max(self.report.depth, len(actions) + 1)
        out = []
        for act in children(world, self.frames):
            if self.report.states >= limit or self.out_of_time():
                break
            self.report.states += 1
            child = fork(world)
            was_busy = act["a"] == "step" or child.robots[act["robot"]].busy
            try:
                if not apply_action(child, act):
                    continue
            except Violation:
                raise _Found(actions + [act]) from None
            if act["a"] == "look" and not was_busy and not child.robots[act["robot"]].busy:
                continue                        # the robot stays: nothing changed
            k = state_key(child)
            if k in self.seen:
                continue
            self.seen.add(k)
            out.append((child, actions + [act]))
        return out


class _Found(Exception):
    def __init__(self, actions):
        super().__init__("violation")
        self.actions = actions


def _breadth_first(ex: _Explorer, root: World, share: int):
    """Layer by layer, each layer ordered by badness, until ``share`` states have been
    generated (checked before each expansion; an expansion is cut only by the whole
    budget); returns the frontier left for the best-first phase."""
    layer = [(root, [])]
    while layer:
        if len(layer[0][1]) >= ex.bounds.depth:
            return []
        nxt = []
        for k, (world, actions) in enumerate(layer):
            if ex.report.states >= share or ex.out_of_time():
                return layer[k:] + nxt
            nxt.extend(ex.expand(world, actions, ex.bounds.budget))
        nxt.sort(key=lambda wa: badness(wa[0]))
        layer = nxt
    return []


def _best_first(ex: _Explorer, frontier: list):
    heap, tick = [], 0
    for world, actions in frontier:
        heapq.heappush(heap, (badness(world), len(actions), ex.rng.random(), tick,
                              world, actions))
        tick += 1
    while heap:
        if ex.report.states >= ex.bounds.budget or ex.out_of_time():
            return
        *_k, world, actions = heapq.heappop(heap)
        if len(actions) >= ex.bounds.depth:
            continue
        for child, acts in ex.expand(world, actions, ex.bounds.budget):
            heapq.heappush(heap, (badness(child), len(acts), ex.rng.random(), tick,
                                  child, acts))
            tick += 1


def search(points, settings: dict, bounds: Bounds = Bounds(), frames=FRAMES) -> SearchReport:
    """Search the adversary's choices for a shortest violating schedule (module
    docstring); never raises a violation."""
    report = SearchReport()
    ex = _Explorer(bounds, frames, report)
    root = root_world(points, settings)
    ex.seen.add(state_key(root))
    try:
        report.phase = "breadth-first"
        frontier = _breadth_first(ex, root, max(1, bounds.budget // 2))
        if frontier:
            report.phase = "best-first"
            _best_first(ex, frontier)
    except _Found as found:
        report.found_length = len(found.actions)
        actions = found.actions
        if bounds.shrink:
            actions, report.shrink_replays = shrink(points, settings, actions)
        report.result = replay_actions(points, settings, actions)
        report.actions = report.result.actions
        report.stopped = "violation"
    else:
        report.phase = None
        if ex.out_of_time():
            report.stopped = "time"
            report.notes.append("cut by the time bound: not reproducible by seed alone")
        elif report.states >= bounds.budget:
            report.stopped = "budget"
    report.seconds = time.monotonic() - ex.start
    return report


def exhaustive(points, settings: dict, max_depth: int = 8, max_nodes: int = 1500):
    """Shortest violating action list, breadth-first only, in the plain and the mirrored
    frame, unshrunk; None within the bounds."""
    report = SearchReport()
    ex = _Explorer(Bounds(budget=max_nodes, depth=max_depth, shrink=False),
                   (IDENTITY, MIRROR), report)
    root = root_world(points, settings)
    ex.seen.add(state_key(root))
    try:
        _breadth_first(ex, root, max_nodes)
    except _Found as found:
        return found.actions
    return None


def search_violation(points, settings: dict, max_depth: int = 8, max_nodes: int = 1500,
                     restarts: int = 10) -> Result | None:
    """A shortest violating run: the search first, then seeded random ASYNC restarts."""
    report = search(points, settings, Bounds(budget=max_nodes, depth=max_depth))
    if report.result is not None:
        return report.result
    best = None
    for seed in range(restarts):
        delta = settings.get("delta")
        res = run(points, "async", seed, Readings(**settings["readings"]),
                  settings.get("rigid", True), None if delta is None else Fraction(delta),
                  settings["max_events"], Checker(enabled=frozenset(settings["invariants"])),
                  algorithm=settings.get("algorithm", "paper"))
        if res.outcome == "violated" and (best is None or res.events < best.events):
            best = res
    return best
