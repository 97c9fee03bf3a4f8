"""One growing tower of quadratic extensions per run: nested-radical positions.

A radial move towards C (FormGPattern, the gathering robot's ``radial_point``) divides ``p - C`` by
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
* :func:`home` -- a number of another tower rewritten in a given one: level by level,
  ``a + b y_i`` with ``y_i`` replaced by the root of the re-homed radicand in the target
  tower (an existing element when it denests there, else a new level);
* :func:`run_tower_for` -- the one RunTower that holds a critical instant's tower.

The gathering simulator's ``run_home`` re-homes points, path pieces and snapshots with
these.

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

import weakref

from ...errors import FieldTooLargeError
from .. import tower as T
from ..mq_closure import decided_sqrt
from ..multiquadratic import MQ
from ..tower import Tower, TowerElement
from .algebraic_numbers import AlgebraicNumber
from .algebraic_tower import is_algebraic_tower, sqrt_over_k_alpha
from .tower_numbers import TowerNumber, is_tower, tower_sqrt

__all__ = ["RunTower", "sqrt_exact", "run_tower_for", "home"]


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
    epoch = 0          # part of every decision cache key (the gathering's RunHome.scratch)

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
    instant at a root of a cubic or quartic factor, :mod:`.algebraic_numbers`) has its
    own tower over K(alpha) (:mod:`.algebraic_tower`), never the run's."""
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


#: a one-level tower of :mod:`.tower_numbers` -> its RunTower; weak keys: an entry lives as
#: long as its tower (the tower's identity is the key: a dead tower's entry goes with it)
_RUN_TOWER_OF: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


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
