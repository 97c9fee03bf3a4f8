"""A start's coordinates as numbers of the motion: every input ``check`` accepts, in bounds.

The configuration reader (:mod:`exactsym.io.fileformat`) gives each coordinate as an
expression tree (:mod:`exactsym.io.exprtree`) and each polar point as a radius tree and a
rational turn.  :func:`start_points` folds them (:func:`~exactsym.io.exprtree.fold`, never
an evaluation of text) into the one number system the run's motion works in
(:mod:`exactsym.exact.algebraic.interface`), chosen once for the whole start:

* **multiquadratic** -- rationals, square roots of rationals and their denestable
  combinations (``sqrt(3 + 2*sqrt(2))``), cos/sin of turns j/24 and its divisors: MQ
  numbers (the default of every run);
* **nested** -- nested radicals (``sqrt(2 + sqrt(3))``) and cos/sin of turns whose
  real cyclotomic field is a 2-group extension (j/5, j/16, j/20, j/40, ...): numbers of
  one :class:`~exactsym.exact.algebraic.run_tower.RunTower`, the run's own tower
  (:class:`.run_home.RunHome` adopts it); at most :data:`MAX_START_LEVELS` levels;
* **algebraic** -- cos/sin of turns whose group of squares is odd (j/7, j/9, j/11, j/28,
  j/36, ...): numbers of ``K(alpha)``, ``alpha = 2 cos(2 pi/L)`` of odd degree over its
  multiquadratic subfield K (:mod:`exactsym.exact.algebraic.turns`, which says which L
  qualify and why the representation is canonical), with square roots of rationals as
  coefficients; degree over K at most 9 and over Q at most 64.

Anything beyond -- a square root of a number of ``K(alpha)``, a nested radical together
with turns of K(alpha) (two systems in one run), more levels, turns j/13, j/17, ... -- is an
:class:`~exactsym.errors.InputError` naming the bound, located ``file:line:col`` at the
expression (``docs/format.md``), raised before any motion.  ``docs/gathering.md``
(section "Starts") lists the accepted inputs.
"""

from __future__ import annotations

from dataclasses import replace

from flint import fmpq

from ..errors import InputError
from ..exact.algebraic.interface import is_multiquadratic, motion_number, nested_tower
from ..exact.algebraic.run_tower import RunTower, sqrt_exact
from ..exact.algebraic.turns import TurnBoundError, turn_field
from ..exact.multiquadratic import MQ
from ..io.exprtree import Const, FieldFold, Node, Trig, fold

__all__ = ["start_points", "certified", "MAX_START_LEVELS", "StartBoundError"]

#: The most quadratic levels a start's nested radicals may build (each level multiplies the
#: cost of a square-root test in the motion by up to three).
MAX_START_LEVELS = 4


class StartBoundError(ValueError):
    """A start's numbers are beyond the motion's bounds (raised with the node's offset)."""

    def __init__(self, message: str, offset: int = 0):
        super().__init__(message)
        self.offset = offset


def _is_algebraic(x) -> bool:
    """A number of K(alpha) (neither an MQ nor a number of a tower of nested radicals)."""
    return not is_multiquadratic(x) and nested_tower(x) is None


class _MotionNumbers(FieldFold):
    """Each node folded into a number of the motion (see the module docstring)."""

    def __init__(self, turns, tower: RunTower):
        self.turns = turns              # TurnField, or None when no turn needs one
        self.tower = tower

    def const(self, node: Const):
        v = node.value
        return MQ.rational(fmpq(v.numerator, v.denominator))

    def zero_division(self, node):
        return StartBoundError("division by zero", node.offset)

    def power(self, node, base):
        k = abs(node.exponent)
        out, b = MQ.rational(1), base
        while k:
            if k & 1:
                out = out * b
            b = b * b
            k >>= 1
        return out if node.exponent >= 0 else 1 / out

    def sqrt(self, node, arg):
        if _is_algebraic(arg):
            raise StartBoundError("a square root of a number of K(alpha) (the cos/sin of the "
                                  "start's turns): the motion's bound is square roots of "
                                  "multiquadratic or nested-radical numbers", node.offset)
        if arg.sign() < 0:
            raise StartBoundError("square root of a negative number", node.offset)
        try:
            root = sqrt_exact(arg, self.tower)
        except ValueError as err:
            raise StartBoundError(f"{err}", node.offset) from None
        if self.tower.levels > MAX_START_LEVELS:
            raise StartBoundError(f"these nested radicals need {self.tower.levels} levels of "
                                  f"square roots: the motion's bound is {MAX_START_LEVELS}",
                                  node.offset)
        return root

    def trig(self, node: Trig):
        turn = fmpq(node.pi_multiple.numerator, node.pi_multiple.denominator) / 2
        c, s = self.turns.cos_sin(turn)
        return c if node.func == "cos" else s


