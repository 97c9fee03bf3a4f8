"""The run's tower in the world: points, path pieces and snapshots re-homed into it.

A run owns one :class:`~exactsym.exact.algebraic.run_tower.RunTower` (nested-radical
positions; the numbers and their square roots live in :mod:`exactsym.exact.algebraic`).
This module moves the simulator's data into it:

* :func:`common_tower` -- a snapshot whose coordinates come from several towers (a
  position of the run and a critical instant built on its own one-level tower, whose
  base test is complete at level 1 only) re-homed into one RunTower;
* :func:`home_point` / :func:`home_piece` -- a point, a path piece of another tower
  rewritten in a given one (:func:`~exactsym.exact.algebraic.run_tower.home`);
* :func:`instant_in` -- a critical instant (a root in its own tower) re-homed into the
  tower of the pieces a Look at it evaluates;
* :func:`snapshot_key` -- a decision cache key that never compares two towers;
* :func:`mixes` -- would numbers of ``K(alpha)`` meet a run's tower in a fresh Look;
* :class:`RunHome` -- the world's holder of its tower (:mod:`.world`): every path a Look
  plans is re-homed into it before the robot moves along it.
"""

from __future__ import annotations

import contextlib
import itertools

from ..errors import FieldTooLargeError
from ..exact.algebraic.interface import (algebraic_root_of, is_multiquadratic, is_run_tower,
                                         nested_tower)
from ..exact.algebraic.run_tower import RunTower, home, run_tower_for
from ..exact.algebraic.tower_numbers import is_tower
from . import geometry as g

__all__ = ["RunHome", "common_tower", "home_point", "home_piece", "towers_of",
           "snapshot_key", "instant_in", "instant_or_none", "mixes"]


def _coordinates(obj):
    """The kernel numbers of a path piece, or of a sequence of points or pieces."""
    out: list = []
    for item in obj:
        if isinstance(item, (g.Segment, g.Arc)):
            pts = (item.start, item.end) + ((item.centre,) if isinstance(item, g.Arc) else ())
            out.extend(c for p in pts for c in p)
        else:
            out.extend(item)
    return out


def towers_of(points) -> tuple:
    """The distinct towers of the coordinates of ``points``, in order of appearance
    (not the towers over K(alpha): those numbers come only from fresh Looks at an
    instant, are compared there and never moved along, so they are not re-homed)."""
    out: list = []
    for c in _coordinates(points):
        tower = nested_tower(c)
        if tower is not None and not any(tower is t for t in out):
            out.append(tower)
    return tuple(out)


def snapshot_key(snapshot) -> tuple:
    """A decision cache key for ``snapshot``: ``(towers, their epochs, points)``, the
    points re-homed into one tower first (:func:`common_tower`).  A tuple compares its
    towers (by identity) and their epochs (:meth:`RunHome.scratch`) first, so points of
    two towers, or of a tower before and after a scratch, are never compared."""
    points, _tower = common_tower(tuple(snapshot))
    towers = towers_of(points)
    return towers, tuple(getattr(t, "epoch", 0) for t in towers), points


def home_point(p, tower: RunTower):
    return (home(p[0], tower), home(p[1], tower))


def home_piece(piece, tower: RunTower):
    if isinstance(piece, g.Segment):
        return g.Segment(home_point(piece.start, tower), home_point(piece.end, tower))
    return g.Arc(home_point(piece.centre, tower), home_point(piece.start, tower),
                 home_point(piece.end, tower), piece.sense)


def common_tower(points):
    """``(points, tower)``: the points with every coordinate in one :class:`RunTower`
    (``tower``; None when all are MQ): the first RunTower among them (the run's), else
    the one of the first other tower (:func:`run_tower_for`)."""
    towers = towers_of(points)
    if not towers:
        return tuple(points), None
    target = next((t for t in towers if is_run_tower(t)), None) or \
        run_tower_for(towers[0])
    if towers == (target,):
        return tuple(points), target
    return tuple(home_point(p, target) for p in points), target


