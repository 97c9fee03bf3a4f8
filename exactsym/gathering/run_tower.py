"""One growing tower of quadratic extensions per run: nested-radical positions.

A radial move towards C (FormGPattern, :func:`.robot.radial_point`) divides ``p - C`` by
``|p - C|``.  With ``|p - C|^2`` rational, or a square in the multiquadratic closure,
the target stays multiquadratic; otherwise (a robot that slid along an arc and is seen
from another C, a mover caught at a nested-radical instant) the target is a point whose
coordinates are numbers of a tower K_0 < K_1 < ... of quadratic extensions over the
multiquadratic closure K_0, and the robot stands there after its move.

Everything that is compared must live in one tower (canonical forms of two towers are
not comparable: :meth:`.tower_numbers.TowerNumber.__eq__` raises), so a run owns one
:class:`RunTower`, created when the first nested radical appears and grown in place
(levels are appended; numbers built earlier stay valid and keep their form):

* :func:`sqrt_exact` -- the non-negative root of a kernel number: an MQ when it lies in
  the multiquadratic closure, else a number of the given tower (a new level only for a
  radicand proved a non-square there), or of a new :class:`RunTower` when none is given;
* :func:`common_tower` -- a snapshot whose coordinates come from several towers (a
  position of the run and a critical instant built on its own one-level tower,
  :mod:`.tower_numbers`, whose base test is complete at level 1 only) re-homed into
  one :class:`RunTower`;
* :func:`home` / :func:`home_point` / :func:`home_piece` -- a number (point, path piece)
  of another tower rewritten in a given one: level by level, ``a + b y_i`` with ``y_i``
  replaced by the root of the re-homed radicand in the target tower (an existing element
  when it denests there, else a new level);
* :func:`instant_in` -- a critical instant (a root in its own tower) re-homed into the
  tower of the pieces a Look at it evaluates;
* :class:`RunHome` -- the world's holder of its tower (:mod:`.world`): every path a Look
  plans is re-homed into it before the robot moves along it.

Soundness.  :class:`RunTower`'s base field is the whole multiquadratic closure: its
square-root test at level 0 is :func:`~exactsym.exact.mq_closure.decided_sqrt` (Kummer
theory, any primes), so the tower's recursive test (:meth:`.Tower.root_in`) is complete
at every level and a level is added only on a radicand that is a square in no field
reached by square roots of rationals added later (layer slots, other radial targets).
When that test cannot write a root it found (an integer of more than 160 bits that
:func:`~exactsym.exact.mq_closure.bounded_squarefree_split` cannot split), or a level beyond
:data:`~exactsym.exact.tower.MAX_LEVELS` would be needed, ValueError: the decision is
then ``undecided``, never wrong.  Runs that never meet a nested radical build no
tower at all.
"""

from __future__ import annotations

import contextlib
import itertools

from ..errors import FieldTooLargeError
from ..exact import tower as T
from ..exact.mq_closure import decided_sqrt
from ..exact.multiquadratic import MQ
from ..exact.tower import Tower, TowerElement
from . import geometry as g
from .tower_numbers import TowerNumber, is_tower, tower_sqrt

__all__ = ["RunTower", "RunHome", "sqrt_exact", "common_tower", "run_tower_for", "home",
           "home_point", "home_piece", "towers_of", "snapshot_key", "instant_in"]


class RunTower(Tower):
    """A tower over the whole multiquadratic closure (see the module docstring)."""

    closure_base = True          # read by :func:`.tower_numbers.tower_sqrt`

    def __init__(self):
        super().__init__(())
        self._homed: dict = {}   # (foreign tower, level) -> raw root of its radicand here

    def base_root(self, x):
        root, decided = decided_sqrt(x)
        if root is None and not decided:
            raise ValueError("a square root whose radicand (more than 160 bits) the bounded "
                             "split cannot tell (mq_closure.decided_sqrt)")
        return root

    def __deepcopy__(self, memo):
        # the adversary search copies worlds (search.py): a copy grows on its own; raw
        # values, radicands and Arb balls are immutable, so its tables are copied
        # shallowly (Arb balls cannot be deep-copied at all)
        twin = RunTower.__new__(RunTower)
        memo[id(self)] = twin
        for name, value in vars(self).items():
            setattr(twin, name, value.copy() if isinstance(value, (list, dict)) else value)
        return twin

    def number(self, v):
        """A raw value as a kernel number of this tower (an MQ at level 0)."""
        return v if isinstance(v, MQ) else TowerNumber(self, v)

    # -- hypothetical growth (the invariants' fresh Looks, RunHome.scratch) ---------------
    epoch = 0          # part of every decision cache key: see :meth:`RunHome.scratch`

    def mark(self) -> tuple:
        return (self.epoch, len(self.radicands), len(self._roots), len(self._balls),
                len(self._homed))

    def rollback(self, mark: tuple) -> None:
        """Forget the levels and table entries added since ``mark`` (the tables are only
        ever added to, so insertion order tells what is newer)."""
        self.epoch, levels, *sizes = mark
        del self.radicands[levels:]
        for table, size in zip((self._roots, self._balls, self._homed), sizes):
            while len(table) > size:
                table.popitem()


