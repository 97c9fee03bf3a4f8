"""A square root that the configuration's number system may not hold: adjoin it.

MakeAsym moves a robot radially to another circle (L1526, "move v_l to the circumference
of the enclosing circle of G_t"): the scale factor is ``sqrt(r_to^2 / r_from^2)``.  When
that square root is not in the configuration's field, the configuration after the move
lives in a larger one: the multiquadratic field with one more square root of a rational,
or a tower of quadratic extensions over it (:class:`~.evaluate.TowerSystem`, a nested
radical).  :func:`adjoin_sqrt` returns the root and the number system that holds it with
every number of the configuration.

A configuration in a cyclotomic field (``FieldSystem`` of Q(zeta_M)) or already in a tower
over one (:class:`~.evaluate.CyclotomicTowerSystem`) gets the root from that tower's
complete square-root test (:mod:`.cyclotomic_sqrt`): a new level only for a non-square.

Over the sparse Q(zeta_N) (cosines of turns of large denominators) the root is a new level
of a copy of the configuration's tower when Legendre characters prove it new
(:mod:`.sparse_nested`); a radicand they do not settle is out of reach.

Out of reach (None): a base Q(zeta_M) beyond the tower's a-priori bound
(:data:`~.cyclotomic_tower.MAX_BASE_DEGREE`), a number field that is not cyclotomic, and a
root sqrt(m) w whose integer m has more than 160 bits (:func:`~.mq_closure.decided_sqrt`
without its bounded split: a root found that way would make the check analyse a moved
copy of the whole configuration in a larger field, at a cost out of proportion).
"""

from __future__ import annotations

from flint import fmpq, fmpz

from ..errors import FieldTooLargeError
from .evaluate import (CyclotomicTowerSystem, FieldSystem, MultiquadraticSystem,
                       RationalSystem, SparseCyclotomicSystem, SparseKummerSystem, TowerSystem)
from .field import FieldElement
from .mq_closure import decided_sqrt
from .multiquadratic import MQ
from .tower import TowerElement, wrap

__all__ = ["adjoin_sqrt"]


def _as_mq(x):
    if isinstance(x, MQ):
        return x
    if isinstance(x, FieldElement):
        return None                       # a cyclotomic (or tower) number
    return MQ.rational(x)


def _radicands(values) -> set:
    out: set = set()
    for v in values:
        out |= set(v.radicands())
    return out


def _sparse_level(system, x):
    """``(system2, root)`` with sqrt(x) a new level over the sparse Q(zeta_N) (a copy of the
    tower: the configuration's own tower keeps its levels), or None."""
    if not isinstance(system, SparseKummerSystem) or not isinstance(x, TowerElement):
        return None
    try:
        bigger = system.extended(x)
    except FieldTooLargeError:          # not proved new: x may be a square there
        return None
    tower = bigger.tower
    return bigger, wrap(tower, (tower.levels, tower.zero, tower.one))


def adjoin_sqrt(system, numbers, x):
    """``(system2, root)``: the non-negative square root of the kernel number ``x >= 0``
    and a number system holding it and every one of ``numbers`` (the configuration's
    coordinates, in ``system``); ``system2`` is ``system`` when it already holds the
    root.  None when out of reach (see the module docstring)."""
    if isinstance(system, FieldSystem) and system.field.conductor is not None:
        try:
            system = CyclotomicTowerSystem(system.field.conductor)
        except FieldTooLargeError:
            return None
    if isinstance(system, CyclotomicTowerSystem):
        # its numbers are Q(zeta_M) elements and MQ rationals only: never an irrational MQ
        try:
            return system, system.sqrt(system.coerce(x))
        except FieldTooLargeError:      # a nested radical over a large base: out of reach
            return None
    if isinstance(system, TowerSystem):
        raw = x.v if isinstance(x, TowerElement) else system.coerce(x)
        if isinstance(raw, MQ):
            root, decided = decided_sqrt(raw, bounded=False)
            if root is not None:
                return system, root
            if not decided:
                return None
        try:
            return system, system.sqrt(x)
        except FieldTooLargeError:      # a tower beyond its bounds, or a sparse base
            return _sparse_level(system, x)
    if isinstance(system, SparseCyclotomicSystem):
        # cosines held as sums of roots of unity: the same numbers in a tower over them
        system = SparseKummerSystem(system.conductor)
        return _sparse_level(system, system.coerce(x))
    if not isinstance(system, (RationalSystem, MultiquadraticSystem)):
        return None
    mx = _as_mq(x)
    # a rational coordinate has no radicand: only the others are converted (100,000
    # random points: 200,000 MQ numbers built for nothing, issue 9)
    values = [_as_mq(v) for v in numbers if type(v) is not fmpq]
    if mx is None or any(v is None for v in values):
        return None
    root, decided = decided_sqrt(mx, bounded=False)
    if root is not None:
        have = set(getattr(system, "radicands", ()))
        need = _radicands([root]) - {1}
        if isinstance(system, MultiquadraticSystem) and need <= have:
            return system, root
        return MultiquadraticSystem(have | need | _radicands(values)), root
    if not decided:
        return None
    primes = sorted({int(p) for m in _radicands(values + [mx]) for p, _ in fmpz(m).factor()})
    tower = TowerSystem(primes)
    return tower, tower.sqrt(mx)