def instant_in(f, pieces):
    """The exact instant ``f`` (a root of a critical polynomial) as a number of the run's
    tower that ``pieces`` (the movers' pieces) lie in, so that ``piece.at(f)`` mixes no
    two towers: a nested root of a polynomial with multiquadratic coefficients is a number
    of its own one-level tower (:mod:`~exactsym.exact.algebraic.tower_numbers`) even when
    the pieces are in the run's (a radial segment from a nested-radical point, ``x(f) = t
    (1 + f)``, has ``x(f)^2 = t^2 (1 + f)^2`` with ``t^2`` multiquadratic).  ``f``
    unchanged when it is no number of a tower of nested radicals (K(alpha)'s towers are
    not re-homed, :func:`towers_of`) or no piece lies in a :class:`RunTower`; ValueError
    when the re-homing needs a square root the tower cannot decide."""
    target = next((t for t in towers_of(list(pieces)) if is_run_tower(t)), None)
    if target is None or not is_tower(f) or towers_of([(f,)]) in ((), (target,)):
        return f
    try:
        return home(f, target)
    except FieldTooLargeError as err:        # more levels than the tower allows
        raise ValueError(str(err)) from None


_EPOCHS = itertools.count(1)


class RunHome:
    """The tower of one run (:class:`.world.World`): the start's (``points``), else None
    until a nested radical appears; every planned path is re-homed into it
    (:meth:`path`)."""

    def __init__(self, points=()):
        # a start of nested radicals (:mod:`.start_numbers`) brings the run's tower along
        self.tower: RunTower | None = next(
            (t for t in towers_of(points) if is_run_tower(t)), None)

    @contextlib.contextmanager
    def scratch(self):
        """The invariants' fresh Looks are hypothetical: the levels they add to the run's
        tower (a target no robot moves to, an instant re-homed) are taken back when the
        block ends normally, so the tower grows only with the run's own moves (each level
        multiplies the cost of a square-root test by up to three).  Numbers built inside
        are dropped with it; the decision caches (:func:`.robot.decide`,
        :func:`.corrected.decide_corrected`) key on the tower's epoch, which is a fresh
        one inside and the old one again after, so no cached decision outlives the levels
        it names.  A Violation leaves the block by an exception: nothing is taken back
        (its witness may name those numbers, and the run stops)."""
        tower = self.tower
        mark = None if tower is None else tower.mark()
        if tower is not None:
            tower.epoch = next(_EPOCHS)
        yield
        if tower is None:
            self.tower = None
        else:
            tower.rollback(mark)

    def path(self, pieces) -> list:
        pieces = list(pieces)
        towers = towers_of(pieces)
        if not towers or towers == (self.tower,):
            return pieces
        if self.tower is None:
            self.tower = RunTower()
        return [home_piece(pc, self.tower) for pc in pieces]

    def same_point(self, a, b) -> bool:
        """Are the points ``a`` and ``b`` equal?  Compared as they are when their
        coordinates share a tower (or are MQs); else both are re-homed into the run's
        tower first (ValueError when that cannot be decided, as in :meth:`path`)."""
        if len(towers_of((a, b))) <= 1:
            return a == b
        if self.tower is None:
            self.tower = RunTower()
        return home_point(a, self.tower) == home_point(b, self.tower)

    @property
    def levels(self) -> int:
        return 0 if self.tower is None else self.tower.levels


def mixes(world, pieces=(), instant=None) -> bool:
    """Would numbers of ``K(alpha)`` meet numbers of another kind (a run's tower of
    nested radicals) in a fresh Look at an instant of ``pieces``: a robot standing, a
    pending target or a planned path in such a field?  They do not mix (no common field
    is built), so such an instant stays ``sided``.  With ``instant`` (a number of some
    ``K(alpha)``): do the world's numbers hold a tower number or a number of another
    ``K(beta)``?  A start in ``K(alpha)`` (:mod:`.start_numbers`) mixes with its own
    instants of ``K(alpha)`` (the same root: one field)."""
    pts = [p for pc in pieces for p in (pc.start, pc.end)]
    for r in world.robots:
        pts.append(r.pos)
        pts += [p for pc in (r.path or ()) for p in (pc.start, pc.end)]
        if r.target is not None:
            pts.append(r.target)
    if instant is None:
        return any(not is_multiquadratic(c) for p in pts for c in p)
    root = algebraic_root_of(instant)
    return any(not is_multiquadratic(c) and algebraic_root_of(c) is not root
               for p in pts for c in p)


def instant_or_none(f, pieces):
    """An exact instant in the pieces' run tower (:func:`instant_in`); None (seen on both
    sides only) when there is none or re-homing it cannot be decided."""
    if f is None:
        return None
    try:
        return instant_in(f, pieces)
    except ValueError:
        return None
