"""From expression trees to exact numbers: choosing the one field a configuration needs.

:func:`number_system` looks at every expression (and every polar turn) of a
configuration once and picks the smallest machinery that holds them all:

1. **Q** when everything is rational (``sqrt(4)``, ``cos(pi/3)`` included):
   numbers are ``fmpq``;
2. **Q(zeta_M)** when the irrational parts are square roots of rationals and
   cosines/sines of rational multiples of pi (:mod:`.cyclotomic`);
3. nested radicals of square roots: a tower of quadratic extensions over the
   multiquadratic field of the square roots, built lazily (:mod:`.tower`);
4. nested radicals mixed with cos/sin: the same tower over the real subfield of Q(zeta_M)
   (:mod:`.cyclotomic_tower`).
5. **sparse Q(zeta_N)** when case 2 would need a dense field above :data:`DENSE_DEGREE`
   (turns j/997, or of denominators near 10^6): sums of roots of unity with an exact zero
   test over N's factorisation (:mod:`.sparse_cyclotomic`); square roots whose Gauss sums
   would be long are then quadratic levels over the cosines' field (:mod:`.kummer`).
(sympy's primitive element is no longer chosen here: tests/reference/general.py keeps it as
a differential oracle, with the sparse nested reading that input does not reach yet.)

Every evaluation error a user can cause (division by zero, the root of a
negative number, a field too large) is an :class:`ExpressionError` carrying the
offending node's offset.
"""

from __future__ import annotations

from contextlib import contextmanager

import sys
from fractions import Fraction
from typing import Iterable, Sequence

from flint import fmpq, fmpz

from ..errors import ExpressionError, FieldTooLargeError
from ..io.exprtree import FieldFold, Fold, Node, fold
from . import cyclotomic
from .field import FieldElement, NumberField, PolyElement, as_fmpq
from .multiquadratic import MQ, sqrt_rational, squarefree_split
from . import sparse_cyclotomic
from .sparse_cyclotomic import SparseCyclotomic


class RationalSystem:
    """The field Q: numbers are ``fmpq``."""

    name = "Q"
    degree = 1
    field = None

    def coerce(self, value):
        return as_fmpq(value)

    def cos_turn(self, turn: fmpq):
        value = rational_cos_turn(turn)
        if value is None:
            raise ValueError(f"cos of {turn} turn is irrational")
        return value

    def sin_turn(self, turn: fmpq):
        return self.cos_turn(fmpq(1, 4) - turn)

    def sqrt(self, q: fmpq):
        root = rational_sqrt(q)
        if root is None:
            raise ValueError(f"sqrt({q}) is irrational")
        return root


class MultiquadraticSystem:
    """Q(sqrt(a1), sqrt(a2), ...): every irrational atom is the square root of a rational.

    Numbers are sparse :class:`~.multiquadratic.MQ` elements (a rational coefficient per
    squarefree radicand): canonical, so equality is exact, and arithmetic costs a few
    operations per term instead of polynomial products modulo a cyclotomic polynomial of
    degree up to thousands (issue 9: three points using sqrt(2), sqrt(3), sqrt(5), sqrt(7)
    took 15 s in Q(zeta_840))."""

    field = None
    atoms: dict = {}     # no nested radicals here

    def __init__(self, radicands):
        base = sorted(set(radicands))
        self.radicands = tuple(base)
        self.degree = 1 << len(base)
        shown = ", ".join(f"sqrt({m})" for m in base[:6]) + (", ..." if len(base) > 6 else "")
        self.name = f"Q({shown})"

    def coerce(self, value):
        return MQ.coerce(as_fmpq(value)) if not isinstance(value, MQ) else value

    def cos_turn(self, turn: fmpq):
        value = rational_cos_turn(turn)
        if value is None:
            raise ValueError(f"cos of {turn} turn is not multiquadratic")
        return MQ.rational(value)

    def sin_turn(self, turn: fmpq):
        return self.cos_turn(fmpq(1, 4) - turn)

    def sqrt(self, q):
        if isinstance(q, MQ):
            q = q.to_fmpq()
        return sqrt_rational(q)


