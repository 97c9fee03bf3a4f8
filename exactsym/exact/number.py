"""The declared interface of the number layer (issue 29): what an exact number and a number
system offer, and the questions the layers above ask about a number.

Every exact number of exactsym is a python-flint ``fmpq`` (the rationals) or an element
of one of the kinds below it (:class:`ExactNumber`: ``MQ``, ``PolyElement``,
``SparseCyclotomic``, ``TowerElement``, the lazy level radii, and the motion's numbers of
exact/algebraic/: ``TowerNumber``, ``AlgebraicNumber``, ``AlgebraicTowerNumber``).  ``fmpq``
is a C type that cannot carry methods, so the questions are functions here that take
either (:func:`sign`, :func:`rational_value`, :func:`enclosure`); the
layers above (geometry/, truth/, paper/) ask them instead of testing classes.  Which kind
holds a configuration's numbers is decided once, by :func:`.evaluate.number_system` (as
sympy's ``construct_domain`` does); how costly a kind's arithmetic is, and therefore which
algorithm suits it (undivided quotients, lazy radii, short texts), is decided here, by the
thresholds below, and nowhere else.
"""

from __future__ import annotations

from typing import Protocol, runtime_checkable

from flint import arb, fmpq

from .field import FieldElement, PolyElement, sign
from .sparse_cyclotomic import SparseCyclotomic
from .tower import TowerElement

#: from this degree a dense field is large: a product costs milliseconds and an inverse a
#: tenth of a second to seconds (issue 9), so lines keep their slopes undivided, levels
#: their radii lazy, keys and texts their quotients homogeneous
LARGE_DEGREE = 512
#: polynomial fields from this degree get ratio keys: all of them, since an inverse is
#: slow at degree thousands and also at degree 4 with coefficients of thousands of digits
#: (a pentagon moved by 10^-1000: fmpq_poly.xgcd, 0.6 s per squared length)
RATIO_KEY_DEGREE = 2


@runtime_checkable
class ExactNumber(Protocol):
    """What every exact number other than ``fmpq`` offers: field arithmetic with ``int``
    and ``fmpq`` operands (``+ - * /``, ``**`` by an integer), exact comparisons and ``==``,
    ``hash`` and the methods below.  Every answer is exact; an enclosure only filters."""

    def sign(self) -> int:
        """-1, 0 or 1, exactly."""

    def is_zero(self) -> bool:
        """Whether the number is 0 (decided exactly)."""

    def is_rational(self) -> bool:
        """Whether the number is rational (decided exactly)."""

    def to_fmpq(self) -> fmpq:
        """The number as an ``fmpq`` (``ValueError`` when it is not rational)."""

    def enclosure(self, prec: int = 53) -> arb:
        """An Arb ball around the value at about ``prec`` bits."""

    def text(self) -> str:
        """The configuration-syntax text, which parses back to the same number."""


class NumberSystem(Protocol):
    """What :func:`.evaluate.number_system` returns and :func:`.evaluate.evaluate` uses:
    the numbers of the atoms of an expression, in one representation."""

    def coerce(self, value):
        """A rational (``int``, ``fmpq``) as a number of the system."""

    def cos_turn(self, turn: fmpq):
        """cos(2 pi turn) for a rational ``turn``."""

    def sin_turn(self, turn: fmpq):
        """sin(2 pi turn) for a rational ``turn``."""

    def sqrt(self, x):
        """The non-negative square root of ``x >= 0`` (a rational, or a number of the
        system where it nests radicals)."""


# -- what a number is ---------------------------------------------------------------

def is_algebraic(x) -> bool:
    """Whether ``x`` is held as an element of a number field (an :class:`ExactNumber`;
    it may still be rational), not as a plain rational."""
    return isinstance(x, FieldElement)


def is_number(x) -> bool:
    """Whether ``x`` is an exact number of the kernel: an ``fmpq`` or an
    :class:`ExactNumber` (not an ``int``, a tuple, a key)."""
    return isinstance(x, (fmpq, FieldElement))


def is_plain_rational(x) -> bool:
    """Whether ``x`` is held as an ``fmpq``: the cheap exact arithmetic of Q, floats
    convertible once for filters."""
    return isinstance(x, fmpq)


def all_plain_rational(values) -> bool:
    """Whether every one of ``values`` is held as an ``fmpq``."""
    return all(isinstance(x, fmpq) for x in values)


def any_algebraic(values) -> bool:
    """Whether one of ``values`` is held as an element of a number field."""
    return any(isinstance(x, FieldElement) for x in values)


def enclosure(x, prec: int = 53) -> arb:
    """An Arb ball around any exact number: the number's own at ``prec`` bits, a
    rational's at the context's precision."""
    return x.enclosure(prec) if isinstance(x, FieldElement) else arb(x)


def rational_value(x):
    """``x`` as an ``fmpq`` when it is rational (decided exactly), else None."""
    if isinstance(x, FieldElement):
        return x.to_fmpq() if x.is_rational() else None
    return fmpq(x)


def reduced(x):
    """``x`` as the rational it is when a sparse cyclotomic quotient is one
    (:meth:`.sparse_cyclotomic.SparseCyclotomic.reduced`), else ``x`` itself."""
    return x.reduced() if isinstance(x, SparseCyclotomic) else x


def is_sparse(x) -> bool:
    """Whether ``x`` is a number of a sparse Q(zeta_N) (held as a quotient of sums of
    cosines, no canonical form)."""
    return isinstance(x, SparseCyclotomic)


