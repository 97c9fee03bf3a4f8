"""Square roots at a K(alpha) instant: one quadratic extension of K(alpha).

At a critical instant that is a root ``alpha`` of a cubic (or other odd-degree) factor
(:mod:`.algebraic_numbers`), a fresh Look may need the square root of a number ``r`` of
``K(alpha)``: the mover's radial target ``C + 2L (p - C) / |p - C|``, MakeAsym's move of
the mover to G_t's circle.  :func:`.algebraic_numbers.algebraic_sqrt` finds it when it
lies in ``K'(alpha)`` for a multiquadratic ``K'``; otherwise this module adjoins it: a
:class:`~exactsym.exact.tower.Tower` whose base is ``K(alpha)`` (its numbers MQ or
:class:`~.algebraic_numbers.AlgebraicNumber`) and whose one level is ``y = sqrt(r)``.

Soundness of the canonical form ``a + b y`` (``==``, hashing) needs ``r`` to be a
non-square in ``K'(alpha)`` for *every* multiquadratic ``K'`` (a Look brings new square
roots of rationals): :func:`.algebraic_numbers.algebraic_sqrt_decided` is complete for
alpha of odd degree, so a level is built only there and only when that search decided
"no root".  The tower's own test (:meth:`~exactsym.exact.tower.Tower.root_in`: norms and
half-sums down to the base, each by that complete base test) is then complete at every
level, so further levels (at most :data:`MAX_LEVELS`) are sound too.  One tower per
root: every number of an instant lives in it, so the same Look computed twice gives
equal numbers; numbers of two towers are not compared (ValueError, as
:class:`~.tower_numbers.TowerNumber`).
"""

from __future__ import annotations

from ..mq_closure import decided_sqrt
from ..tower import Tower
from .algebraic_numbers import AlgebraicNumber, algebraic_sqrt_decided, is_algebraic
from .tower_numbers import TowerNumber

__all__ = ["AlgebraicTower", "AlgebraicTowerNumber", "is_algebraic_tower",
           "sqrt_over_k_alpha", "own_sqrt_over_k_alpha", "MAX_LEVELS"]

#: The largest number of quadratic levels built over one K(alpha).
MAX_LEVELS = 3


class AlgebraicTower(Tower):
    """``K(alpha)(sqrt r)``: base values MQ or numbers of one ``K(alpha)``."""

    def __init__(self, root):
        super().__init__(())
        self.root = root

    def __deepcopy__(self, memo):
        # shared by copies of a world (the search's forks), as its root is: levels are
        # only added, each proved a non-square over everything below it
        return self

    def coerce_base(self, other):
        if isinstance(other, AlgebraicNumber):
            return other if other.root is self.root else None
        return super().coerce_base(other)

    def wrap(self, v):
        return AlgebraicTowerNumber(self, v) if type(v) is tuple else v

    def base_root(self, x):
        """A root of the base value ``x >= 0`` in ``K'(alpha)``, or None (complete; an
        undecided search raises: no level may rest on it)."""
        root, decided = (algebraic_sqrt_decided(x) if is_algebraic(x)
                         else decided_sqrt(x))
        if not decided:
            raise ArithmeticError("square root test undecided")
        return root

    def mul(self, x, y):
        return self._mul(x, y)            # no rescaling of rational coefficients (MQ only)


class AlgebraicTowerNumber(TowerNumber):
    """A number ``a + b y`` of an :class:`AlgebraicTower` (``b != 0``): a
    :class:`~.tower_numbers.TowerNumber` (the MQ methods the gathering code calls) whose
    arithmetic keeps base values (MQ, numbers of ``K(alpha)``) as they are."""

    __slots__ = ()

    def _new(self, v):
        return self.tower.wrap(v)

    def __eq__(self, other):
        if isinstance(other, AlgebraicNumber) and other.root is not self.tower.root:
            raise ValueError("numbers of two different algebraic instants are not compared")
        return TowerNumber.__eq__(self, other)

    __ne__ = TowerNumber.__ne__
    __hash__ = TowerNumber.__hash__

    def __deepcopy__(self, memo):
        return self                       # immutable, its tower shared (above)

    def __repr__(self):
        return f"AlgebraicTowerNumber({self.text()!r})"


def is_algebraic_tower(x) -> bool:
    return isinstance(x, AlgebraicTowerNumber)


def _tower_of(root) -> AlgebraicTower:
    """The one tower over ``K(alpha)`` of this root (levels added as square roots are
    asked: every number of the instant lives in it, so all of them compare)."""
    tower = root.__dict__.get("_tower")
    if tower is None:
        tower = root.__dict__["_tower"] = AlgebraicTower(root)
    return tower


def sqrt_over_k_alpha(x):
    """The non-negative square root of ``x >= 0``, a number of ``K(alpha)`` or of its
    :class:`AlgebraicTower`: an element of the tower (``K'(alpha)`` included) when it has
    one, else -- alpha of odd degree, at most :data:`MAX_LEVELS` levels -- the generator
    of a new level; None when that cannot be decided or is not built."""
    if x.sign() < 0:
        return None
    root = x.tower.root if is_algebraic_tower(x) else x.root
    # a number of an instant's own tower (own_sqrt_over_k_alpha) grows that tower
    tower = x.tower if is_algebraic_tower(x) else _tower_of(root)
    v = x.v if is_algebraic_tower(x) else x
    try:
        found = tower.root_in(v, tower.levels)
        if found is None:
            if tower.levels >= MAX_LEVELS or root.degree % 2 == 0:
                return None            # (a quartic alpha: the base test is not complete)
            found = tower.sqrt(v)
    except ArithmeticError:
        return None
    y = tower.wrap(found)
    return -y if y.sign() < 0 else y


def own_sqrt_over_k_alpha(x):
    """The non-negative square root of the number ``x > 0`` of ``K(alpha)`` (alpha of odd
    degree) in ``K'(alpha)`` when it lies there, else the generator of a one-level tower
    of its own, ``K(alpha)(sqrt x)`` -- one per radicand and root, as
    :func:`.tower_numbers.tower_of` gives one per multiquadratic radicand.  For the
    critical instants of a run whose start is in ``K(alpha)`` (``gathering.start_numbers``):
    their discriminants would otherwise fill the root's one shared tower
    (:data:`MAX_LEVELS`) with levels no robot stands on.  Sound as the shared tower: a
    level only after the complete base test (:func:`algebraic_sqrt_decided`) found no
    root.  None when ``x <= 0``, alpha's degree is even or the test is undecided."""
    if not is_algebraic(x) or x.sign() <= 0 or x.root.degree % 2 == 0:
        return None
    table = x.root.__dict__.setdefault("_own_towers", {})
    hit = table.get(x)
    if hit is not None:
        return hit
    root, decided = algebraic_sqrt_decided(x)
    if root is None:
        if not decided or len(table) >= 4096:
            return None
        tower = AlgebraicTower(x.root)
        tower.radicands.append(x)                # proved a non-square: the one level
        root = tower.wrap((1, tower.zero, tower.one))
    table[x] = root
    return root