class TowerSystem:
    """Nested radicals of square roots: a :class:`~.tower.Tower` of quadratic extensions over
    the multiquadratic field of the configuration's square roots of rationals, built lazily
    (a level only for a radicand that is not a square in the field below).  Numbers are
    ``MQ`` (level 0) or :class:`~.tower.TowerElement`."""

    field = None
    atoms: dict = {}

    def __init__(self, primes):
        from .tower import Tower
        self.tower = Tower(primes)

    @property
    def name(self) -> str:
        return self.tower.name

    @property
    def degree(self) -> int:
        return self.tower.degree

    def coerce(self, value):
        return value if isinstance(value, FieldElement) else MQ.coerce(as_fmpq(value))

    def cos_turn(self, turn: fmpq):
        value = rational_cos_turn(turn)
        if value is None:
            raise ValueError(f"cos of {turn} turn is not in a tower of square roots")
        return MQ.rational(value)

    def sin_turn(self, turn: fmpq):
        return self.cos_turn(fmpq(1, 4) - turn)

    def sqrt(self, x):
        """The non-negative root of x >= 0 (a rational or a number of this tower)."""
        from .tower import TowerElement, wrap
        raw = x.v if isinstance(x, TowerElement) else self.coerce(x)
        return wrap(self.tower, self.tower.sqrt(raw))


class CyclotomicTowerSystem(TowerSystem):
    """Nested radicals mixed with cos/sin: a :class:`~.cyclotomic_tower.CyclotomicTower` over
    the real subfield of Q(zeta_M).  Numbers are ``MQ`` (rationals) or
    :class:`~.tower.TowerElement` (irrational base elements and the levels above)."""

    def __init__(self, conductor: int, base_checked: bool = True):
        from .cyclotomic_tower import CyclotomicTower, check_base
        if base_checked:
            check_base(conductor)                  # a-priori bound, before anything is built
        self.tower = CyclotomicTower(cyclotomic.cyclotomic_field(conductor))

    def cos_turn(self, turn: fmpq):
        value = rational_cos_turn(turn)
        if value is not None:
            return MQ.rational(value)
        return self.tower.wrap(cyclotomic.cos_turn(self.tower.field, turn))

    def coerce(self, value):
        """Also a number of the base field as ``FieldSystem`` makes it (MakeAsym's radial
        move rewrites a cyclotomic configuration in this tower)."""
        field = self.tower.field
        if isinstance(value, PolyElement) and value.field.conductor == field.conductor:
            # same Q(zeta_M), possibly another NumberField object: same power basis
            return self.tower.wrap(value if value.field is field else
                                   PolyElement(field, value.poly))
        return super().coerce(value)


class SparseCyclotomicSystem:
    """Q(zeta_N) for a conductor whose dense field is too large (issue 9: turns 1/999983 and
    3/999979 need N near 2.6 * 10^14): numbers are
    :class:`~.sparse_cyclotomic.SparseCyclotomic` sums of roots of unity; only cosines, sines
    and square roots of rationals with small Gauss sums (:data:`MAX_GAUSS_TERMS`) are held."""

    field = None
    atoms: dict = {}

    def __init__(self, conductor: int):
        self.context = sparse_cyclotomic.sparse_context(conductor)
        self.conductor = conductor
        self.name = f"Q(zeta_{conductor})"
        self.degree = self.context.phi

    def coerce(self, value):
        if isinstance(value, SparseCyclotomic):
            return value
        one = SparseCyclotomic(self.context, {0: fmpq(1)})
        return one * value if isinstance(value, FieldElement) else one * as_fmpq(value)

    def cos_turn(self, turn: fmpq):
        value = rational_cos_turn(turn)
        if value is not None:
            return self.coerce(value)
        return sparse_cyclotomic.cos_turn(self.context, turn)

    def sin_turn(self, turn: fmpq):
        return self.cos_turn(fmpq(1, 4) - turn)

    def sqrt(self, q: fmpq):
        root = rational_sqrt(q)
        if root is not None:
            return self.coerce(root)
        return sparse_cyclotomic.sqrt_rational(self.context, q)