def sqrt_exact(x, tower: RunTower | None = None):
    """The non-negative square root of the kernel number ``x >= 0`` (an MQ or a tower
    number): an MQ when it lies in the multiquadratic closure, else a tower number of
    ``x``'s tower, of ``tower`` (x an MQ), or of a new :class:`RunTower`.  ValueError
    when ``x < 0`` or when the closure test cannot decide.  A number of K(alpha) (an
    instant at a root of a cubic or quartic factor, :mod:`.algebraic_instants`) has its
    own tower over K(alpha) (:mod:`.algebraic_tower`), never the run's."""
    from .algebraic_instants import AlgebraicNumber
    from .algebraic_tower import is_algebraic_tower, sqrt_over_k_alpha
    if isinstance(x, AlgebraicNumber) or is_algebraic_tower(x):
        root = sqrt_over_k_alpha(x)
        if root is None:
            raise ValueError("a square root over K(alpha) that is not built")
        return root
    if is_tower(x):
        try:
            root = tower_sqrt(x)
        except FieldTooLargeError as err:
            raise ValueError(str(err)) from None
        if root is None:
            raise ValueError("the square root of a tower number cannot be decided")
        return root
    if not isinstance(x, MQ):
        x = MQ.coerce(x)
    if x.sign() < 0:
        raise ValueError("square root of a negative number")
    root, decided = decided_sqrt(x)
    if root is not None:
        return root
    if not decided:
        raise ValueError("a square root whose radicand (more than 160 bits) the bounded "
                         "split cannot tell (mq_closure.decided_sqrt)")
    tower = tower if tower is not None else RunTower()
    try:
        return tower.number(tower.sqrt(x))
    except FieldTooLargeError as err:        # more levels than the tower allows
        raise ValueError(str(err)) from None


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
    from .algebraic_tower import AlgebraicTower
    out: list = []
    for c in _coordinates(points):
        if (isinstance(c, TowerElement) and not isinstance(c.tower, AlgebraicTower)
                and not any(c.tower is t for t in out)):
            out.append(c.tower)
    return tuple(out)


def snapshot_key(snapshot) -> tuple:
    """A decision cache key for ``snapshot``: ``(towers, their epochs, points)``, the
    points re-homed into one tower first (:func:`common_tower`).  A tuple compares its
    towers (by identity) and their epochs (:meth:`RunHome.scratch`) first, so points of
    two towers, or of a tower before and after a scratch, are never compared."""
    points, _tower = common_tower(tuple(snapshot))
    towers = towers_of(points)
    return towers, tuple(getattr(t, "epoch", 0) for t in towers), points


def home(x, tower: RunTower):
    """The kernel number ``x`` as a number of ``tower`` (the same value)."""
    if not isinstance(x, TowerElement) or x.tower is tower:
        return x
    return tower.number(_home_raw(x.tower, x.v, tower))


def _home_raw(src: Tower, v, tower: RunTower):
    if type(v) is not tuple:
        return v
    lev, a, b = v
    key = (src, lev)
    root = tower._homed.get(key)
    if root is None:
        radicand = _home_raw(src, src.radicands[lev - 1], tower)
        root = tower._homed[key] = tower.sqrt(radicand)
    return T.add(_home_raw(src, a, tower), tower.mul(_home_raw(src, b, tower), root))


def home_point(p, tower: RunTower):
    return (home(p[0], tower), home(p[1], tower))


def home_piece(piece, tower: RunTower):
    if isinstance(piece, g.Segment):
        return g.Segment(home_point(piece.start, tower), home_point(piece.end, tower))
    return g.Arc(home_point(piece.centre, tower), home_point(piece.start, tower),
                 home_point(piece.end, tower), piece.sense)


_RUN_TOWER_OF: dict = {}       # a one-level tower of tower_numbers -> its RunTower


def run_tower_for(tower: Tower) -> RunTower:
    """The :class:`RunTower` that holds the numbers of ``tower``: itself, or for a
    tower of :mod:`.tower_numbers` (a critical instant's, shared per radicand) one
    RunTower per such tower, so that two Looks at the same instant give equal numbers."""
    if isinstance(tower, RunTower):
        return tower
    run = _RUN_TOWER_OF.get(tower)
    if run is None:
        run = _RUN_TOWER_OF[tower] = RunTower()
    return run


def common_tower(points):
    """``(points, tower)``: the points with every coordinate in one :class:`RunTower`
    (``tower``; None when all are MQ): the first RunTower among them (the run's), else
    the one of the first other tower (:func:`run_tower_for`)."""
    towers = towers_of(points)
    if not towers:
        return tuple(points), None
    target = next((t for t in towers if isinstance(t, RunTower)), None) or \
        run_tower_for(towers[0])
    if towers == (target,):
        return tuple(points), target
    return tuple(home_point(p, target) for p in points), target


def instant_in(f, pieces):
    """The exact instant ``f`` (a root of a critical polynomial) as a number of the run's
    tower that ``pieces`` (the movers' pieces) lie in, so that ``piece.at(f)`` mixes no
    two towers: a nested root of a polynomial with multiquadratic coefficients is a
    number of its own one-level tower (:mod:`.tower_numbers`) even when the pieces are
    in the run's (a radial segment from a nested-radical point, ``x(f) = t (1 + f)``,
    has ``x(f)^2 = t^2 (1 + f)^2`` with ``t^2`` multiquadratic).  ``f`` unchanged when
    it is no number of a tower of nested radicals (K(alpha)'s towers are not re-homed,
    :func:`towers_of`) or no piece lies in a :class:`RunTower`; ValueError when the
    re-homing needs a square root the tower cannot decide."""
    target = next((t for t in towers_of(list(pieces)) if isinstance(t, RunTower)), None)
    if target is None or not is_tower(f) or towers_of([(f,)]) in ((), (target,)):
        return f
    try:
        return home(f, target)
    except FieldTooLargeError as err:        # more levels than the tower allows
        raise ValueError(str(err)) from None


_EPOCHS = itertools.count(1)


class RunHome:
    """The tower of one run (:class:`.world.World`): None until a nested radical
    appears; every planned path is re-homed into it (:meth:`path`)."""

    def __init__(self):
        self.tower: RunTower | None = None

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