def _trig_turns(node: Node, out: list) -> None:
    """The turns (fmpq) of every cos/sin in the tree."""
    if type(node) is Trig:
        out.append(fmpq(node.pi_multiple.numerator, node.pi_multiple.denominator) / 2)
    for child in ("arg", "left", "right", "base"):
        sub = getattr(node, child, None)
        if isinstance(sub, Node):
            _trig_turns(sub, out)


def _turns_of(spec) -> list:
    turns = [fmpq(spec.turn.numerator, spec.turn.denominator)] if spec.is_polar else []
    for node in (spec.r, spec.x, spec.y):
        if node is not None:
            _trig_turns(node, turns)
    return turns


def _culprit(specs, per_spec):
    """The first point whose own turns are beyond the bounds, else the first whose turns
    are not multiquadratic (two systems together), else the first point."""
    for spec, turns in zip(specs, per_spec):
        if turns:
            try:
                turn_field(turns)
            except TurnBoundError:
                return spec
    for spec, turns in zip(specs, per_spec):
        if turns and turn_field(turns).kind != "multiquadratic":
            return spec
    return specs[0]


def start_points(specs, source: str) -> list:
    """The points of ``specs`` (:class:`~exactsym.io.fileformat.PointSpec`, already read by
    ``check``'s reader) as pairs of motion numbers in one system; raises
    :class:`InputError` (``file:line:col``, the bound named) beyond the bounds."""
    per_spec = [_turns_of(spec) for spec in specs]
    turns = [t for ts in per_spec for t in ts]
    tower = RunTower()
    field = None
    if turns:
        try:
            field = turn_field(turns, tower)
        except TurnBoundError as err:
            spec = _culprit(specs, per_spec)
            raise InputError(str(err), source, spec.line, spec.column) from None
    algebra = _MotionNumbers(field, tower)
    points = []
    for spec in specs:
        slots = ((spec.r,) if spec.is_polar else (spec.x, spec.y))
        values = []
        for slot, node in enumerate(slots):
            try:
                values.append(fold(node, algebra))
            except StartBoundError as err:
                column = (spec.columns[slot] + err.offset if slot < len(spec.columns)
                          else spec.column)
                raise InputError(str(err), source, spec.line, column) from None
        if spec.is_polar:
            c, s = field.cos_sin(fmpq(spec.turn.numerator, spec.turn.denominator))
            values = [values[0] * c, values[0] * s]
        points.append(tuple(values))
    numbers = [x for p in points for x in p]
    if tower.levels and any(_is_algebraic(x) for x in numbers):
        spec = specs[0]
        raise InputError("nested radicals together with cos/sin of turns of K(alpha) need two "
                         "number systems: the motion's bound is one system per run (a "
                         "RunTower, or K(alpha) with square roots of rationals)", source,
                         spec.line, spec.column)
    return points


def certified(res, points):
    """The run's result ``res`` (:class:`.schedulers.Result`) as it may be quoted: from a
    start beyond the multiquadratic field (a RunTower's or K(alpha)'s numbers) a
    ``gathered`` or ``stalled`` that rests on critical instants seen on both sides only
    (``sided``: no exact value built for a root of a polynomial with such coefficients)
    is ``undecided`` -- the instant itself was never looked at.  A violation stands (its
    witness is exact)."""
    sided = res.checks.get("sided", 0)
    if not sided or res.outcome not in ("gathered", "stalled") or all(
            is_multiquadratic(motion_number(c)) for p in points for c in p):
        return res
    return replace(res, outcome="undecided", detail=(
        f"{res.outcome} ({res.detail}), but {sided} critical instants of the motion from "
        "this algebraic start were seen on both sides only (no exact value): not certified"))