def tower_of(x):
    """The tower of nested radicals ``x`` lies in, or None."""
    return x.tower if isinstance(x, TowerElement) else None


def dense_field(x):
    """The dense polynomial field (:class:`.field.NumberField`) of ``x``, or None."""
    return x.field if isinstance(x, PolyElement) else None


# -- how costly its arithmetic is: which algorithm suits it -------------------------

def shares_inverse(d) -> bool:
    """Whether quotients by ``d`` are best made as one inverse shared by their readers: a
    dense field or tower element (a sparse quotient divides for free, a multiquadratic
    number term by term)."""
    return isinstance(d, (PolyElement, TowerElement))


def costly_inverse(d) -> bool:
    """Whether an inverse of the irrational ``d`` costs more than guessing a rational
    quotient from balls and proving it: any kind but the multiquadratic one."""
    return isinstance(d, (PolyElement, TowerElement, SparseCyclotomic)) and not d.is_rational()


def large_dense(x) -> bool:
    """Whether ``x`` lies in a dense field of degree >= :data:`LARGE_DEGREE`."""
    return isinstance(x, PolyElement) and x.field.degree >= LARGE_DEGREE


def short_texts(d) -> bool:
    """Whether texts about quotients by ``d`` are written homogeneous: a dense field of
    degree >= :data:`LARGE_DEGREE`, or a tower of square roots of that degree over such a
    field or over the sparse Q(zeta_N).  In the sparse Q(zeta_N) itself a number is held
    as such a quotient anyway."""
    if isinstance(d, PolyElement):
        return d.field.degree >= LARGE_DEGREE
    return isinstance(d, TowerElement) and d.tower.degree >= LARGE_DEGREE


def cheap_products(numbers) -> bool:
    """Whether products of ``numbers`` are fast: none is sparse (a product convolves sums
    of cosines) or a nested radical (a product in a tower over the sparse Q(zeta_N) costs a
    tenth of a second to seconds)."""
    return not any(isinstance(c, (SparseCyclotomic, TowerElement)) for c in numbers)


def kummer_tower(x) -> bool:
    """Whether ``x`` lies in a tower of square roots of rationals (exact/kummer.py) of
    degree >= :data:`LARGE_DEGREE` over a cyclotomic base."""
    if not (isinstance(x, TowerElement) and x.kernel):
        return False
    tower = x.tower
    return getattr(tower, "classes", None) is not None and tower.levels > 0 and \
        tower.degree >= LARGE_DEGREE


def slow_quotient(*numbers) -> bool:
    """Whether one of ``numbers`` lies in a dense field of degree >= :data:`LARGE_DEGREE`
    or in a :func:`kummer_tower`: there a slope's division costs seconds or grows its
    quotient's sums without bound."""
    return any(getattr(getattr(x, "field", None), "degree", 0) >= LARGE_DEGREE or
               kummer_tower(x) for x in numbers)


def huge_field(*numbers) -> bool:
    """Whether a number lies where a :func:`slow_quotient` does, in a sparse Q(zeta_N) or
    in a tower of nested radicals (not the gathering simulator's subclass): there keys
    are read from balls and F_p images, and exact products made only for equalities."""
    return slow_quotient(*numbers) or any(
        isinstance(v, SparseCyclotomic) or isinstance(v, TowerElement) and v.kernel
        for v in numbers)


def general_field(*numbers) -> bool:
    """Whether one of ``numbers`` is an element of a number field given by its minimal
    polynomial and not cyclotomic (the gathering simulator's Q(gamma) of a K(alpha)
    snapshot, :mod:`exactsym.gathering.algebraic_kernel`): decided by type, so that every
    number of one such configuration answers alike.  Its coefficients can have thousands
    of digits, where an inverse (an xgcd over Q) costs seconds."""
    return any(isinstance(x, PolyElement) and x.field.conductor is None for x in numbers)


def big_field(*numbers) -> bool:
    """Whether one of ``numbers`` lies in a polynomial field of degree >=
    :data:`RATIO_KEY_DEGREE`, in a sparse Q(zeta_N) (products convolve sums of hundreds of
    cosines) or in a tower of nested radicals (an inverse there is a chain of conjugate
    products down the levels): quotients are then keyed undivided.  (Not the gathering
    simulator's tower numbers, a subclass: its decisions keep their keys.)"""
    return any(isinstance(x, SparseCyclotomic) or isinstance(x, TowerElement) and x.kernel or
               isinstance(x, PolyElement) and x.field.degree >= RATIO_KEY_DEGREE
               for x in numbers)


def largest_field(numbers):
    """The field a product of ``numbers`` lands in: the largest of their polynomial fields
    (the smaller ones embed into it); a sparse Q(zeta_N) is larger than any (its context:
    one per N), and so is a tower."""
    best = None
    for x in numbers:
        if isinstance(x, SparseCyclotomic):
            return x.ctx
        if isinstance(x, TowerElement):
            return x.tower
        if isinstance(x, PolyElement) and (best is None or x.field.degree > best.degree):
            best = x.field
    return best


__all__ = ["LARGE_DEGREE", "RATIO_KEY_DEGREE", "ExactNumber", "NumberSystem",
           "is_algebraic", "is_number", "is_plain_rational", "all_plain_rational", "any_algebraic", "sign",
           "enclosure", "rational_value", "reduced", "is_sparse", "tower_of", "dense_field",
           "shares_inverse", "costly_inverse", "large_dense", "short_texts",
           "cheap_products", "kummer_tower", "slow_quotient", "huge_field", "general_field", "big_field",
           "largest_field"]
