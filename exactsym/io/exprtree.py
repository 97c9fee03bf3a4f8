"""Expression trees of the configuration format (``docs/format.md``).

The parser (:mod:`exactsym.io.expr`) builds them; the number kernel
(:mod:`exactsym.exact`) evaluates them.  Nothing here evaluates Python code.
``offset`` is the 0-based position in the source string of the node's first
character; it takes no part in equality.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction


@dataclass(frozen=True)
class Node:
    offset: int = field(default=0, compare=False, kw_only=True)


@dataclass(frozen=True)
class Const(Node):
    """A rational constant (integers, exact decimals, ``3/7`` folded by the parser or not)."""
    value: Fraction


@dataclass(frozen=True)
class Neg(Node):
    arg: Node


@dataclass(frozen=True)
class BinOp(Node):
    """``op`` is one of ``+ - * /``."""
    op: str
    left: Node
    right: Node


@dataclass(frozen=True)
class Pow(Node):
    """``base ^ exponent`` with an integer exponent (possibly negative)."""
    base: Node
    exponent: int


@dataclass(frozen=True)
class Sqrt(Node):
    """The non-negative square root of a non-negative expression."""
    arg: Node


@dataclass(frozen=True)
class Trig(Node):
    """``cos(q*pi)`` or ``sin(q*pi)``: ``func`` is ``"cos"`` or ``"sin"``, ``pi_multiple`` is q.

    The angle is ``pi_multiple * pi`` radians, i.e. ``pi_multiple / 2`` turns.
    """
    func: str
    pi_multiple: Fraction


Expr = Node


class Fold:
    """What :func:`fold` calls at each node, bottom-up: each method gets the node (for its
    operator, constant and offset) and the folded values of its children.  A subclass
    overrides all six; :meth:`unknown` is called for a node the parser does not make."""

    def const(self, node: Const):
        raise NotImplementedError

    def neg(self, node: Neg, arg):
        raise NotImplementedError

    def binop(self, node: BinOp, left, right):
        raise NotImplementedError

    def power(self, node: Pow, base):
        raise NotImplementedError

    def sqrt(self, node: Sqrt, arg):
        raise NotImplementedError

    def trig(self, node: Trig):
        raise NotImplementedError

    def unknown(self, node: Node):
        raise TypeError(f"unknown expression node {type(node).__name__}")


class FieldFold(Fold):
    """A fold into a field of exact numbers: negation and the four operations as the
    numbers define them; a division by an exact zero raises :meth:`zero_division`'s
    error (the caller's own, located at the node)."""

    def neg(self, node: Neg, arg):
        return -arg

    def binop(self, node: BinOp, left, right):
        if node.op == "+":
            return left + right
        if node.op == "-":
            return left - right
        if node.op == "*":
            return left * right
        if right == 0:
            raise self.zero_division(node)
        return left / right

    def zero_division(self, node: BinOp) -> Exception:
        return ZeroDivisionError("division by zero")


def fold(node: Node, algebra: Fold):
    """The one walk over an expression tree: ``node`` evaluated bottom-up in ``algebra``
    (exact numbers, Arb balls, texts: :mod:`exactsym.exact.evaluate`,
    :mod:`exactsym.exact.balls`, :mod:`exactsym.exact.text`).  Recursive: callers that
    read deep trees raise the recursion limit (``evaluate._DeepTrees``)."""
    kind = type(node)
    if kind is Const:
        return algebra.const(node)
    if kind is BinOp:
        return algebra.binop(node, fold(node.left, algebra), fold(node.right, algebra))
    if kind is Neg:
        return algebra.neg(node, fold(node.arg, algebra))
    if kind is Pow:
        return algebra.power(node, fold(node.base, algebra))
    if kind is Sqrt:
        return algebra.sqrt(node, fold(node.arg, algebra))
    if kind is Trig:
        return algebra.trig(node)
    return algebra.unknown(node)