class SparseKummerSystem(TowerSystem):
    """Cosines in the sparse Q(zeta_N) with square roots of rationals as tower levels above
    them (:class:`~.sparse_tower.SparseKummerTower`), instead of Gauss sums of hundreds of
    roots of unity.  Numbers are ``MQ`` (rationals) or :class:`~.tower.TowerElement`."""

    def __init__(self, conductor: int, tower=None):
        from .sparse_tower import SparseKummerTower
        self.context = sparse_cyclotomic.sparse_context(conductor)
        self.tower = SparseKummerTower(self.context) if tower is None else tower

    def cos_turn(self, turn: fmpq):
        value = rational_cos_turn(turn)
        if value is not None:
            return MQ.rational(value)
        return self.tower.wrap(sparse_cyclotomic.cos_turn(self.context, turn))

    def coerce(self, value):
        from .tower import TowerElement
        if isinstance(value, SparseCyclotomic):
            return self.tower.wrap(value)
        if isinstance(value, TowerElement) and value.tower is not self.tower and \
                getattr(value.tower, "context", None) is self.context and \
                value.tower.radicands == self.tower.radicands[:value.tower.levels]:
            return self.tower.wrap(value.v)     # a number of a tower this one extends
        return super().coerce(value)

    def extended(self, x) -> "SparseKummerSystem":
        """This system with sqrt(x) adjoined as a new level of a copy of its tower
        (:meth:`~.sparse_tower.SparseKummerTower.extended`; FieldTooLargeError when the
        level is not proved new)."""
        from .tower import TowerElement
        raw = x.v if isinstance(x, TowerElement) else self.tower.coerce_base(x)
        return SparseKummerSystem(self.context.n, self.tower.extended(raw))


class FieldSystem:
    """A number field ``field`` with the atoms (square roots, trig values) it holds."""

    def __init__(self, field: NumberField, atoms: dict | None = None):
        self.field = field
        self.name = field.name
        self.degree = field.degree
        self.atoms = atoms or {}

    def coerce(self, value):
        return self.field(value)

    def cos_turn(self, turn: fmpq):
        value = rational_cos_turn(turn)      # cos(pi/3) adds nothing to the conductor
        if value is not None:
            return self.field(value)
        if self.field.conductor is not None:
            return cyclotomic.cos_turn(self.field, turn)
        return self.atoms[("cos", normal_turn(turn))]

    def sin_turn(self, turn: fmpq):
        return self.cos_turn(fmpq(1, 4) - turn)

    def sqrt(self, q: fmpq):
        root = rational_sqrt(q)
        if root is not None:
            return self.field(root)
        if self.field.conductor is not None:
            return cyclotomic.sqrt_element(self.field, q)
        return self.atoms[("sqrt", q)]


