"""Square roots of rationals over the sparse Q(zeta_N): Kummer levels above sparse numbers.

Turns of denominators near 10^6 put the cosines in the sparse Q(zeta_N)
(:mod:`.sparse_cyclotomic`); a radius sqrt(145) there was a Gauss sum of 112 cosines, and
products of such sums grew until two robots ran past 100 s (issue 9).  As over a dense base
(:mod:`.cyclotomic_tower`), the square roots are instead levels of a tower whose base is the
real subfield of Q(zeta_N), decided new by Kummer theory (:mod:`.kummer`), with the tower's
canonical form a + b y per level.  The base numbers are :class:`~.sparse_cyclotomic.
SparseCyclotomic`, whose form is not canonical but whose equality, hash and zero test are
exact, which is all the tower's structural equality and hash ask of its base values.

There is no square-root test in the sparse base.  A nested radical is a new level when
Legendre characters prove its radicand no square of the top field (:mod:`.sparse_nested`):
MakeAsym's radial move (a root of a ratio of squared radii) gets a copy of the tower with
that level (:meth:`SparseKummerTower.extended`); a radicand the characters do not settle
(it may be a square, e.g. a denesting) is refused (FieldTooLargeError, exit 2).  (The
sparse nested reading, not reached from input, extends a tower in place:
tests/reference/sparse_nested_reading.py.)  Above a nested level a rational whose root would
need a new level is refused (rational levels come first, so that
:class:`.kummer.SquareClasses` still indexes them).  A rational whose class needs a Gauss sum of
more than :data:`.sparse_cyclotomic.MAX_GAUSS_TERMS` terms (a prime of N near 10^6) is
refused too.  ``certify`` writes the tower over the sparse base, its levels proved new by
Legendre symbols at primes p = 1 mod N (:func:`.tower_proof.legendre_rank_primes`; the
checker: ``exactsym/checker/tower_sparse.py``).

Public names: :class:`SparseKummerTower`.
"""

from __future__ import annotations

from copy import deepcopy
from fractions import Fraction

from flint import fmpq, fmpz

from ..errors import FieldTooLargeError
from . import sparse_cyclotomic
from .cyclotomic import squarefree_decomposition
from .cyclotomic_tower import CyclotomicTower
from .kummer import SquareClasses
from .multiquadratic import MQ
from .sparse_cyclotomic import SparseCyclotomic
from .sparse_nested import new_level_proved
from .tower import MAX_LEVELS, Tower


class SparseKummerTower(CyclotomicTower):
    """A tower of square roots of rationals over the real subfield of a sparse Q(zeta_N)."""

    def __init__(self, context):
        Tower.__init__(self, ())
        self.context = context
        self.conductor = context.n
        self.zero = SparseCyclotomic(context, {})
        self.one = SparseCyclotomic(context, {0: fmpq(1)})
        self.classes = SquareClasses(self.conductor)
        self.nested = 0             # levels whose radicand is not rational (the last ones)

    @property
    def degree(self) -> int:
        return max(self.context.phi // 2, 1) << self.levels

    def const(self, q):
        return SparseCyclotomic(self.context, {0: fmpq(q)} if q else {})

    def coerce_base(self, other):
        if isinstance(other, SparseCyclotomic):
            return other
        if isinstance(other, MQ) and other.is_rational():
            return self.const(other.to_fmpq())
        if isinstance(other, (int, fmpz, fmpq)):
            return self.const(other)
        if isinstance(other, Fraction):
            return self.const(fmpq(other.numerator, other.denominator))
        return None

    def base_root(self, x):
        raise FieldTooLargeError(f"a nested radical over the sparse Q(zeta_{self.conductor}) "
                                 "(no square-root test there)")

    def base_text(self, v) -> str:
        return v.text()

    def _base_sqrt(self, q: fmpq):
        terms = sparse_cyclotomic.gauss_terms(squarefree_decomposition(q)[1])
        if terms > sparse_cyclotomic.MAX_GAUSS_TERMS:
            raise FieldTooLargeError(
                f"sqrt({q}) would be a sum of {terms} roots of unity in Q(zeta_"
                f"{self.conductor}) (limit {sparse_cyclotomic.MAX_GAUSS_TERMS})")
        return sparse_cyclotomic.sqrt_rational(self.context, q)

    def sqrt(self, x):
        if type(x) is not tuple:
            x = self.coerce_base(x)
            if x is not None and x.is_rational():
                if self.nested and x not in self._roots and \
                        self.classes.express(x.to_fmpq()) is None and x.to_fmpq() > 0:
                    raise FieldTooLargeError(
                        f"sqrt({x.to_fmpq()}) above a nested radical over the sparse "
                        f"Q(zeta_{self.conductor}) (no square-root test there)")
                return self._kummer_sqrt(x)
        return self.base_root(x)

    def extended(self, x) -> "SparseKummerTower":
        """A copy of this tower with one more level, sqrt(x), for a positive raw value x
        that is not rational: Legendre characters prove x no square of the top field
        (:func:`.sparse_nested.new_level_proved`).  The numbers of this tower are numbers
        of the copy (same levels below).  FieldTooLargeError when nothing is proved (x
        may be a square: no root is computed here) or past :data:`.tower.MAX_LEVELS`
        nested levels."""
        copy = SparseKummerTower(self.context)
        copy.radicands = list(self.radicands)
        copy.classes = deepcopy(self.classes)
        copy.nested = self.nested
        copy._roots = dict(self._roots)
        copy._adjoin_proved(x)
        return copy

    def _adjoin_proved(self, x):
        if self.nested >= MAX_LEVELS:
            raise FieldTooLargeError(f"more than {MAX_LEVELS} nested radicals over the "
                                     f"sparse Q(zeta_{self.conductor})")
        if not new_level_proved(self, x):
            raise FieldTooLargeError(
                f"a square root over the sparse Q(zeta_{self.conductor}) that characters do "
                "not prove new (it may lie in the field: no square-root test there)")
        self.radicands.append(x)
        self.nested += 1
        root = self._roots[x] = (self.levels, self.zero, self.one)
        return root

    def _check_new_level(self) -> None:
        raise FieldTooLargeError(f"a nested radical over the sparse Q(zeta_{self.conductor})"
                                 " (no square-root test there)")


__all__ = ["SparseKummerTower"]
