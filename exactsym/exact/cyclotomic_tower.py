"""Nested radicals mixed with cos/sin: a tower of quadratic extensions over Q(zeta_M) (issue 9).

The base K_0 is the real subfield of the cyclotomic field Q(zeta_M) whose conductor M holds every
cosine, sine and square root of a rational of the configuration (elements are
:class:`~.field.PolyElement` of :func:`~.cyclotomic.cyclotomic_field`, as ``FieldSystem`` makes
them); above it K_i = K_(i-1)(y_i), y_i = sqrt(r_i) > 0, is added only when r_i is not a square
in K_(i-1), exactly as in :mod:`.tower` (same canonical form, same recursion for the
square-root test).  The base case of that recursion is :func:`.cyclotomic_sqrt.field_sqrt`,
exact and complete.  A positive real a of K_0 that is a square in Q(zeta_M) has a real root
(z^2 = a > 0 rules out z imaginary), so the test in Q(zeta_M) is the test in K_0.

Why not sympy's primitive element: ``sqrt(1+sqrt(2))`` with ``cos(2*pi/13)`` needed a field of
degree 48 built in 12 s whose minimal polynomial no prime keeps irreducible (so it could not be
certified); here the base is built in microseconds and each level is proved by a prime.

Limits (decided before expensive work): phi(M) <= :data:`MAX_BASE_DEGREE` from the conductor,
before anything is built; phi(M) * 2^L <= :data:`MAX_DEGREE` checked before level L is added.

Public names: :class:`CyclotomicTower`, :data:`MAX_BASE_DEGREE`, :data:`MAX_DEGREE`.
"""

from __future__ import annotations

from fractions import Fraction

from flint import fmpq, fmpz

from ..errors import FieldTooLargeError
from . import cyclotomic
from .cyclotomic_sqrt import field_sqrt
from .field import NumberField, PolyElement
from .kummer import SquareClasses
from .multiquadratic import MQ
from .text import number_text
from .tower import MAX_LEVELS, Tower, TowerElement

#: largest phi(M) of the base Q(zeta_M).  Its square-root test refutes a non-square modulo
#: primes in milliseconds; a square (a denesting) factors a norm of degree 2 phi(M): about
#: 0.05 s at phi = 48, 3 s at 144, 11 s at 208 (this machine).
MAX_BASE_DEGREE = 192
#: largest phi(M) * 2^L (L quadratic levels above the base)
MAX_DEGREE = 4096
#: most levels that are square roots of rationals (:mod:`.kummer`: no recursive test, so
#: neither bound above applies to them)
MAX_RATIONAL_LEVELS = 256


def check_base(conductor: int) -> None:
    """Raise FieldTooLargeError when Q(zeta_conductor) is beyond :data:`MAX_BASE_DEGREE`."""
    degree = cyclotomic.euler_phi(conductor)
    if degree > MAX_BASE_DEGREE:
        raise FieldTooLargeError(
            f"these nested radicals with cos/sin need Q(zeta_{conductor}) of degree {degree} "
            f"as the base of a tower, above the limit {MAX_BASE_DEGREE}")