def normal_turn(turn: fmpq) -> fmpq:
    """The turn reduced to [0, 1)."""
    return turn - (turn.p // turn.q)


def rational_cos_turn(turn: fmpq) -> fmpq | None:
    """``cos(2 pi turn)`` when it is rational (denominators 1, 2, 3, 4, 6), else None."""
    t = normal_turn(turn)
    table = {fmpq(0): fmpq(1), fmpq(1, 2): fmpq(-1), fmpq(1, 4): fmpq(0), fmpq(3, 4): fmpq(0),
             fmpq(1, 3): fmpq(-1, 2), fmpq(2, 3): fmpq(-1, 2), fmpq(1, 6): fmpq(1, 2),
             fmpq(5, 6): fmpq(1, 2)}
    return table.get(t)


def rational_sqrt(q: fmpq) -> fmpq | None:
    """The rational square root of ``q >= 0``, or None when it is irrational."""
    p, d = q.p.isqrt(), q.q.isqrt()
    if p * p == q.p and d * d == q.q:
        return fmpq(p, d)
    return None


# ---------------------------------------------------------------- atom collection
def _collect(node: Node, atoms: list) -> None:
    """Append the irrational atoms of ``node``: ("sqrt", q), ("cos", turn), ("nested",
    Sqrt node), left to right, a nested radical after the atoms of its radicand; raise
    the first error found on the way (:class:`_Atoms`)."""
    found, error = fold(node, _ATOMS)
    if error is not None:
        raise error
    if found:
        atoms.extend(found)


#: a node without atoms or errors
_NOTHING = (None, None)


class _Atoms(Fold):
    """``(atoms, error)`` of a node, for :func:`_collect`: its irrational atoms (a list, or
    None for none) and the first error of the collection (or None).  A square root reads
    its radicand in Q (:class:`RationalSystem`): an error of that reading is the error
    (before any error inside the radicand); an irrational radicand is a nested radical,
    whose own atoms and error count; a rational one is an atom when it is no square.
    Errors are carried up, not raised, so that the first in that order (left before right)
    is the one :func:`_collect` raises."""

    __slots__ = ()

    def const(self, node):
        return _NOTHING

    def neg(self, node, arg):
        return arg

    def power(self, node, base):
        return base

    def binop(self, node, left, right):
        atoms, error = left
        if error is not None or right is _NOTHING:
            return left
        if atoms is None:
            return right
        if right[0]:
            atoms.extend(right[0])         # left's list: made below this node, used once
        return atoms, right[1]

    def trig(self, node):
        turn = fmpq(1, 4) - as_fmpq(node.pi_multiple) / 2 if node.func == "sin" \
            else as_fmpq(node.pi_multiple) / 2
        if rational_cos_turn(turn) is None:
            return [("cos", normal_turn(turn), node.func)], None
        return _NOTHING

    def sqrt(self, node, arg):
        try:
            q = _evaluate(node.arg, RationalSystem())
        except ValueError:                 # an irrational atom: a nested radical
            atoms, error = arg
            if error is not None:
                return arg
            atoms = atoms if atoms is not None else []
            atoms.append(("nested", node))
            return atoms, None
        except ExpressionError as err:
            return None, err
        if q < 0:
            return None, ExpressionError("square root of a negative number", offset=node.offset)
        return ([("sqrt", q)], None) if rational_sqrt(q) is None else _NOTHING

    def unknown(self, node):  # pragma: no cover - the parser makes no other nodes
        return None, ExpressionError(f"unknown expression node {type(node).__name__}",
                                     offset=node.offset)


_ATOMS = _Atoms()


# ---------------------------------------------------------------- evaluation
#: Bound on the size of a power's result, so that ``(2^10000)^10000`` is an error, not a hang.
MAX_POWER_BITS = 1_000_000


def _height_bits(x) -> int:
    """Bits of the largest numerator or denominator in ``x`` (a rational or field element)."""
    if isinstance(x, (MQ, SparseCyclotomic)) or hasattr(x, "tower"):
        from .tower import height_bits
        return height_bits(x if isinstance(x, (MQ, SparseCyclotomic)) else x.v)
    if isinstance(x, FieldElement):
        coeffs = x.poly.coeffs() or [fmpq(0)]
        return max(int(c.p).bit_length() + int(c.q).bit_length() for c in coeffs)
    x = as_fmpq(x)
    return int(x.p).bit_length() + int(x.q).bit_length()


class _DeepTrees:
    """Expression trees may be thousands of levels deep (a long flat sum is a left-deep
    tree): raise the recursion limit while walking them.  Python 3.11 runs
    Python-to-Python calls without growing the C stack, so this is safe."""

    LIMIT = 40_000

    def __enter__(self):
        self.saved = sys.getrecursionlimit()
        sys.setrecursionlimit(max(self.saved, self.LIMIT))

    def __exit__(self, *exc):
        sys.setrecursionlimit(self.saved)


class _Evaluation(FieldFold):
    """Exact values in ``system`` (RationalSystem raises ValueError on irrational atoms);
    every error a user can cause an :class:`ExpressionError` at the node's offset."""

    __slots__ = ("system",)

    def __init__(self, system):
        self.system = system

    def const(self, node):
        return self.system.coerce(node.value)

    def zero_division(self, node):
        return ExpressionError("division by zero", offset=node.offset)

    def power(self, node, base):
        if node.exponent < 0 and base == 0:
            raise ExpressionError("division by zero (zero to a negative power)", offset=node.offset)
        if _height_bits(base) * abs(node.exponent) > MAX_POWER_BITS:
            raise ExpressionError(f"power too large: the result would need more than "
                                  f"{MAX_POWER_BITS} bits", offset=node.offset)
        return base ** node.exponent

    def trig(self, node):
        turn = as_fmpq(node.pi_multiple) / 2
        system = self.system
        return system.cos_turn(turn) if node.func == "cos" else system.sin_turn(turn)

    def sqrt(self, node, arg):
        system = self.system
        if isinstance(system, TowerSystem):
            if arg < 0:
                raise ExpressionError("square root of a negative number", offset=node.offset)
            return system.sqrt(arg)
        if isinstance(arg, FieldElement) and (not arg.is_rational()
                                              or ("nested", node) in system.atoms):
            if arg.sign() < 0:
                raise ExpressionError("square root of a negative number", offset=node.offset)
            return system.atoms[("nested", node)]
        arg = arg.to_fmpq() if isinstance(arg, FieldElement) else arg
        if arg < 0:
            raise ExpressionError("square root of a negative number", offset=node.offset)
        return system.sqrt(arg)

    def unknown(self, node):
        raise ExpressionError(f"unknown expression node {type(node).__name__}",
                              offset=node.offset)


def _evaluate(node: Node, system):
    """Evaluate ``node`` in ``system`` (RationalSystem raises ValueError on irrational atoms)."""
    return fold(node, _Evaluation(system))


#: the largest phi(M) of a dense Q(zeta_M); cos/sin needing a larger one are sparse sums in
#: Q(zeta_N) (:mod:`.sparse_cyclotomic`).  Measured (bench/bench_small_algebraic.py): at
#: degree 960 and 1,992 the sparse field is as fast or faster (three robots at turns j/997
#: off-centre: 24 s dense, one division of the moved SEC centre costing seconds; 0.7 s
#: sparse), and no input of the benchmark is slower
DENSE_DEGREE = 256

#: the dense limit while :func:`dense_degree_limit` is active (the innermost block's)
_DENSE_LIMITS: list = []


@contextmanager
def dense_degree_limit(degree: int):
    """Within the block, cos/sin are read in a dense Q(zeta_M) up to phi(M) = ``degree``
    (at most :data:`.cyclotomic.MAX_DEGREE`) instead of :data:`DENSE_DEGREE`, and in the
    sparse Q(zeta_N) beyond: ``exactsym certify`` asks for 64, because the standard-library
    checker multiplies dense numbers of degree hundreds term by term, while the sparse
    certificate's numbers keep a few terms; tests ask for more to reach the dense field."""
    _DENSE_LIMITS.append(degree)
    try:
        yield
    finally:
        _DENSE_LIMITS.pop()


def number_system(exprs: Iterable[Node], turns: Iterable[fmpq] = ()):
    """The smallest number system holding every expression and cos/sin of every turn.

    Raises :class:`ExpressionError` (with the node's offset; the caller adds the
    file location) for a root of a negative rational, and
    :class:`FieldTooLargeError` when the numbers need too large a field.
    """
    with _DeepTrees():
        return _number_system(exprs, turns)


def _number_system(exprs: Iterable[Node], turns: Iterable[fmpq]):
    atoms: list = []
    for index, expr in enumerate(exprs):
        try:
            _collect(expr, atoms)
        except ExpressionError as err:
            err.index = index      # which expression: the caller knows its file location
            raise
    for turn in turns:
        for t in (normal_turn(as_fmpq(turn)), normal_turn(fmpq(1, 4) - as_fmpq(turn))):
            if rational_cos_turn(t) is None:
                atoms.append(("cos", t, "cos"))
    if not atoms:
        return RationalSystem()
    if all(kind == "sqrt" for kind, *_ in atoms):
        return MultiquadraticSystem(squarefree_split(int(q.p) * int(q.q))[1] for _, q in atoms)
    if all(kind != "nested" for kind, *_ in atoms):
        # sines are cosines of 1/4 - t, already in the list; i needs 4 | M for them
        conductor = cyclotomic.lcm(_conductor(atoms), 4)
        degree = cyclotomic.euler_phi(conductor)
        limit = min(cyclotomic.MAX_DEGREE, _DENSE_LIMITS[-1]) if _DENSE_LIMITS else DENSE_DEGREE
        if degree <= limit:
            return FieldSystem(cyclotomic.cyclotomic_field(conductor))
        if any(atom[0] == "cos" for atom in atoms):
            # the square roots' Gauss sums take the field beyond the dense limit: the
            # cosines alone fit a dense Q(zeta_M)? then the roots are levels over it
            cosines = _cosine_conductor(atoms)
            phi = cyclotomic.euler_phi(cosines)
            if cosines != conductor and phi <= limit:
                return _kummer_system(cosines, phi)
            return _sparse_system(atoms, conductor)
    if all(kind != "cos" for kind, *_ in atoms):   # nested radicals of square roots only
        primes: set = set()
        for atom in atoms:
            if atom[0] == "sqrt":
                m = squarefree_split(int(atom[1].p) * int(atom[1].q))[1]
                primes.update(int(p) for p, _ in fmpz(m).factor())
        _check_tower_levels(atoms, primes)
        return TowerSystem(primes)
    return _mixed_system(atoms)


def _check_tower_levels(atoms, primes) -> None:
    """FieldTooLargeError before anything is built when the radicands of depth 2 (square
    roots of sums of square roots of rationals) are proved to need more than
    ``tower.MAX_LEVELS`` quadratic levels: that many of them independent modulo squares
    of the multiquadratic base (:func:`.modular.square_class_rank`, F_p characters).
    (Else the tower refuses the level beyond the bound when it would build it, after the
    square-root tests of the levels below: a minute for twelve.)"""
    from .tower import MAX_LEVELS
    from .modular import square_class_rank
    base = MultiquadraticSystem(primes)
    values: list = []
    for atom in atoms:
        if atom[0] != "nested":
            continue
        inner: list = []
        _collect(atom[1].arg, inner)
        if any(kind != "sqrt" for kind, *_ in inner):
            continue                       # deeper: decided by the tower itself
        value = evaluate(atom[1].arg, base)
        if isinstance(value, MQ) and value.sign() > 0 and value not in values:
            values.append(value)
    if len(values) > MAX_LEVELS and \
            square_class_rank(sorted(primes), values) > MAX_LEVELS:
        raise FieldTooLargeError(f"these nested radicals need more than {MAX_LEVELS} "
                                 "quadratic extensions above the square roots")


#: a square root whose Gauss sum has more terms is a tower level over the sparse Q(zeta_N)
#: (:class:`SparseKummerSystem`); smaller ones (sqrt(2): 2 terms, sqrt(3): 2) stay Gauss sums
SPARSE_GAUSS_LEVEL = 32


def _sparse_system(atoms, conductor: int):
    """The sparse Q(zeta_N) for cos/sin beyond the dense limit, square roots held as Gauss
    sums of at most :data:`SPARSE_GAUSS_LEVEL` terms; with a longer one, the tower of square
    roots over the cosines' sparse field instead (which refuses a Gauss sum beyond
    :data:`.sparse_cyclotomic.MAX_GAUSS_TERMS` when the input needs one)."""
    if any(atom[0] == "sqrt" and sparse_cyclotomic.gauss_terms(
            cyclotomic.squarefree_decomposition(atom[1])[1]) > SPARSE_GAUSS_LEVEL
           for atom in atoms):
        return SparseKummerSystem(_cosine_conductor(atoms))
    return SparseCyclotomicSystem(conductor)


#: largest phi(M) of a dense base under square-root levels; beyond it the sparse base
KUMMER_DENSE_DEGREE = 256


def _kummer_system(conductor: int, degree: int):
    """Square roots of rationals whose Gauss sums would take the field beyond the dense limit
    (``sqrt(145)`` with turns j/997: Q(zeta_578260)) while the cosines alone fit Q(zeta_M)
    (``conductor``, of degree ``degree``): a tower over Q(zeta_M) whose levels are the square
    roots (:mod:`.kummer` decides which are new)."""
    if degree > KUMMER_DENSE_DEGREE:
        # over Q(zeta_3988) the paper layer's divisions (a moved configuration's SEC
        # centre) cost seconds each in the dense field, microseconds as sparse quotients
        return SparseKummerSystem(conductor)
    return CyclotomicTowerSystem(conductor, base_checked=False)


def _cosine_conductor(atoms) -> int:
    """The least M divisible by 4 with Q(zeta_M) holding the cosines among the atoms."""
    conductor = 4
    for atom in atoms:
        if atom[0] == "cos":
            conductor = cyclotomic.lcm(conductor, cyclotomic.turn_conductor(atom[1], "cos"))
    return conductor


def _mixed_system(atoms):
    """Nested radicals mixed with cos/sin: a tower over the dense Q(zeta_M), refused beyond
    :data:`.cyclotomic_tower.MAX_BASE_DEGREE` (tests swap in the former path, sympy's
    primitive element, and the sparse nested reading, both in tests/reference/, for
    differential tests)."""
    return CyclotomicTowerSystem(cyclotomic.lcm(_conductor(atoms), 4))


def _conductor(atoms) -> int:
    """The least M with Q(zeta_M) holding the cosines and square roots of rationals among
    the atoms (nested radicals are not counted: a tower holds them)."""
    conductor = 1
    for atom in atoms:
        if atom[0] == "cos":
            conductor = cyclotomic.lcm(conductor, cyclotomic.turn_conductor(atom[1], "cos"))
        elif atom[0] == "sqrt":
            conductor = cyclotomic.lcm(conductor, cyclotomic.sqrt_conductor(
                cyclotomic.squarefree_decomposition(atom[1])[1]))
    return conductor


def evaluate(node: Node, system):
    """The exact value of ``node`` in a system from :func:`number_system` covering it."""
    with _DeepTrees():
        return _evaluate(node, system)


def evaluate_all(exprs: Sequence[Node], turns: Sequence[fmpq] = ()):
    """``(system, values)``: one number system for all ``exprs`` and their exact values."""
    system = number_system(exprs, turns)
    with _DeepTrees():
        return system, [_evaluate(expr, system) for expr in exprs]


__all__ = ["RationalSystem", "MultiquadraticSystem", "TowerSystem", "CyclotomicTowerSystem",
           "SparseCyclotomicSystem", "SparseKummerSystem",
           "FieldSystem", "number_system", "evaluate", "evaluate_all",
           "rational_cos_turn", "rational_sqrt", "normal_turn", "Fraction"]
