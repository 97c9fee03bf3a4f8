"""The adversary search: a shortest schedule that violates an invariant.

Breadth-first over the adversary's choices (which robot acts; a Look in the plain or the
reflected frame -- the two handednesses; an advance to the end of the current piece or to
its middle; a non-rigid stop; with two or more pending moves, a ``step`` of every busy
robot, and of every pair of them, at once -- all to their pieces' ends or all to their
middles -- so overlaps that only simultaneous motion produces are found), so the first
violation found has the fewest actions.
Looks after which the robot stays change nothing and are not expanded; states already
seen (same positions and pending paths) are not expanded twice.  Exhaustive up to
``max_depth`` actions and ``max_nodes`` states; beyond, random ASYNC restarts (seeded)
and the shortest violation among them.  The result is a run replayed from the found
actions, so it carries its trace.
"""

from __future__ import annotations

import copy
from collections import deque
from itertools import combinations
from fractions import Fraction

from .invariants import Checker, Violation
from .robot import Readings
from .schedulers import Result, run
from .state_key import state_key
from .world import IDENTITY, MIRROR, Frame, World


def _children(world: World):
    busy = world.busy()
    if len(busy) >= 2:
        groups = [tuple(busy)] + [c for c in combinations(busy, 2) if len(busy) > 2]
        for group in groups:
            for stop in (None, "1/2"):
                yield {"a": "step", "moves": [[i, stop, False] for i in group]}
    for i, rob in enumerate(world.robots):
        if rob.busy:
            yield {"a": "advance", "robot": i, "stop": None, "end": False}
            yield {"a": "advance", "robot": i, "stop": "1/2", "end": False}
            if not world.rigid:
                yield {"a": "advance", "robot": i, "stop": "1/2", "end": True}
        else:
            for frame in (IDENTITY, MIRROR):
                yield {"a": "look", "robot": i, "frame": frame.as_list()}


def _apply(world: World, act) -> bool:
    """Apply ``act``; False when it is not allowed (a non-rigid stop before delta)."""
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


def exhaustive(points, settings: dict, max_depth: int = 8, max_nodes: int = 1500):
    """Shortest violating action list (breadth-first), or None within the bounds."""
    readings = Readings(**settings["readings"])
    delta = settings.get("delta")
    root = World(points, readings, settings.get("rigid", True),
                 None if delta is None else Fraction(delta),
                 Checker(enabled=frozenset(settings["invariants"])),
                 settings.get("algorithm", "paper"))
    queue = deque([(root, [])])
    seen = {state_key(root)}
    nodes = 0
    while queue and nodes < max_nodes:
        world, actions = queue.popleft()
        if len(actions) >= max_depth:
            continue
        for act in _children(world):
            nodes += 1
            child = copy.deepcopy(world)
            was_busy = act["a"] == "step" or child.robots[act["robot"]].busy
            try:
                if not _apply(child, act):
                    continue
            except Violation:
                return actions + [act]
            if act["a"] == "look" and not was_busy and not child.robots[act["robot"]].busy:
                continue                        # the robot stays: nothing changed
            k = state_key(child)
            if k in seen:
                continue
            seen.add(k)
            queue.append((child, actions + [act]))
    return None


def search_violation(points, settings: dict, max_depth: int = 8, max_nodes: int = 1500,
                     restarts: int = 10) -> Result | None:
    """A shortest violating run: exhaustive first, then seeded random ASYNC restarts."""
    def replayed(actions):
        delta = settings.get("delta")
        return run(points, readings=Readings(**settings["readings"]),
                   rigid=settings.get("rigid", True),
                   delta=None if delta is None else Fraction(delta),
                   max_events=len(actions) + 1,
                   checker=Checker(enabled=frozenset(settings["invariants"])),
                   actions=actions, algorithm=settings.get("algorithm", "paper"))
    found = exhaustive(points, settings, max_depth, max_nodes)
    if found is not None:
        return replayed(found)
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