class CyclotomicTower(Tower):
    """A :class:`~.tower.Tower` whose base values are real elements of Q(zeta_M)."""

    def __init__(self, field: NumberField):
        super().__init__(())
        self.field = field
        self.conductor = field.conductor
        self.zero = field(0)
        self.one = field(1)
        # while every level is the root of a rational, squares of rationals are decided by
        # Kummer theory (:mod:`.kummer`), without the recursive test
        self.classes = SquareClasses(self.conductor) if self.conductor % 4 == 0 else None

    @property
    def degree(self) -> int:
        """[K_L : Q]: the real subfield of Q(zeta_M) has degree phi(M)/2 (M > 2)."""
        return max(self.field.degree // 2, 1) << self.levels

    @property
    def name(self) -> str:
        # one group of parentheses, Q(cos(2*pi/M), sqrt(r_1), ...): the field generated
        gens = [f"cos(2*pi/{self.conductor})"] + [f"sqrt({self.text_of(r)})"
                                                  for r in self.radicands]
        name = f"Q({', '.join(gens)})"
        return name if len(name) <= 200 else \
            f"Q(cos(2*pi/{self.conductor})) with {self.levels} quadratic levels"

    def text_of(self, v) -> str:
        from .tower import text
        return text(self, v)

    # -- the base ---------------------------------------------------------------
    def const(self, q):
        return self.field(q)

    def coerce_base(self, other):
        if isinstance(other, PolyElement):
            return self.field(other)            # the field itself or a cyclotomic subfield
        if isinstance(other, MQ):
            return self.field(other.to_fmpq()) if other.is_rational() else self.field(other)
        if isinstance(other, (int, fmpz, fmpq, Fraction)):
            return self.field(other)
        return None

    def wrap(self, v):
        if type(v) is not tuple and v.is_rational():
            return MQ.rational(v.to_fmpq())    # rationals are MQ: keys and hashes as rationals
        return TowerElement(self, v)

    def base_root(self, x):
        return field_sqrt(self.field, x)

    def base_text(self, v) -> str:
        return number_text(v)

    mul = Tower._mul        # fmpq_poly keeps one denominator: no scaling needed

    def sqrt(self, x):
        if type(x) is not tuple:
            x = self.coerce_base(x)
            if self.classes is not None and x.is_rational():
                return self._kummer_sqrt(x)
        if self.levels > MAX_LEVELS or self.field.degree > MAX_BASE_DEGREE:
            # the complete test branches 2^levels times and factors norms of degree 2 phi(M)
            raise FieldTooLargeError(
                f"a nested radical over Q(zeta_{self.conductor}) (phi = {self.field.degree})"
                f" with {self.levels} quadratic levels is beyond the limits (base degree "
                f"{MAX_BASE_DEGREE}, {MAX_LEVELS} levels)")
        self.classes = None           # a level from here on may hold new roots of rationals
        return super().sqrt(x)

    def _kummer_sqrt(self, x):
        """The root of a rational x >= 0 in the top field, or the generator of a new level:
        decided by :class:`.kummer.SquareClasses` while every level is a rational's root."""
        root = self._roots.get(x)
        if root is not None:
            return root
        q = x.to_fmpq()
        if q <= 0:
            if q < 0:
                raise ValueError("the square root of a negative number")
            return self.zero
        levels = self.classes.express(q)
        if levels is None:
            if self.levels >= MAX_RATIONAL_LEVELS:
                raise FieldTooLargeError(
                    f"these square roots need more than {MAX_RATIONAL_LEVELS} quadratic "
                    f"extensions of Q(zeta_{self.conductor})")
            self.classes.add(q)
            self.radicands.append(x)
            root = (self.levels, self.zero, self.one)
        else:
            rest = q
            for i in levels:
                rest /= self.radicands[i].to_fmpq()
            root = self._base_sqrt(rest)                          # every factor positive
            for i in levels:
                root = self.mul(root, (i + 1, self.zero, self.one))
        self._roots[x] = root
        return root

    def _base_sqrt(self, q: fmpq):
        """The root in the base of a positive rational whose class holds only base
        primes (a Gauss sum)."""
        return cyclotomic.sqrt_element(self.field, q)

    def _rational_sqrt(self, x):
        if type(x) is tuple or not x.is_rational():
            return None
        q = x.to_fmpq()
        if q < 0:
            return None
        if q == 0:
            return self.zero
        _, s = cyclotomic.squarefree_decomposition(q)
        if self.conductor % cyclotomic.sqrt_conductor(s) == 0:
            return cyclotomic.sqrt_element(self.field, q)    # a Gauss sum: no test needed
        return None                                  # the complete test decides

    def _check_new_level(self) -> None:
        if self.levels >= MAX_LEVELS or self.field.degree << (self.levels + 1) > MAX_DEGREE:
            raise FieldTooLargeError(
                f"these nested radicals need a tower of degree above {MAX_DEGREE} over "
                f"Q(zeta_{self.conductor}) (phi = {self.field.degree}) times 2^levels")


__all__ = ["CyclotomicTower", "MAX_BASE_DEGREE", "MAX_DEGREE", "check_base"]
