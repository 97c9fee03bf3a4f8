"""Nested radicals for the gathering simulator: critical instants held exactly in a tower.

A critical instant of a motion (the gathering simulator's ``instants``) is a root of a
polynomial with multiquadratic coefficients.  When that root needs a nested radical (a
quadratic whose discriminant is not a square in any multiquadratic field, or a biquadratic
quartic), it lives in a tower of quadratic extensions over the multiquadratic field
(:mod:`exactsym.exact.tower`, used read-only).  This module is the small adapter the
simulator needs on top of it:

* :class:`TowerNumber` -- a :class:`~exactsym.exact.tower.TowerElement` that offers the
  :class:`~exactsym.exact.multiquadratic.MQ` methods the gathering geometry calls
  (``is_zero``, ``to_fmpq``, ``text``) and keeps its type through arithmetic, so the
  geometry, the pattern recogniser and the robots' decisions run unchanged on points
  whose coordinates are tower numbers (a level-0 result is an ``MQ`` again);
* :func:`quadratic_root` and :func:`biquadratic_root` -- the root of a quadratic (or of
  ``a f^4 + b f^2 + c``) inside a rational interval, as a tower number;
* :func:`tower_sqrt` -- the square root of a tower number.

A root sqrt(m) w whose integer m (more than 160 bits) has a square-free part that
:func:`~exactsym.exact.mq_closure.bounded_squarefree_split` cannot tell (a full
factorisation could take minutes) stays without an exact value (``sided``).

Soundness of the canonical form.  The tower's canonical form (``a + b y`` with ``y^2``
not a square below) makes ``==`` exact only while the radicand of every level is a
non-square in the field below *whatever square roots of rationals appear later* (a
Look builds new ones: layer slots, radial targets).  So a level is added only after
:func:`~exactsym.exact.mq_closure.decided_sqrt` -- which searches the whole
multiquadratic closure, any primes -- proved there is no root: a radicand of level 1 is
then a non-square in every multiquadratic field, and the same check one level down makes
:func:`tower_sqrt` sound for level-1 numbers.  Square roots of numbers of level 2 or more
fall back to the tower's own test over its base primes (never needed by the simulator's
runs so far).

Towers are shared by their first radicand (:func:`tower_of`) within a run (its context,
:mod:`..context`: the levels a run adds to a tower are that run's, never a later run's),
so the same instant computed twice (a Look's I3 and I9 checks, the snapshot cache) gives
equal numbers;
numbers of two different towers are not compared (:meth:`TowerNumber.__eq__`:
it raises ValueError, so a decision that would need it is ``undecided``, never wrong;
callers that must decide equality across towers, :func:`.roots.same_root`, use
the polynomials instead).
"""

from __future__ import annotations

from flint import fmpz

from ..context import Cache
from ..mq_closure import decided_sqrt
from ..multiquadratic import MQ
from ..tower import Tower, TowerElement

__all__ = ["TowerNumber", "tower_of", "quadratic_root", "biquadratic_root", "tower_sqrt",
           "is_tower"]


def is_tower(x) -> bool:
    return isinstance(x, TowerElement)


def _wrap(tower: Tower, v):
    return v if isinstance(v, MQ) else TowerNumber(tower, v)


class TowerNumber(TowerElement):
    """A tower number that answers the MQ methods the gathering code calls and stays a
    :class:`TowerNumber` through arithmetic."""

    __slots__ = ()
    kernel = False          # its decisions keep their exact keys (paper.ratio_keys.big_field)

    def _new(self, v):
        return _wrap(self.tower, v)      # TowerElement's arithmetic keeps this type

    def __abs__(self):
        return -self if self.sign() < 0 else self

    def __eq__(self, other):
        if isinstance(other, TowerElement) and other.tower is not self.tower:
            # canonical forms of two towers are not comparable: equal values may differ
            # in form, so no answer is given (a Look that needs one is "undecided")
            raise ValueError("numbers of two different towers cannot be compared here")
        return TowerElement.__eq__(self, other)

    def __ne__(self, other):
        eq = self.__eq__(other)
        return eq if eq is NotImplemented else not eq

    __hash__ = TowerElement.__hash__

    # -- the MQ methods the gathering code calls ------------------------------------
    def is_zero(self) -> bool:
        return False                     # a number of level >= 1 is never zero

    def to_fmpq(self):
        raise ValueError(f"{self.text()} is not rational")

    def to_arb(self, prec: int = 53):
        """An Arb ball around the value (MQ's name for it: filters and drawing only)."""
        return self.enclosure(prec)

    def __repr__(self):
        return f"TowerNumber({self.text()!r})"


def _primes_of(values) -> list:
    """The primes dividing the radicands of the MQ numbers ``values``."""
    out: set = set()
    for v in values:
        for m in v.radicands():
            out |= {int(p) for p, _ in fmpz(m).factor()}
    return sorted(out)


#: radicand -> its one-level tower, grown in place by later levels: one per run (before, a
#: process-wide lru_cache: a later run got the levels, at most 12, of every earlier one)
_TOWERS = Cache("instant towers", shared_outside=True)


def tower_of(radicand: MQ) -> Tower:
    """A one-level tower ``K_0(sqrt(radicand))``, ``K_0`` the multiquadratic field of the
    radicand's square roots; the same object for the same radicand in a run.  The caller
    has checked that ``radicand > 0`` has no square root in any multiquadratic field."""
    towers = _TOWERS.table()
    tower = towers.get(radicand)
    if tower is None:
        if len(towers) >= 1024:           # a bound on the memory (as the lru_cache was)
            towers.clear()
        tower = towers[radicand] = Tower(_primes_of([radicand]))
        tower.adjoin(radicand)       # proved a non-square by the caller: no second test
    return tower


def _new_root(radicand: MQ) -> TowerNumber:
    tower = tower_of(radicand)
    return TowerNumber(tower, tower.sqrt(radicand))


def mq_sqrt_any(x):
    """The non-negative root of ``x >= 0`` (an MQ or a tower number): in the
    multiquadratic closure when it lies there, else a tower number (a new tower, or a
    new level of ``x``'s tower); None when that cannot be decided (a large rational left
    unfactored on the way: :func:`~exactsym.exact.mq_closure.decided_sqrt`)."""
    if is_tower(x):
        return tower_sqrt(x)
    root, decided = decided_sqrt(x)
    if root is not None or not decided:
        return root
    return _new_root(x)


def tower_sqrt(x: TowerElement):
    """The non-negative square root of the tower number ``x > 0``: an element of its
    tower when it has one there (level 1: searched over the multiquadratic closure, so
    a miss is a true non-square), else the generator of a new level; None when the
    closure search cannot decide."""
    tower = x.tower
    if x.sign() < 0:
        raise ValueError("square root of a negative number")
    v = x.v
    if getattr(tower, "closure_base", False):
        # a run's tower (:mod:`.run_tower`): its own test is complete at every level
        return _wrap(tower, tower.sqrt(v))
    if v[0] == 1:
        a, b = v[1], v[2]
        r = tower.radicands[0]
        n, decided = decided_sqrt(a * a - r * b * b)
        if not decided:
            return None
        if n is not None:
            for t in ((a + n) / 2, (a - n) / 2):
                c, decided = decided_sqrt(t) if t.sign() >= 0 else (None, True)
                if not decided:
                    return None
                if c is not None and not c.is_zero():
                    y = TowerNumber(tower, (1, c, b / (c * 2)))
                    if y * y == x:
                        return y if y.sign() >= 0 else -y
        # no root in any multiquadratic K_0(y): a new level (the tower's own test agrees)
    return _wrap(tower, tower.sqrt(v))


def _in(x, lo, hi) -> bool:
    return (x - lo).sign() > 0 and (x - hi).sign() < 0


def _monic_roots(c, b, a):
    """The real roots of ``a u^2 + b u + c`` (MQ coefficients, a != 0), exact (MQ or tower
    numbers; the discriminant of the monic polynomial: one radicand per root); ``()``
    when there are none, None when the square root cannot be decided."""
    inv = 1 / a                     # one inverse for both (the same values as b / a, c / a)
    bm, cm = b * inv, c * inv
    disc = bm * bm - cm * 4
    if disc.sign() < 0:
        return ()
    y = mq_sqrt_any(disc)
    return None if y is None else ((-bm - y) / 2, (-bm + y) / 2)


def quadratic_root(c, b, a, lo, hi):
    """The root of ``a f^2 + b f + c`` (MQ coefficients, a != 0) in ``(lo, hi)``, exact:
    an MQ when the discriminant is a square there, else a tower number; None when no
    root lies in the interval (or a large rational on the way was left unfactored)."""
    return next((r for r in _monic_roots(c, b, a) or () if _in(r, lo, hi)), None)


def biquadratic_root(p, lo, hi):
    """The root of ``p = c + b f^2 + a f^4`` (odd coefficients zero) in ``(lo, hi)``,
    ``0 <= lo``: ``f = sqrt(u)``, ``u`` a root of ``a u^2 + b u + c``; None otherwise."""
    c, _, b, _, a = p
    for u in _monic_roots(c, b, a) or ():
        f = mq_sqrt_any(u) if u.sign() > 0 else None
        if f is not None and _in(f, lo, hi):
            return f
    return None
